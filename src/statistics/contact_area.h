// From single gaps to area-load curves (doc/theory.md, section 4). Each tensile
// summit of the full-contact pressure, of peak P = p - p_bar above the mean
// pressure p_bar, holds a gap of area pi c_t(P)^2; summed over the Gaussian
// summit heights,
//
//   A_nc/A_0 = eta int_{p0}^inf pi c_t(P)^2 phi_V(P + p_bar) dP.
//
// Everything here is in units of the pressure spread sqrt(V) (pressures) and
// of 3 pi R_p sqrt(V) (gap areas), so a population of gaps is two numbers.
#pragma once

#include "statistics/roughness.h"

#include <functional>
#include <vector>

namespace penny
{
  struct GapPopulation
  {
    double prefactor; // 3 pi R_p eta sqrt(V); sqrt(2 pi) in the paper convention
    double adhesion;  // p0/sqrt(V)
  };

  // The paper's choice: prefactor sqrt(2 pi) (A_nc/A_0 = 1 at zero load without
  // adhesion) and p0/sqrt(V) = zeta^theta, theta = (2/5)(2H - 1).
  GapPopulation paper_population(double hurst, double zeta);

  // A surface's gaps: p0/sqrt(V) from its summits (either convention); the
  // prefactor sqrt(2 pi) in the paper convention, 3 pi R_p eta sqrt(V) in the consistent one.
  GapPopulation surface_population(const PressureSummits &summits, double K_Ic, Convention convention);

  // The prefactor of the power law (H, zeta) in `convention`: 3 pi R_p eta
  // sqrt(V) is a ratio of its moments, sqrt(m2 m6)/m4 up to a number, which
  // no scale (q0, h0, E*, K_Ic) enters.
  double power_law_prefactor(double hurst, double zeta, Convention convention);

  // Gap area pi c_t^2/(3 pi R_p sqrt(V)) against the summit's peak tension
  // P/sqrt(V) >= p0/sqrt(V); gaps below p0 are closed and never asked for.
  using GapAreaLaw = std::function<double(double P)>;

  // Stable branch of K_I = K_Ic (the paper's g, closed_form::stable_gap_radius).
  GapAreaLaw exact_gap_law(double adhesion);
  // The paper's linear law pi c_t^2 = 3 pi R_p (P - p0); p0 = 0 is the exact
  // adhesionless law c_t^2 = 3 R_p P.
  GapAreaLaw linear_gap_law(double adhesion);
  // The fit the paper derives that law from, p_hat = c_hat^2/5 + 1/2 (p_hat =
  // P/p0, c_hat = c/c_min), with c_min^2 = (3/5) R_p p0: pi c_t^2 = 3 pi R_p
  // (P - p0/2) for P >= p0. The linear law drops the p0/2, the gap of area
  // (3/2) pi R_p p0 a summit holds at the threshold (doc/theory.md, section 1).
  GapAreaLaw fitted_gap_law(double adhesion);

  // A_nc/A_0 by adaptive Gauss-Kronrod quadrature over P = p0 + t^2 (the
  // substitution smooths the square-root onset of the exact g at p0).
  double noncontact_area(const GapPopulation &gaps, const GapAreaLaw &law, double mean_pressure);

  // The same for the linear law in closed form:
  // prefactor [phi(x) - (x/2) erfc(x/sqrt 2)], x = (p_bar + p0)/sqrt(V).
  double linear_law_noncontact_area(const GapPopulation &gaps, double mean_pressure);

  // The paper's alternative derivation: A_c/A_0 = erf((p_bar + p0)/sqrt(2 V)),
  // Persson's form with the mean pressure shifted by p0 (zero below -p0).
  double persson_contact_area(double adhesion, double mean_pressure);

  // Peak tensions P/sqrt(V) = p0/sqrt(V) + t^2 at Chebyshev points t in
  // [0, t_max], and the law that interpolates gap areas tabulated there
  // (barycentric, spectrally accurate in t where g is smooth).
  std::vector<double> chebyshev_tensions(double adhesion, double t_max, unsigned int n_points);
  GapAreaLaw          tabulated_gap_law(double adhesion, double t_max, std::vector<double> gap_areas);

  // The largest t = sqrt(P/sqrt(V) - p0/sqrt(V)) noncontact_area() integrates to.
  double integration_limit(double adhesion, double mean_pressure);
} // namespace penny
