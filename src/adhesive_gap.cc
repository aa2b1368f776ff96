#include "adhesive_gap.h"

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <stdexcept>

namespace penny
{
  namespace
  {
    const double sqrt_pi = std::sqrt(M_PI);

    // Bits of c a root is found to: about 1e-12 relative for FE functions,
    // above the rounding noise of the FE K_I; full precision for closed forms.
    constexpr int fe_root_bits = 40, closed_form_root_bits = 52;

    // Bracketing root of f on [lo, hi] (TOMS 748, Brent's method refined).
    template <typename F>
    double bracketed_root(F &&f, const double lo, const double hi, const double f_lo, const double f_hi, const int bits)
    {
      std::uintmax_t iterations = 100;
      const auto     bracket =
        boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(bits), iterations);
      if (iterations >= 100)
        throw std::runtime_error("root finder: no convergence in 100 iterations");
      return 0.5 * (bracket.first + bracket.second);
    }

    // Widens [lo, hi] geometrically until f changes sign; f(lo) must be > 0.
    template <typename F>
    double root_above(F &&f, double lo, double f_lo, const int bits = fe_root_bits)
    {
      if (!(f_lo > 0))
        throw std::runtime_error("root finder: the lower bracket end has no positive value");
      double hi = 2 * lo, f_hi = f(hi);
      for (unsigned int k = 0; f_hi > 0; ++k, f_hi = f(hi))
        {
          if (k == 20)
            throw std::runtime_error("root finder: no sign change up to 2^20 times the start");
          lo   = hi;
          f_lo = f_hi;
          hi *= 2;
        }
      return bracketed_root(f, lo, hi, f_lo, f_hi, bits);
    }
  } // namespace

  double closed_form::adhesive_tension(const double c, const double R_p, const double K_Ic)
  {
    return c * c / (3 * R_p) + sqrt_pi * K_Ic / (2 * std::sqrt(c));
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
    return root_above(f, c_min, f(c_min), closed_form_root_bits);
  }

  double adhesion_length(const double R_p, const double K_Ic)
  {
    return std::pow(R_p * K_Ic, 0.4);
  }

  double adhesion_tension(const double R_p, const double K_Ic)
  {
    return std::pow(std::pow(K_Ic, 4) / R_p, 0.2);
  }

  // Starts below the root at c = a/2 (halving until K_I > 0), then brackets upwards.
  double fe_adhesionless_gap_radius(GapFamily &gaps, const double P, const double a)
  {
    const auto K_I = [&](const double c) { return gaps.parabolic_stress_intensity_factor(c, P, a); };
    double     lo = 0.5 * a, K_lo = K_I(lo);
    for (unsigned int k = 0; K_lo <= 0; ++k, K_lo = K_I(lo))
      {
        if (k == 20)
          throw std::runtime_error("gap size: K_I(c) is not positive for any c down to 2^-20 a");
        lo /= 2;
      }
    return root_above(K_I, lo, K_lo);
  }

  AdhesiveMinimum fe_adhesive_minimum(GapFamily &gaps, const double R_p, const double K_Ic)
  {
    const auto tension = [&](const double c) {
      const UnitLoadSifs K = gaps.unit_load_sifs(c);
      return (K_Ic + K.quadratic / (2 * R_p)) / K.uniform;
    };
    const double   scale      = adhesion_length(R_p, K_Ic);
    std::uintmax_t iterations = 100;
    // Brent's parabolic minimiser to half the double digits, the most a minimum allows.
    const auto [c_min, p0] = boost::math::tools::brent_find_minima(tension, 0.25 * scale, 4 * scale, 26, iterations);
    if (iterations >= 100)
      throw std::runtime_error("adhesive minimum: Brent's method did not converge in 100 steps");
    if (c_min < 0.26 * scale || c_min > 3.9 * scale)
      throw std::runtime_error("adhesive minimum: the minimum lies at the end of the search interval");
    return {c_min, p0};
  }

  std::optional<double> fe_stable_gap_radius(GapFamily             &gaps,
                                             const double           P,
                                             const double           R_p,
                                             const double           K_Ic,
                                             const AdhesiveMinimum &minimum)
  {
    if (P < minimum.tension)
      return std::nullopt;
    const auto excess = [&](const double c) {
      const UnitLoadSifs K = gaps.unit_load_sifs(c);
      return P * K.uniform - K.quadratic / (2 * R_p) - K_Ic;
    };
    if (P == minimum.tension)
      return minimum.gap_radius;
    return root_above(excess, minimum.gap_radius, excess(minimum.gap_radius));
  }
} // namespace penny
