#include "closed_forms/periodic_array.h"

#include "numerics/root_finding.h"

#include <cmath>
#include <stdexcept>

namespace penny::periodic_array
{
  namespace
  {
    // (3/5)^(1/4): where 4 u^3/(1 + u^4)^2 has its maximum.
    const double merging_u = std::pow(0.6, 0.25);

    double stationarity(const double u, const double alpha)
    {
      return 4 * u * u * u - alpha * std::pow(1 + u * u * u * u, 2);
    }

    LoadExtremum extremum_at(const double u, const double alpha)
    {
      const double theta = std::atan(u * u);
      return {theta / M_PI, johnson_load(theta / M_PI, alpha)};
    }

    void check_alpha(const double alpha)
    {
      if (!(alpha > 0 && alpha < largest_alpha_with_extremes()))
        throw std::invalid_argument("Johnson's curve has extremes only for 0 < alpha < (25/16) (3/5)^(3/4)");
    }
  } // namespace

  double stress_intensity_factor(const double c, const double wavelength, const double peak_tension,
                                 const double mean_pressure)
  {
    const double angle = M_PI * c / wavelength;
    return std::sqrt(wavelength) * (peak_tension * std::pow(std::cos(angle), 2) - mean_pressure) *
           std::sqrt(std::tan(angle));
  }

  double johnson_load(const double contact_ratio, const double alpha)
  {
    const double angle = M_PI * contact_ratio;
    return std::pow(std::sin(angle), 2) - alpha * std::sqrt(std::tan(angle));
  }

  double westergaard_contact_ratio(const double load_ratio)
  {
    return std::asin(std::sqrt(load_ratio)) / M_PI;
  }

  double westergaard_pressure(const double position, const double load_ratio)
  {
    const double a    = westergaard_contact_ratio(load_ratio);
    const double edge = std::sin(M_PI * a), s = std::sin(M_PI * position);
    return std::abs(position) < a ? 2 * std::cos(M_PI * position) * std::sqrt(edge * edge - s * s) : 0.;
  }

  double largest_alpha_with_extremes()
  {
    return 25. / 16 * std::pow(0.6, 0.75);
  }

  LoadExtremum jump_into_contact(const double alpha)
  {
    if (alpha == 0)
      return {0.5, 1};
    check_alpha(alpha);
    const auto f  = [&](const double u) { return stationarity(u, alpha); };
    double     lo = merging_u, hi = 2 * merging_u;
    while (f(hi) > 0)
      {
        lo = hi;
        hi *= 2;
      }
    return extremum_at(bracketed_root(f, lo, hi, f(lo), f(hi), closed_form_root_bits), alpha);
  }

  LoadExtremum pull_off(const double alpha)
  {
    if (alpha == 0)
      return {0, 0};
    check_alpha(alpha);
    const auto f = [&](const double u) { return stationarity(u, alpha); };
    return extremum_at(bracketed_root(f, 0., merging_u, f(0), f(merging_u), closed_form_root_bits), alpha);
  }

  double small_alpha_jump(const double alpha)
  {
    return 5 * std::pow(alpha / 4, 0.8);
  }
} // namespace penny::periodic_array
