#include "fracture/periodic_gap_family.h"

#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"

namespace penny
{
  using namespace dealii;

  PeriodicGapFamily::PeriodicGapFamily(const PeriodicGapModelParameters &model, const double ring_radius,
                                       TimerOutput &timer)
      : model(model), ring_radius(ring_radius), timer(timer)
  {
  }

  SinusoidUnitSifs PeriodicGapFamily::unit_load_sifs(const double c)
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
