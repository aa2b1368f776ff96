#include "fracture/elliptical_gap_family.h"

#include "fracture/front_stress_intensity.h"

#include <cmath>

namespace penny
{
  using namespace dealii;

  double UnitLoadFrontSifs::stress_intensity_factor(const unsigned int i, const QuadraticTraction &t,
                                                    const double lambda) const
  {
    return std::sqrt(lambda) * t.constant * uniform[i] + std::pow(lambda, 2.5) * (t.xx * xx[i] + t.yy * yy[i]);
  }

  UnitLoadFrontSifs closed_form_unit_load_sifs(const double a, const double b_over_a,
                                               const std::vector<double> &angles, const double plane_strain_modulus)
  {
    const double        b = b_over_a * a;
    const GalinSolution uniform(a, b, {1, 0, 0}, plane_strain_modulus), xx(a, b, {0, 1, 0}, plane_strain_modulus),
        yy(a, b, {0, 0, 1}, plane_strain_modulus);
    UnitLoadFrontSifs sifs{a, b, angles, {}, {}, {}};
    for (const double phi : angles)
      {
        sifs.uniform.push_back(uniform.stress_intensity_factor(phi));
        sifs.xx.push_back(xx.stress_intensity_factor(phi));
        sifs.yy.push_back(yy.stress_intensity_factor(phi));
      }
    return sifs;
  }

  EllipticalGapFamily::EllipticalGapFamily(const EllipticalGapModelParameters &model,
                                           const FrontIntegralSettings &front_integral, TimerOutput &timer)
      : model(model), front_integral(front_integral), timer(timer)
  {
  }

  UnitLoadFrontSifs EllipticalGapFamily::unit_load_sifs(const double b_over_a)
  {
    if (const auto known = evaluations.find(b_over_a); known != evaluations.end())
      return known->second;
    const double       a = model.mesh.semi_axis_a;
    EllipticalGapModel gap(model.with_semi_axes(a, b_over_a * a), timer);
    const auto         unit = [](const double constant, const double xx, const double yy) {
      return [=](const Point<3> &x) { return constant + xx * x[0] * x[0] + yy * x[1] * x[1]; };
    };
    const EllipticalGapModel::Traction uniform = unit(1, 0, 0), t_xx = unit(0, 1, 0), t_yy = unit(0, 0, 1);
    const DisplacementVector           u_uniform = gap.solve(uniform);
    const DisplacementVector           u_xx      = gap.solve(t_xx);
    const DisplacementVector           u_yy      = gap.solve(t_yy);
    ++models;
    dofs = gap.get_system().get_dof_handler().n_dofs();

    UnitLoadFrontSifs sifs{a, b_over_a * a, front_integral.angles, {}, {}, {}};
    {
      TimerOutput::Scope         scope(timer, "J-integral");
      const FrontStressIntensity front(gap, front_integral.angles, front_integral.half_width_cells,
                                       {front_integral.ring_radius});
      sifs.uniform = front.sifs(u_uniform, uniform).front();
      sifs.xx      = front.signed_sifs(u_xx, t_xx, u_uniform, uniform).front();
      sifs.yy      = front.signed_sifs(u_yy, t_yy, u_uniform, uniform).front();
    }
    evaluations.emplace(b_over_a, sifs);
    if (evaluated)
      evaluated(b_over_a);
    return sifs;
  }

  ShapeSifs EllipticalGapFamily::shape_sifs()
  {
    return [this](const double b_over_a) { return unit_load_sifs(b_over_a); };
  }
} // namespace penny
