#include "searches/elliptical_gap_family.h"

#include "fracture/front_stress_intensity.h"

namespace penny
{
  using namespace dealii;

  namespace
  {
    // `model` with the rings and outer shells of the gap of b/a = `slenderest`.
    EllipticalGapModelParameters counted_alike(EllipticalGapModelParameters model, const double slenderest)
    {
      model.mesh.counts_aspect_ratio = slenderest;
      return model;
    }
  } // namespace

  EllipticalGapFamily::EllipticalGapFamily(const EllipticalGapModelParameters &model,
                                           const FrontWeight &weight, const double ring_radius,
                                           const double slenderest, TimerOutput &timer)
      : model(counted_alike(model, slenderest)), weight(weight), ring_radius(ring_radius), timer(timer)
  {
  }

  std::vector<EllipticalUnitLoadSifs> EllipticalGapFamily::unit_load_sifs(const double               s,
                                                                          const std::vector<double> &angles)
  {
    EllipticalGapModelParameters shaped = model;
    shaped.mesh.semi_axis_a             = 1;
    shaped.mesh.semi_axis_b             = s;
    EllipticalGapModel                 gap(shaped, timer);
    const EllipticalGapModel::Traction uniform = [](const Point<3> &) { return 1.; };
    const EllipticalGapModel::Traction xx      = [](const Point<3> &x) { return x[0] * x[0]; };
    const EllipticalGapModel::Traction yy      = [](const Point<3> &x) { return x[1] * x[1]; };
    const DisplacementVector           u       = gap.solve(uniform);
    const DisplacementVector           u_xx    = gap.solve(xx);
    const DisplacementVector           u_yy    = gap.solve(yy);
    ++models;

    std::vector<EllipticalUnitLoadSifs> K(angles.size());
    {
      TimerOutput::Scope         scope(timer, "J-integral");
      const FrontStressIntensity front(gap, angles, weight, {ring_radius});
      // One ring: [load][0][point].
      const auto sifs = front.signed_sifs({{&u, &uniform}, {&u_xx, &xx}, {&u_yy, &yy}}, u, uniform);
      for (unsigned int i = 0; i < angles.size(); ++i)
        K[i] = {sifs[0][0][i], sifs[1][0][i], sifs[2][0][i]};
    }
    if (evaluated)
      evaluated(s);
    return K;
  }
} // namespace penny
