// One gap under the Bueckner parabola p = P - r^2/(2 R_p), with and without
// adhesion (physics.md section 1): the closed forms, and the same quantities
// found from FE solves alone by root finding and minimisation over the gap
// radius c. Closed-form values never enter an FE search, which only uses the
// natural length scale (R_p K_Ic)^(2/5) to place its first bracket.
#pragma once

#include "gap_family.h"

#include <optional>

namespace penny
{
  namespace closed_form
  {
    constexpr double psi          = 1.2020809449045589; // p0 = psi (K_Ic^4/R_p)^(1/5)
    constexpr double c_min_factor = 0.8492635438677062; // c_min = c_min_factor (R_p K_Ic)^(2/5)
    constexpr double adhesionless_c_over_a = 1.224744871391589; // sqrt(3/2)

    // Peak tension P(c) that holds a gap of radius c at K_I = K_Ic.
    double adhesive_tension(double c, double R_p, double K_Ic);

    // The paper's g: the stable-branch (c >= c_min) radius with P(c) = P, or
    // nothing when P < p0 and the gap closes.
    std::optional<double> stable_gap_radius(double P, double R_p, double K_Ic);
  } // namespace closed_form

  double adhesion_length(double R_p, double K_Ic);  // (R_p K_Ic)^(2/5) (m)
  double adhesion_tension(double R_p, double K_Ic); // (K_Ic^4/R_p)^(1/5) (Pa)

  struct AdhesiveMinimum
  {
    double gap_radius; // c_min (m)
    double tension;    // p0 = P(c_min) (Pa)
  };

  // Adhesionless gap: the root of the FE K_I(c) for the parabola (P, a).
  double fe_adhesionless_gap_radius(GapFamily &gaps, double P, double a);

  // Minimum over c of the FE P(c) = [K_Ic + K_quadratic(c)/(2 R_p)] / K_uniform(c) (Brent).
  AdhesiveMinimum fe_adhesive_minimum(GapFamily &gaps, double R_p, double K_Ic);

  // FE g: the radius c >= c_min where P K_uniform(c) - K_quadratic(c)/(2 R_p) = K_Ic,
  // or nothing when P < p0 (the gap closes: full contact).
  std::optional<double>
  fe_stable_gap_radius(GapFamily &gaps, double P, double R_p, double K_Ic, const AdhesiveMinimum &minimum);
} // namespace penny
