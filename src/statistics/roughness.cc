#include "statistics/roughness.h"

#include "closed_forms/adhesive_gap.h"
#include "input/input_error.h"

#include <Eigen/Dense>

#include <cmath>
#include <fstream>
#include <sstream>

namespace penny
{
  PowerSpectrum power_law_spectrum(const double hurst, const double q0, const double zeta, const double h0)
  {
    const double C0 = hurst / (2 * M_PI) * std::pow(h0 / q0, 2);
    return {{q0, zeta * q0}, {C0, C0 * std::pow(zeta, -2 * (hurst + 1))}};
  }

  PowerSpectrum read_power_spectrum(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      throw InputError(in_quotes(filename) + " cannot be read (expected two columns q (1/m), C(q) (m^4))");
    PowerSpectrum spectrum;
    std::string   line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        // A UTF-8 byte-order mark, as some editors write, is no text.
        if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
          line.erase(0, 3);
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos)
          continue;
        std::istringstream row(line);
        double             q, C;
        std::string        rest;
        const bool valid = (row >> q >> C) && !(row >> rest) && std::isfinite(q) && std::isfinite(C) &&
                           q > 0 && C > 0 &&
                           (spectrum.wavenumbers.empty() || q > spectrum.wavenumbers.back());
        if (!valid)
          throw InputError(in_quotes(filename) + ", line " + std::to_string(number) +
                           ": expected two numbers q > 0 (increasing) and C(q) > 0");
        spectrum.wavenumbers.push_back(q);
        spectrum.densities.push_back(C);
      }
    if (spectrum.wavenumbers.size() < 2)
      throw InputError(in_quotes(filename) + " holds fewer than two rows q C(q)");
    return spectrum;
  }

  SpectralMoments spectral_moments(const PowerSpectrum &spectrum)
  {
    // Radial moment 2 pi int q^(k+1) C dq of one segment C = C_a (q/q_a)^s:
    // 2 pi C_a q_a^(k+2) (r^e - 1)/e with r = q_b/q_a and e = k + 2 + s, written
    // with expm1 so that e -> 0 (a 1/q^(k+2) segment) keeps its digits.
    const auto radial_moment = [&](const int k) {
      double sum = 0;
      for (std::size_t i = 0; i + 1 < spectrum.wavenumbers.size(); ++i)
        {
          const double q_a = spectrum.wavenumbers[i], C_a = spectrum.densities[i];
          const double log_r = std::log(spectrum.wavenumbers[i + 1] / q_a);
          const double e     = k + 2 + std::log(spectrum.densities[i + 1] / C_a) / log_r;
          const double x     = e * log_r;
          sum += 2 * M_PI * C_a * std::pow(q_a, k + 2) * log_r * (x == 0 ? 1. : std::expm1(x) / x);
        }
      return sum;
    };
    // Along one line, q_x^n averages q^n cos^n over the angle: 1, 1/2, 3/8, 5/16.
    return {radial_moment(0), radial_moment(2) / 2, radial_moment(4) * 3 / 8, radial_moment(6) * 5 / 16};
  }

  std::string to_string(const Convention convention)
  {
    return convention == Convention::paper ? "paper" : "consistent";
  }

  PressureSummits pressure_summits(const SpectralMoments &m, const double E_star, const Convention convention)
  {
    if (convention == Convention::paper)
      return {E_star * E_star * m.m2 / 4, m.m6 / (6 * std::sqrt(M_PI) * m.m4),
              0.375 * std::sqrt(2 * M_PI / m.m6) / E_star};

    // The pressure's PSD is (E*^2/4) q^2 C(q), so its profile moments are the
    // heights' radial moments two orders up with the angular factors of their
    // own order: m0^p = (E*^2/4) 2 m2, m2^p = (E*^2/4) (4/3) m4, m4^p = (E*^2/4) (6/5) m6.
    const double scale = E_star * E_star / 4;
    const double m0_p = scale * 2 * m.m2, m2_p = scale * 4 / 3 * m.m4, m4_p = scale * 6 / 5 * m.m6;
    // Nayak: summit density m4/(6 pi sqrt(3) m2), mean summit curvature (8/3) sqrt(m4/pi).
    return {m0_p, m4_p / (6 * M_PI * std::sqrt(3.) * m2_p), 3 / (8 * std::sqrt(m4_p / M_PI))};
  }

  double adhesion_ratio(const PressureSummits &summits, const double K_Ic)
  {
    return closed_form::psi * adhesion_tension(summits.summit_radius, K_Ic) / std::sqrt(summits.variance);
  }

  double fitted_scaling_exponent(const double hurst, const double zeta_first, const double zeta_last,
                                 const unsigned int n_points, const Convention convention)
  {
    Eigen::MatrixXd design(n_points, 2);
    Eigen::VectorXd log_ratio(n_points);
    for (unsigned int i = 0; i < n_points; ++i)
      {
        const double log_zeta = std::log(zeta_first) + i * std::log(zeta_last / zeta_first) / (n_points - 1);
        const auto   moments  = spectral_moments(power_law_spectrum(hurst, 1, std::exp(log_zeta), 1));
        design(i, 0)          = log_zeta;
        design(i, 1)          = 1;
        log_ratio(i)          = std::log(adhesion_ratio(pressure_summits(moments, 1, convention), 1));
      }
    return design.colPivHouseholderQr().solve(log_ratio)(0);
  }

  double scaling_exponent(const double hurst)
  {
    return 0.4 * (2 * hurst - 1);
  }
} // namespace penny
