// Closed forms for one gap under the Bueckner parabola p = P - r^2/(2 R_p),
// with and without adhesion (doc/theory.md, section 1). No FE here: the
// statistical layer uses these too.
#pragma once

#include <optional>

namespace penny
{
  namespace closed_form
  {
    constexpr double psi                   = 1.2020809449045589; // p0 = psi (K_Ic^4/R_p)^(1/5)
    constexpr double c_min_factor          = 0.8492635438677062; // c_min = c_min_factor (R_p K_Ic)^(2/5)
    constexpr double adhesionless_c_over_a = 1.224744871391589;  // sqrt(3/2)

    // Peak tension P(c) that holds a gap of radius c at K_I = K_Ic (Pa).
    double adhesive_tension(double c, double R_p, double K_Ic);

    // The paper's g: the stable-branch (c >= c_min) radius with P(c) = P, or
    // nothing when P < p0 and the gap closes.
    std::optional<double> stable_gap_radius(double P, double R_p, double K_Ic);
  } // namespace closed_form

  double adhesion_length(double R_p, double K_Ic);  // (R_p K_Ic)^(2/5) (m)
  double adhesion_tension(double R_p, double K_Ic); // (K_Ic^4/R_p)^(1/5) (Pa)
} // namespace penny
