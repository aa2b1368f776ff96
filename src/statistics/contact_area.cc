#include "statistics/contact_area.h"

#include "closed_forms/adhesive_gap.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <stdexcept>

namespace penny
{
  namespace
  {
    double standard_normal(const double x)
    {
      return std::exp(-x * x / 2) / std::sqrt(2 * M_PI);
    }

    // The j-th of n Chebyshev points of the second kind on [0, t_max].
    double chebyshev_point(const double t_max, const unsigned int j, const unsigned int n)
    {
      return t_max * (1 - std::cos(j * M_PI / (n - 1))) / 2;
    }
  } // namespace

  GapPopulation paper_population(const double hurst, const double zeta)
  {
    return {std::sqrt(2 * M_PI), std::pow(zeta, scaling_exponent(hurst))};
  }

  GapPopulation surface_population(const PressureSummits &summits, const double K_Ic,
                                   const Convention convention)
  {
    const double prefactor =
        convention == Convention::paper
            ? std::sqrt(2 * M_PI)
            : 3 * M_PI * summits.summit_radius * summits.density * std::sqrt(summits.variance);
    return {prefactor, adhesion_ratio(summits, K_Ic)};
  }

  double power_law_prefactor(const double hurst, const double zeta, const Convention convention)
  {
    const auto moments = spectral_moments(power_law_spectrum(hurst, 1, zeta, 1));
    return surface_population(pressure_summits(moments, 1, convention), 1, convention).prefactor;
  }

  // In units with sqrt(V) = 1 and R_p = 1, p0 = psi K_Ic^(4/5) fixes K_Ic.
  GapAreaLaw exact_gap_law(const double adhesion)
  {
    if (adhesion == 0)
      return linear_gap_law(0);
    const double K_Ic = std::pow(adhesion / closed_form::psi, 1.25);
    const double p0 =
        closed_form::adhesive_tension(closed_form::c_min_factor * adhesion_length(1, K_Ic), 1, K_Ic);
    return [K_Ic, p0](const double P) {
      // P = p0/sqrt(V) + t^2 may round a hair below the closed-form p0.
      const double c = *closed_form::stable_gap_radius(std::max(P, p0), 1, K_Ic);
      return c * c / 3;
    };
  }

  GapAreaLaw linear_gap_law(const double adhesion)
  {
    return [adhesion](const double P) { return P - adhesion; };
  }

  GapAreaLaw fitted_gap_law(const double adhesion)
  {
    return [adhesion](const double P) { return P - adhesion / 2; };
  }

  double integration_limit(const double adhesion, const double mean_pressure)
  {
    // Beyond P + p_bar = 12 (or 12 past the bulk when p_bar + p0 < 0) the
    // Gaussian weight is below 1e-31 of its peak.
    return std::sqrt(std::max(0., -(adhesion + mean_pressure)) + 12);
  }

  double noncontact_area(const GapPopulation &gaps, const GapAreaLaw &law, const double mean_pressure)
  {
    const auto integrand = [&](const double t) {
      const double P = gaps.adhesion + t * t;
      return law(P) * standard_normal(P + mean_pressure) * 2 * t;
    };
    double       error    = 0;
    const double integral = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
        integrand, 0., integration_limit(gaps.adhesion, mean_pressure), 15, 1e-13, &error);
    return gaps.prefactor * integral;
  }

  double linear_law_noncontact_area(const GapPopulation &gaps, const double mean_pressure)
  {
    const double x = mean_pressure + gaps.adhesion;
    return gaps.prefactor * (standard_normal(x) - x / 2 * std::erfc(x / std::sqrt(2.)));
  }

  double persson_contact_area(const double adhesion, const double mean_pressure)
  {
    return std::max(0., std::erf((mean_pressure + adhesion) / std::sqrt(2.)));
  }

  std::vector<double> chebyshev_tensions(const double adhesion, const double t_max,
                                         const unsigned int n_points)
  {
    std::vector<double> tensions(n_points);
    for (unsigned int j = 0; j < n_points; ++j)
      {
        const double t = chebyshev_point(t_max, j, n_points);
        tensions[j]    = adhesion + t * t;
      }
    return tensions;
  }

  GapAreaLaw tabulated_gap_law(const double adhesion, const double t_max, std::vector<double> gap_areas)
  {
    const unsigned int  n = gap_areas.size();
    std::vector<double> nodes(n), weights(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        nodes[j]   = chebyshev_point(t_max, j, n);
        weights[j] = (j % 2 ? -1. : 1.) * (j == 0 || j == n - 1 ? 0.5 : 1.);
      }
    // Barycentric formula for Chebyshev points of the second kind.
    return [=](const double P) {
      const double t = std::sqrt(std::max(0., P - adhesion));
      if (t > t_max * (1 + 1e-12))
        throw std::out_of_range("tabulated gap law: P beyond the last tabulated tension");
      double numerator = 0, denominator = 0;
      for (unsigned int j = 0; j < n; ++j)
        {
          if (t == nodes[j])
            return gap_areas[j];
          const double w = weights[j] / (t - nodes[j]);
          numerator += w * gap_areas[j];
          denominator += w;
        }
      return numerator / denominator;
    };
  }
} // namespace penny
