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
  double GapFamily::parabolic_stress_intensity_factor(const double c, const double P, const double a)
  {
    const Parameters parameters = scaled_to(c);
    LoadParameters   parabola   = parameters.load;
    parabola.type               = LoadParameters::Type::parabolic;
    parabola.peak_tension       = P;
    parabola.tension_radius     = a;
    const FaceLoad load(parabola, c);
    const FaceLoad reference = FaceLoad::unit_uniform();

    PennyGapModel        model(parameters, timer);
    const Vector<double> u     = model.solve(load);
    const Vector<double> u_ref = model.solve(reference);
    solves += 2;
    TimerOutput::Scope scope(timer, "J-integral");
    return JIntegral(model).signed_stress_intensity_factor(
      u, load, u_ref, reference, parameters.j_integral.ring_radii.back() * c);
  }

  UnitLoadSifs GapFamily::unit_load_sifs(const double c)
  {
    const Parameters parameters = scaled_to(c);
    const FaceLoad   uniform    = FaceLoad::unit_uniform();
    const FaceLoad   quadratic  = FaceLoad::unit_quadratic();

    PennyGapModel        model(parameters, timer);
    const Vector<double> u_uniform   = model.solve(uniform);
    const Vector<double> u_quadratic = model.solve(quadratic);
    solves += 2;
    TimerOutput::Scope scope(timer, "J-integral");
    const JIntegral    j_integral(model);
    const double       rho = parameters.j_integral.ring_radii.back() * c;
    return {j_integral.stress_intensity_factor(u_uniform, uniform, rho),
            j_integral.signed_stress_intensity_factor(u_quadratic, quadratic, u_uniform, uniform, rho)};
  }
} // namespace penny
