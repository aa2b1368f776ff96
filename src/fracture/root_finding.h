// Roots of scalar functions by bracketing (Boost's TOMS 748, a refinement of
// Brent's method), for closed forms and for functions evaluated by FE solves.
#pragma once

#include <boost/math/tools/roots.hpp>

#include <cstdint>
#include <stdexcept>

namespace penny
{
  // Bits of the root: about 1e-12 relative for FE functions, above the
  // rounding noise of the FE K_I; full precision for closed forms.
  constexpr int fe_root_bits = 40, closed_form_root_bits = 52;

  // The root of f on [lo, hi], where f(lo) and f(hi) differ in sign.
  template <typename F>
  double bracketed_root(F &&f, const double lo, const double hi, const double f_lo, const double f_hi,
                        const int bits)
  {
    std::uintmax_t iterations = 100;
    const auto     bracket    = boost::math::tools::toms748_solve(
               f, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(bits), iterations);
    if (iterations >= 100)
      throw std::runtime_error("root finder: no convergence in 100 iterations");
    return 0.5 * (bracket.first + bracket.second);
  }

  // The first root above lo, where f(lo) > 0: the bracket widens geometrically
  // until f changes sign.
  template <typename F> double root_above(F &&f, double lo, double f_lo, const int bits = fe_root_bits)
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
} // namespace penny
