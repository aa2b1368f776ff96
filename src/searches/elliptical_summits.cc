#include "searches/elliptical_summits.h"

#include "closed_forms/elliptical_crack.h"
#include "numerics/root_finding.h"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace penny
{
  namespace
  {
    // The searches run on closed forms and on sampled FE families, where a
    // step costs no model: the root to about 1e-12 in s, the minimum of P(s)
    // to Brent's limit, half the mantissa (P moves by its square there).
    constexpr int shape_bits   = 40;
    constexpr int minimum_bits = std::numeric_limits<double>::digits / 2;

    std::array<EllipticalUnitLoadSifs, 2> front_ends(const EllipticalGapSifs &sifs, const double s)
    {
      const std::vector<EllipticalUnitLoadSifs> K = sifs(s, {0., M_PI / 2});
      return {{K[0], K[1]}};
    }
  } // namespace

  std::vector<EllipticalUnitLoadSifs> galin_unit_load_sifs(const double               aspect_ratio,
                                                           const std::vector<double> &angles)
  {
    // K_I of a traction does not depend on the modulus.
    const GalinSolution uniform(1, aspect_ratio, {1, 0, 0}, 1), xx(1, aspect_ratio, {0, 1, 0}, 1),
        yy(1, aspect_ratio, {0, 0, 1}, 1);
    std::vector<EllipticalUnitLoadSifs> K;
    for (const double phi : angles)
      K.push_back({uniform.stress_intensity_factor(phi), xx.stress_intensity_factor(phi),
                   yy.stress_intensity_factor(phi)});
    return K;
  }

  SampledGapSifs::SampledGapSifs(const EllipticalGapSifs &sifs, const double smallest_aspect_ratio,
                                 const unsigned int samples, const std::vector<double> &angles)
      : log_aspect_ratios(std::log(smallest_aspect_ratio), 0, samples), angles(angles)
  {
    for (const double log_s : log_aspect_ratios.nodes())
      this->samples.push_back(sifs(std::exp(log_s), angles));
  }

  std::vector<EllipticalUnitLoadSifs> SampledGapSifs::operator()(const double               s,
                                                                 const std::vector<double> &at) const
  {
    const std::vector<double>           c = log_aspect_ratios.cardinal_weights(std::log(s));
    std::vector<EllipticalUnitLoadSifs> K;
    for (const double phi : at)
      {
        const auto sampled = std::find_if(angles.begin(), angles.end(),
                                          [phi](const double p) { return std::abs(p - phi) < 1e-12; });
        if (sampled == angles.end())
          throw std::invalid_argument("sampled K_I: phi = " + std::to_string(phi) + " was not sampled");
        const std::size_t      i = sampled - angles.begin();
        EllipticalUnitLoadSifs k{0, 0, 0};
        for (unsigned int j = 0; j < c.size(); ++j)
          {
            k.uniform += c[j] * samples[j][i].uniform;
            k.xx += c[j] * samples[j][i].xx;
            k.yy += c[j] * samples[j][i].yy;
          }
        K.push_back(k);
      }
    return K;
  }

  // K_I/P = K_uniform - (a/Ax)^2 K_xx - (a/Ay)^2 K_yy on the gap a = 1.
  AdhesionlessSummitGap adhesionless_gap(const double s, const std::array<EllipticalUnitLoadSifs, 2> &ends)
  {
    const auto &[k0, k1] = ends;
    const double det     = k0.xx * k1.yy - k0.yy * k1.xx;
    const double u       = (k0.uniform * k1.yy - k0.yy * k1.uniform) / det; // (a/Ax)^2
    const double v       = (k0.xx * k1.uniform - k0.uniform * k1.xx) / det; // (a/Ay)^2
    if (!(u > 0 && v > 0))
      throw std::runtime_error("elliptical summit: no summit has a gap of aspect ratio " + std::to_string(s) +
                               " with K_I = 0 at both ends");
    return {s, std::sqrt(u / v), std::sqrt(u), s * std::sqrt(v), s * std::sqrt(u * v)};
  }

  double AdhesionlessSummitGap::relative_sif(const EllipticalUnitLoadSifs &K) const
  {
    const double a_over_Ay = b_over_Ay / aspect_ratio;
    return 1 - (a_over_Ax * a_over_Ax * K.xx + a_over_Ay * a_over_Ay * K.yy) / K.uniform;
  }

  // With K_Ic = R_p = 1, R_1 = 1/rho, R_2 = rho: at either end i
  //   P a^(1/2) K_uniform,i - a^(5/2) g_i = 1,  g_i = (rho K_xx,i + K_yy,i/rho)/2,
  // so P is the same at both ends for a^(5/2) (g_0/K_0 - g_1/K_1) = 1/K_1 - 1/K_0.
  AdhesiveSummitGap adhesive_gap(const double s, const double rho,
                                 const std::array<EllipticalUnitLoadSifs, 2> &ends)
  {
    const auto &[k0, k1] = ends;
    if (rho == 1)
      {
        // P(a) = (1 + a^(5/2) g)/(a^(1/2) K) for every circle; both ends of the front averaged.
        const double K = (k0.uniform + k1.uniform) / 2;
        const double g = (k0.xx + k0.yy + k1.xx + k1.yy) / 4;
        const double a = std::pow(1 / (4 * g), 0.4);
        return {s, 1, a, (1 + std::pow(a, 2.5) * g) / (std::sqrt(a) * K)};
      }
    const double g0 = (rho * k0.xx + k0.yy / rho) / 2, g1 = (rho * k1.xx + k1.yy / rho) / 2;
    const double a_to_5_2 = (1 / k1.uniform - 1 / k0.uniform) / (g0 / k0.uniform - g1 / k1.uniform);
    const double infinity = std::numeric_limits<double>::infinity();
    if (!(a_to_5_2 > 0 && std::isfinite(a_to_5_2)))
      return {s, rho, std::nan(""), infinity};
    const double a = std::pow(a_to_5_2, 0.4);
    return {s, rho, a, (1 + a_to_5_2 * g0) / (std::sqrt(a) * k0.uniform)};
  }

  double AdhesiveSummitGap::relative_sif(const EllipticalUnitLoadSifs &K) const
  {
    const double rho = tension_aspect_ratio;
    return tension * std::sqrt(a) * K.uniform - std::pow(a, 2.5) * (rho * K.xx + K.yy / rho) / 2;
  }

  double adhesionless_summit_shape(const EllipticalGapSifs &sifs, const double rho, const double slenderest)
  {
    if (rho == 1)
      return 1;
    // Ay/Ax - rho is 1 - rho > 0 at s = 1 (the circle); from s = rho (every
    // gap is rounder than its summit), halve s until it turns negative.
    const auto excess = [&](const double s) {
      return adhesionless_gap(s, front_ends(sifs, s)).tension_aspect_ratio - rho;
    };
    double hi = 1, excess_hi = 1 - rho, lo = std::max(rho, slenderest), excess_lo = excess(lo);
    for (unsigned int k = 0; excess_lo >= 0; ++k, excess_lo = excess(lo))
      {
        if (k == 6 || lo == slenderest)
          throw std::runtime_error("elliptical summit: no gap down to b/a = " + std::to_string(lo) +
                                   " for Ay/Ax = " + std::to_string(rho));
        hi        = lo;
        excess_hi = excess_lo;
        lo        = std::max(lo / 2, slenderest);
      }
    return bracketed_root(excess, lo, hi, excess_lo, excess_hi, shape_bits);
  }

  double adhesive_summit_shape(const EllipticalGapSifs &sifs, const double rho,
                               const double adhesionless_aspect_ratio)
  {
    if (rho == 1)
      return 1;
    // s = s_0 + t (1 - s_0), t in (0, 1): Brent's tolerance is relative to
    // t, so the search resolves the interval however narrow it gets as
    // Ay/Ax -> 1 (in s it stopped at its start, the circle, once the
    // interval was narrower than the tolerance: Ay/Ax = 0.999).
    const double s_0     = adhesionless_aspect_ratio;
    const auto   shape   = [&](const double t) { return s_0 + t * (1 - s_0); };
    const auto   tension = [&](const double t) {
      return adhesive_gap(shape(t), rho, front_ends(sifs, shape(t))).tension;
    };
    std::uintmax_t iterations = 100;
    const auto [t, P] = boost::math::tools::brent_find_minima(tension, 0., 1., minimum_bits, iterations);
    if (iterations >= 100)
      throw std::runtime_error("elliptical summit: Brent's method did not converge in 100 steps");
    if (!std::isfinite(P))
      throw std::runtime_error("elliptical summit: no adhesive equilibrium for Ay/Ax = " +
                               std::to_string(rho));
    return shape(t);
  }
} // namespace penny
