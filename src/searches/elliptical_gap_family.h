// The family of elliptical-gap models indexed by the aspect ratio s = b/a,
// with a = 1 m: for each s the model is rebuilt (box and mesh scaled with the
// semi-axes), assembled and preconditioned once, and solved for the three
// unit tractions 1, x^2 and y^2. The summit searches (elliptical_summits.h)
// sample it; every evaluation is a full 3D FE model.
#pragma once

#include "fe/elliptical_gap_model.h"
#include "fracture/front_stress_intensity.h"
#include "searches/elliptical_summits.h"

#include <deal.II/base/timer.h>

#include <functional>
#include <vector>

namespace penny
{
  class EllipticalGapFamily
  {
  public:
    // `model`: the discretisation (its semi-axes are replaced); the front
    // J-integrals have the front weight and the ring radius (in units of
    // b^2/a) of fracture/front_stress_intensity.h. Every model has as many
    // rings and outer shells as the slenderest shape sampled, b/a =
    // `slenderest`, needs: the mesh moves with b/a instead of changing in
    // steps, so that K_I is a smooth function of b/a.
    EllipticalGapFamily(const EllipticalGapModelParameters &model, const FrontWeight &weight,
                        double ring_radius, double slenderest, dealii::TimerOutput &timer);

    // Signed K_I of the unit tractions at `angles` on the gap a = 1 m, b = s,
    // each with the unit pressure as reference.
    std::vector<EllipticalUnitLoadSifs> unit_load_sifs(double s, const std::vector<double> &angles);

    unsigned int n_models() const { return models; }

    // `observer(s)` is called after each evaluation, with its aspect ratio.
    void observe(std::function<void(double s)> observer) { evaluated = std::move(observer); }

  private:
    const EllipticalGapModelParameters model;
    const FrontWeight                  weight;
    const double                       ring_radius;
    dealii::TimerOutput               &timer;
    unsigned int                       models = 0;
    std::function<void(double)>        evaluated;
  };
} // namespace penny
