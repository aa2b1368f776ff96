#include "fracture/gap_family.h"

#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"
#include "parallel/spread_over_ranks.h"

namespace penny
{
  using namespace dealii;

  namespace
  {
    PennyGapModelParameters on_one_rank(PennyGapModelParameters model)
    {
      model.communicator = MPI_COMM_SELF;
      return model;
    }
  } // namespace

  GapFamily::GapFamily(const PennyGapModelParameters &model, const double ring_radius, TimerOutput &timer)
      : model(on_one_rank(model)), ring_radius(ring_radius), timer(timer)
  {
  }

  std::vector<UnitLoadSifs> GapFamily::unit_load_sifs(const std::vector<double> &radii, const MPI_Comm ranks)
  {
    const auto                rows = spread_over_ranks(ranks, radii.size(), [&](const unsigned int i) {
      const UnitLoadSifs K = solve(radii[i]);
      return std::vector<double>{K.uniform, K.quadratic};
    });
    std::vector<UnitLoadSifs> sifs;
    for (const auto &row : rows)
      sifs.push_back({row[0], row[1]});
    return sifs;
  }

  // The quadratic load's signed K_I by the interaction form with the
  // unit-pressure solution as the reference.
  UnitLoadSifs GapFamily::solve(const double c)
  {
    const FaceLoad           uniform = FaceLoad::unit_uniform(), quadratic = FaceLoad::unit_quadratic();
    PennyGapModel            gap(model.scaled_to(c), timer);
    const DisplacementVector u_quadratic = gap.solve(quadratic);
    const DisplacementVector u_uniform   = gap.solve(uniform);
    solves += 2;
    UnitLoadSifs sifs;
    {
      TimerOutput::Scope                 scope(timer, "J-integral");
      const DomainIntegral<Axisymmetric> j_integral(gap.get_system(), model.material.plane_strain_modulus());
      const RingExtension<2>             ring(gap.crack_tip(), ring_radius * c, c);
      const DomainIntegral<Axisymmetric>::Traction t_quadratic = face_traction(quadratic),
                                                   t_uniform   = face_traction(uniform);
      const auto K =
          j_integral.stress_intensities({{&u_quadratic, &t_quadratic}}, {&u_uniform, &t_uniform}, {&ring});
      sifs = {K.reference[0], K.signed_sifs[0][0]};
    }
    if (evaluated)
      evaluated(c);
    return sifs;
  }
} // namespace penny
