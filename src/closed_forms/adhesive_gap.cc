#include "closed_forms/adhesive_gap.h"

#include "numerics/root_finding.h"

#include <cmath>

namespace penny
{
  double closed_form::adhesive_tension(const double c, const double R_p, const double K_Ic)
  {
    return c * c / (3 * R_p) + std::sqrt(M_PI) * K_Ic / (2 * std::sqrt(c));
  }

  std::optional<double> closed_form::stable_gap_radius(const double P, const double R_p, const double K_Ic)
  {
    const double c_min = c_min_factor * adhesion_length(R_p, K_Ic);
    const double p0    = adhesive_tension(c_min, R_p, K_Ic);
    if (P < p0)
      return std::nullopt;
    if (P == p0)
      return c_min;
    const auto f = [&](const double c) { return P - adhesive_tension(c, R_p, K_Ic); };
    // Cheap to evaluate: the search may span the doubles (weak adhesion puts
    // the stable gap millions of c_min out).
    return root_above(f, c_min, f(c_min), "closed-form stable gap radius", closed_form_root_bits, 1000);
  }

  double adhesion_length(const double R_p, const double K_Ic)
  {
    return std::pow(R_p * K_Ic, 0.4);
  }

  double adhesion_tension(const double R_p, const double K_Ic)
  {
    return std::pow(std::pow(K_Ic, 4) / R_p, 0.2);
  }
} // namespace penny
