#include "searches/gap_family.h"

#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"

namespace penny
{
  using namespace dealii;

  // The quadratic load's signed K_I by the interaction form with the
  // unit-pressure solution as the reference.
  PennyUnitSifs PennyGaps::solve(const double c, TimerOutput &timer) const
  {
    const FaceLoad           uniform = FaceLoad::unit_uniform(), quadratic = FaceLoad::unit_quadratic();
    PennyGapModel            gap(model.scaled_to(c), timer);
    const DisplacementVector u_quadratic = gap.solve(quadratic);
    const DisplacementVector u_uniform   = gap.solve(uniform);
    TimerOutput::Scope       scope(timer, "J-integral");
    const DomainIntegral<Axisymmetric> j_integral(gap.get_system(), model.material.plane_strain_modulus());
    const RingExtension<2>             ring(gap.crack_tip(), ring_radius * c, c);
    const DomainIntegral<Axisymmetric>::Traction t_quadratic = face_traction(quadratic),
                                                 t_uniform   = face_traction(uniform);
    const auto K =
        j_integral.stress_intensities({{&u_quadratic, &t_quadratic}}, {&u_uniform, &t_uniform}, {&ring});
    return {K.reference[0], K.signed_sifs[0][0]};
  }

  // The cosine's signed K_I by the interaction form with the unit uniform
  // tension as the reference.
  SinusoidUnitSifs PeriodicGaps::solve(const double c, TimerOutput &timer) const
  {
    const auto                        cosine  = BuecknerTension::unit_cosine(model.wavelength);
    const auto                        uniform = BuecknerTension::unit_uniform(model.wavelength);
    PeriodicGapModel                  gap(model.with_gap_half_width(c), timer);
    const DisplacementVector          u_cosine  = gap.solve(cosine);
    const DisplacementVector          u_uniform = gap.solve(uniform);
    TimerOutput::Scope                scope(timer, "J-integral");
    const DomainIntegral<PlaneStrain> j_integral(gap.get_system(), model.material.plane_strain_modulus());
    const RingExtension<2> ring(gap.crack_tip(), ring_radius * gap.get_parameters().tip_distance(), 1);
    const DomainIntegral<PlaneStrain>::Traction t_cosine = cosine, t_uniform = uniform;
    const auto K = j_integral.stress_intensities({{&u_cosine, &t_cosine}}, {&u_uniform, &t_uniform}, {&ring});
    return {K.signed_sifs[0][0], K.reference[0]};
  }
} // namespace penny
