// The paper's remark that elliptical gaps "do not change the results
// significantly", asked of summits with two principal radii
// (doc/theory.md, section 8). A summit of the tension field is
//   t(x, y) = P (1 - x^2/Ax^2 - y^2/Ay^2) = P - x^2/(2 R_1) - y^2/(2 R_2),
// R_1 = Ax^2/(2 P), R_2 = Ay^2/(2 P), R_p = (R_1 R_2)^(1/2), and the gaps
// sought are ellipses x^2/a^2 + y^2/b^2 < 1 (a >= b, s = b/a) with
//   without adhesion: K_I = 0 at both ends of the quarter front, phi = 0
//                     (on the x axis) and pi/2 (on the y axis);
//   with adhesion:    K_I = K_Ic at both ends, at the least peak tension P.
// K_I is linear in t, and the unit tractions 1, x^2, y^2 on the gap with
// a = 1 m scale to any a as a^(1/2), a^(5/2), a^(5/2). So every condition is
// algebra on the unit-load K_I of one shape s, and each search is a 1D search
// over s: on Galin's closed form, or on FE models sampled at a few shapes and
// interpolated between them (SampledGapSifs).
#pragma once

#include "numerics/chebyshev_interpolation.h"

#include <array>
#include <functional>
#include <vector>

namespace penny
{
  // K_I (Pa m^1/2) at one front point of the unit face tractions t = 1 Pa,
  // t = x^2 and t = y^2 (Pa/m^2) on a gap with a = 1 m.
  struct EllipticalUnitLoadSifs
  {
    double uniform;
    double xx;
    double yy;
  };

  // The unit-load K_I of the gap a = 1 m, b = s at the parametric angles.
  using EllipticalGapSifs = std::function<std::vector<EllipticalUnitLoadSifs>(
      double aspect_ratio, const std::vector<double> &angles)>;

  // Galin's closed form (fracture/elliptical_crack.h) of the same.
  std::vector<EllipticalUnitLoadSifs> galin_unit_load_sifs(double                     aspect_ratio,
                                                           const std::vector<double> &angles);

  // The unit-load K_I of a family sampled once, at Chebyshev points in
  // log(b/a) on [smallest, 1], and interpolated between them, so that a
  // search step costs no model (the FE models are the samples). K_I is
  // analytic in log(b/a) (the circle included), so the error falls
  // geometrically with the samples; the scene measures it on the closed form.
  class SampledGapSifs
  {
  public:
    SampledGapSifs(const EllipticalGapSifs &sifs, double smallest_aspect_ratio, unsigned int samples,
                   const std::vector<double> &angles);

    // At `angles`, each one of the sampled angles; s in [smallest, 1].
    std::vector<EllipticalUnitLoadSifs> operator()(double s, const std::vector<double> &angles) const;

  private:
    ChebyshevPoints                                  log_aspect_ratios;
    std::vector<double>                              angles;
    std::vector<std::vector<EllipticalUnitLoadSifs>> samples; // [point][angle]
  };

  // Without adhesion: the gap of shape s whose ends have K_I = 0 fixes the
  // summit's shape, from two linear equations in (a/Ax)^2 and (a/Ay)^2.
  struct AdhesionlessSummitGap
  {
    double aspect_ratio;         // b/a
    double tension_aspect_ratio; // Ay/Ax of the summit
    double a_over_Ax;
    double b_over_Ay;
    double area_ratio; // a b/(Ax Ay): gap area over tension area (3/2 for the circle)

    // K_I/(P K_uniform) at a front point: 0 where the ellipse is exact.
    double relative_sif(const EllipticalUnitLoadSifs &K) const;
  };
  AdhesionlessSummitGap adhesionless_gap(double                                       aspect_ratio,
                                         const std::array<EllipticalUnitLoadSifs, 2> &ends);

  // With adhesion, in the units K_Ic = 1, R_p = 1 (lengths in (R_p K_Ic)^(2/5),
  // tensions in (K_Ic^4/R_p)^(1/5)): the gap of shape s with K_I = K_Ic at both
  // ends under the summit of shape Ay/Ax, its size a and peak tension P.
  struct AdhesiveSummitGap
  {
    double aspect_ratio;         // b/a
    double tension_aspect_ratio; // Ay/Ax = (R_2/R_1)^(1/2)
    double a;                    // in (R_p K_Ic)^(2/5)
    double tension;              // P in (K_Ic^4/R_p)^(1/5); at the minimum over s, psi

    // K_I/K_Ic at a front point: 1 at both ends.
    double relative_sif(const EllipticalUnitLoadSifs &K) const;
  };
  // Nothing in range (a of either sign undefined) is returned as tension +inf.
  // For the circle (Ay/Ax = 1, then s = 1) every a has K_I = K_Ic at both ends
  // for its own P; the least P, at a^(5/2) = 1/(4 g), is returned.
  AdhesiveSummitGap adhesive_gap(double aspect_ratio, double tension_aspect_ratio,
                                 const std::array<EllipticalUnitLoadSifs, 2> &ends);

  // The searches over s return the shape b/a (each evaluation one call of
  // `sifs` at phi = 0, pi/2; the gap itself then comes from the ends of the
  // front at that shape): the root of Ay/Ax(s) = tension_aspect_ratio, and
  // the minimum over s of P. The adhesive gaps of a summit lie between its
  // adhesionless shape s_0 (where a grows without bound) and the circle
  // (where a shrinks to 0), so the minimum is sought on (s_0, 1). The circle
  // Ay/Ax = 1 is s = 1 by symmetry. `slenderest`: the smallest s that `sifs`
  // answers (a sampled family's lower end; 0: any s > 0).
  double adhesionless_summit_shape(const EllipticalGapSifs &sifs, double tension_aspect_ratio,
                                   double slenderest = 0);
  double adhesive_summit_shape(const EllipticalGapSifs &sifs, double tension_aspect_ratio,
                               double adhesionless_aspect_ratio);
} // namespace penny
