#include "fracture/periodic_gap_family.h"

#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"
#include "parallel/spread_over_ranks.h"

namespace penny
{
  using namespace dealii;

  namespace
  {
    PeriodicGapModelParameters on_one_rank(PeriodicGapModelParameters model)
    {
      model.communicator = MPI_COMM_SELF;
      return model;
    }
  } // namespace

  PeriodicGapFamily::PeriodicGapFamily(const PeriodicGapModelParameters &model, const double ring_radius,
                                       TimerOutput &timer)
      : model(on_one_rank(model)), ring_radius(ring_radius), timer(timer)
  {
  }

  std::vector<SinusoidUnitSifs> PeriodicGapFamily::unit_load_sifs(const std::vector<double> &half_widths,
                                                                  const MPI_Comm             ranks)
  {
    const auto rows = spread_over_ranks(ranks, half_widths.size(), [&](const unsigned int i) {
      const SinusoidUnitSifs K = solve(half_widths[i]);
      return std::vector<double>{K.cosine, K.uniform};
    });
    std::vector<SinusoidUnitSifs> sifs;
    for (const auto &row : rows)
      sifs.push_back({row[0], row[1]});
    return sifs;
  }

  SinusoidUnitSifs PeriodicGapFamily::solve(const double c)
  {
    const auto               cosine  = BuecknerTension::unit_cosine(model.wavelength);
    const auto               uniform = BuecknerTension::unit_uniform(model.wavelength);
    PeriodicGapModel         gap(model.with_gap_half_width(c), timer);
    const DisplacementVector u_cosine  = gap.solve(cosine);
    const DisplacementVector u_uniform = gap.solve(uniform);
    solves += 2;
    TimerOutput::Scope                scope(timer, "J-integral");
    const DomainIntegral<PlaneStrain> j_integral(gap.get_system(), model.material.plane_strain_modulus());
    const RingExtension<2> ring(gap.crack_tip(), ring_radius * gap.get_parameters().tip_distance(), 1);
    const DomainIntegral<PlaneStrain>::Traction t_cosine = cosine, t_uniform = uniform;
    const auto K = j_integral.stress_intensities({{&u_cosine, &t_cosine}}, {&u_uniform, &t_uniform}, {&ring});
    return {K.signed_sifs[0][0], K.reference[0]};
  }
} // namespace penny
