// Isotropic Gaussian rough surfaces (doc/theory.md, section 4): the power
// spectral density C(q) of the heights, its moments, and the statistics of the
// full-contact pressure field whose tensile summits are the gaps.
#pragma once

#include <string>
#include <vector>

namespace penny
{
  // C(q) (m^4) at increasing wavenumbers q (1/m), zero outside the table and
  // log-log linear between its points: a piecewise power law.
  struct PowerSpectrum
  {
    std::vector<double> wavenumbers;
    std::vector<double> densities;
  };

  // The paper's self-affine spectrum C(q) = (H/2pi) (h0/q0)^2 (q/q0)^(-2(H+1))
  // for q0 <= q <= zeta q0. The paper prints (h0/lambda0)^2, which leaves C
  // without its units m^4; with (h0/q0)^2 (Persson's form) m0 = h0^2 (1 - zeta^(-2H))/2.
  // h0 = (h0/lambda0) lambda0 with lambda0 = 2 pi/q0.
  PowerSpectrum power_law_spectrum(double hurst, double q0, double zeta, double h0);

  // The smallest Hurst exponent the scenes take: the power law's heights
  // vanish with H (m0 ~ h0^2 H ln zeta), and far below this bound the
  // contact solver works near the end of a double's range (H = 1e-200 gave
  // NaN, 1e-160 did not finish); the paper's H lie between 0.25 and 0.75.
  constexpr double smallest_hurst_exponent = 0.01;

  // The height PSD of a rough surface: the paper's power law (its H, q0,
  // zeta and amplitude h0) or the table of a file.
  struct RoughnessParameters
  {
    enum class Spectrum
    {
      power_law,
      file
    };
    Spectrum    spectrum;
    double      hurst;     // H
    double      q0;        // long-wavelength cut-off (1/m)
    double      zeta;      // magnification q1/q0
    double      amplitude; // h0 (m) of the power law
    std::string spectrum_file;
  };

  // A two-column text file "q C(q)" (1/m, m^4), '#' starts a comment. Throws
  // InputError, its message starting with the file name in quotes, when the
  // file is missing or not a valid table.
  PowerSpectrum read_power_spectrum(const std::string &filename);

  // Profile (one-direction) moments m_n = int q_x^n C(q) d^2q of the heights,
  // Nayak's definition: m0 the height variance, m2 the slope variance along a
  // line. Integrated exactly on the piecewise power law, so the closed form for
  // the paper's spectrum is the one-segment case.
  struct SpectralMoments
  {
    double m0, m2, m4, m6;
  };
  SpectralMoments spectral_moments(const PowerSpectrum &spectrum);

  // Which normalisations turn moments into summit statistics (doc/theory.md, section 4).
  enum class Convention
  {
    paper,     // V = E*^2 m2/4, eta = m6/(6 sqrt(pi) m4), R_p = 0.375 sqrt(2 pi/m6)/E*
    consistent // Nayak's summits of the isotropic pressure field, whose moments
               // follow from its PSD (E*^2/4) q^2 C(q)
  };
  std::string to_string(Convention convention);

  // The full-contact pressure field p_fc and its tensile summits.
  struct PressureSummits
  {
    double variance;      // V = <p_fc^2> (Pa^2)
    double density;       // eta, summits per area (1/m^2)
    double summit_radius; // R_p: p = P - r^2/(2 R_p) near a summit (m^2/Pa)
  };
  PressureSummits pressure_summits(const SpectralMoments &moments, double E_star, Convention convention);

  // p0/sqrt(V), the minimum peak tension of an adhesive gap,
  // p0 = psi (K_Ic^4/R_p)^(1/5), in units of the pressure spread.
  double adhesion_ratio(const PressureSummits &summits, double K_Ic);

  // theta in p0/sqrt(V) ~ zeta^theta: the least-squares slope (Eigen) of
  // log(p0/sqrt(V)) against log(zeta), computed from the moments of the paper's
  // spectrum at `n_points` magnifications spaced evenly in log between
  // zeta_first and zeta_last (q0, h0, E* and K_Ic only shift the intercept).
  double fitted_scaling_exponent(double hurst, double zeta_first, double zeta_last, unsigned int n_points,
                                 Convention convention);

  // The paper's exponent (2/5)(2H - 1).
  double scaling_exponent(double hurst);
} // namespace penny
