#include "gap_family.h"

#include "face_load.h"
#include "gap_mesh.h"
#include "j_integral.h"
#include "penny_gap_model.h"

namespace penny
{
  using namespace dealii;

  GapFamily::GapFamily(const Parameters &parameters, TimerOutput &timer)
    : base(parameters)
    , timer(timer)
  {}

  Parameters GapFamily::scaled_to(const double c) const
  {
    Parameters   scaled = base;
    const double factor = c / base.geometry.gap_radius;
    scaled.geometry.gap_radius    = c;
    scaled.geometry.domain_radius = factor * base.geometry.domain_radius;
    scaled.geometry.domain_height = factor * base.geometry.domain_height;
    return scaled;
  }

  // The ring used for derived quantities is the last one listed.
  GapFamily::SifsWithReference GapFamily::solve_with_reference(const double c, const FaceLoad &load)
  {
    const Parameters parameters = scaled_to(c);
    const FaceLoad   reference  = FaceLoad::unit_uniform();

    PennyGapModel        model(parameters, timer);
    const DisplacementVector u     = model.solve(load);
    const DisplacementVector u_ref = model.solve(reference);
    solves += 2;
    TimerOutput::Scope scope(timer, "J-integral");
    const JIntegral    j_integral(model);
    const double       rho = parameters.j_integral.ring_radii.back() * c;
    return {j_integral.stress_intensity_factor(u_ref, reference, rho),
            j_integral.signed_stress_intensity_factor(u, load, u_ref, reference, rho)};
  }

  double GapFamily::parabolic_stress_intensity_factor(const double c, const double P, const double a)
  {
    LoadParameters parabola = base.load;
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

  double GapFamily::wall_time() const
  {
    double total = 0;
    for (const auto &phase : timer.get_summary_data(TimerOutput::total_wall_time))
      total += phase.second;
    return total;
  }
} // namespace penny
