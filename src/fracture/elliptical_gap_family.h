// The family of elliptical-gap models indexed by the shape b/a, and the unit
// loads the summit searches combine (doc/theory.md, section 6). K_I is linear
// in the face traction, so the stress intensity factors of t = 1, x^2 and y^2
// on one gap give K_I of every QuadraticTraction; and a gap scaled by lambda
// scales them by lambda^(1/2), lambda^(5/2) and lambda^(5/2). So a search over
// gaps (a, b) needs FE solves only over the shape b/a: each evaluation is one
// model built for (a_0, b/a a_0), a_0 the scene's semi-axis, with its mesh,
// one stiffness matrix and preconditioner, and three right-hand sides.
#pragma once

#include "fe/elliptical_gap_model.h"
#include "fracture/elliptical_crack.h"

#include <deal.II/base/timer.h>

#include <functional>
#include <map>
#include <vector>

namespace penny
{
  // K_I (Pa m^1/2) along the front of the gap (a, b) under t = 1 Pa and
  // t = x^2, y^2 (Pa/m^2), at the parametric angles `angles` (first 0, last pi/2).
  struct UnitLoadFrontSifs
  {
    double              semi_axis_a, semi_axis_b;
    std::vector<double> angles;
    std::vector<double> uniform, xx, yy;

    // K_I at point i of the traction t on the gap scaled by lambda: (lambda a, lambda b).
    double stress_intensity_factor(unsigned int i, const QuadraticTraction &t, double lambda = 1) const;
  };

  // The unit-load SIFs of the shape b/a, from FE or from the closed form.
  using ShapeSifs = std::function<UnitLoadFrontSifs(double b_over_a)>;

  // Galin's closed form for the gap (a, b/a a) at `angles`.
  UnitLoadFrontSifs closed_form_unit_load_sifs(double a, double b_over_a, const std::vector<double> &angles,
                                               double plane_strain_modulus);

  struct FrontIntegralSettings
  {
    std::vector<double> angles;           // front points
    double              half_width_cells; // of the front weight
    double              ring_radius;      // in units of b^2/a
  };

  class EllipticalGapFamily
  {
  public:
    EllipticalGapFamily(const EllipticalGapModelParameters &model, const FrontIntegralSettings &front_integral,
                        dealii::TimerOutput &timer);

    // FE unit-load SIFs of the gap (a_0, b/a a_0), signed with the unit
    // pressure as reference; a shape evaluated before is not solved again.
    UnitLoadFrontSifs unit_load_sifs(double b_over_a);

    // This family as a ShapeSifs.
    ShapeSifs shape_sifs();

    unsigned int n_models() const { return models; }
    unsigned int n_solves() const { return 3 * models; }
    // Degrees of freedom of the last model built.
    unsigned int n_dofs() const { return dofs; }

    // `observer(b/a)` is called after each new model is solved.
    void observe(std::function<void(double)> observer) { evaluated = std::move(observer); }

  private:
    const EllipticalGapModelParameters   model;
    const FrontIntegralSettings          front_integral;
    dealii::TimerOutput                 &timer;
    std::map<double, UnitLoadFrontSifs>  evaluations;
    unsigned int                         models = 0;
    unsigned int                         dofs   = 0;
    std::function<void(double)>          evaluated;
  };
} // namespace penny
