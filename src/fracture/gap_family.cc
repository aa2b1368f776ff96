#include "fracture/gap_family.h"

#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"

namespace penny
{
  using namespace dealii;

  GapFamily::GapFamily(const PennyGapModelParameters &model, const double ring_radius, TimerOutput &timer)
      : model(model), ring_radius(ring_radius), timer(timer)
  {
  }

  GapFamily::SifsWithReference GapFamily::solve_with_reference(const double c, const FaceLoad &load)
  {
    const FaceLoad           reference = FaceLoad::unit_uniform();
    PennyGapModel            gap(model.scaled_to(c), timer);
    const DisplacementVector u     = gap.solve(load);
    const DisplacementVector u_ref = gap.solve(reference);
    solves += 2;
    SifsWithReference sifs;
    {
      TimerOutput::Scope                 scope(timer, "J-integral");
      const DomainIntegral<Axisymmetric> j_integral(gap.get_system(), model.material.plane_strain_modulus());
      const RingExtension<2>             ring(gap.crack_tip(), ring_radius * c, c);
      const DomainIntegral<Axisymmetric>::Traction t = face_traction(load), t_ref = face_traction(reference);
      const auto K = j_integral.stress_intensities({{&u, &t}}, {&u_ref, &t_ref}, {&ring});
      sifs         = {K.reference[0], K.signed_sifs[0][0]};
    }
    if (evaluated)
      evaluated(c);
    return sifs;
  }

  double GapFamily::parabolic_stress_intensity_factor(const double c, const double P, const double a)
  {
    LoadParameters parabola;
    parabola.type           = LoadParameters::Type::parabolic;
    parabola.peak_tension   = P;
    parabola.tension_radius = a;
    return solve_with_reference(c, FaceLoad(parabola, c)).load;
  }

  UnitLoadSifs GapFamily::unit_load_sifs(const double c)
  {
    const SifsWithReference K = solve_with_reference(c, FaceLoad::unit_quadratic());
    return {K.reference, K.load};
  }
} // namespace penny
