// Roots of scalar functions by bracketing (Boost's TOMS 748, a refinement of
// Brent's method), for closed forms and for functions evaluated by FE solves;
// the extremes of FE functions as roots of their difference quotients.
#pragma once

#include <boost/math/tools/roots.hpp>

#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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

  // The first root above lo, where f(lo) > 0: the bracket doubles, at most
  // `doublings` times, until f changes sign. `what` names the root in errors.
  template <typename F>
  double root_above(F &&f, double lo, double f_lo, const std::string &what, const int bits = fe_root_bits,
                    const unsigned int doublings = 21)
  {
    if (!(f_lo > 0))
      throw std::runtime_error(what + ": the search starts where the function is not positive");
    double hi = 2 * lo, f_hi = f(hi);
    for (unsigned int k = 1; f_hi > 0; ++k, f_hi = f(hi))
      {
        if (k == doublings)
          throw std::runtime_error(what + ": no root up to 2^" + std::to_string(doublings) +
                                   " times where the search started");
        lo   = hi;
        f_lo = f_hi;
        hi *= 2;
      }
    return bracketed_root(f, lo, hi, f_lo, f_hi, bits);
  }

  enum class Extremum
  {
    minimum,
    maximum
  };

  // The interior minimum or maximum x of a smooth FE function f on [lo, hi]
  // (lo > 0): the root of its central difference quotient
  // (f(x + hx) - f(x - hx))/(2hx), h = 1e-4, by TOMS 748 to 26 bits.
  // `values` returns f at a list of points, a batch of independent FE solves
  // that the caller may spread over MPI ranks: each quotient is one batch of
  // two, the quotients at both ends one batch of four. A minimiser of f
  // itself places x only to the square root of the rounding noise of f
  // (1e-6 for noise 1e-12); the root of the quotient places it to about
  // noise/h + h^2 |f'''/(6 f'')| x, 1e-8 here. `what` names the search in
  // its errors; `remedy` says what to change when the extremum is not inside.
  template <typename Values>
  double fe_stationary_point(Values &&values, const double lo, const double hi, const Extremum kind,
                             const std::string &what, const std::string &remedy)
  {
    constexpr double h         = 1e-4;
    constexpr int    bits      = 26;
    const double     ascent    = kind == Extremum::minimum ? 1 : -1;
    const auto       quotients = [&](const std::vector<double> &xs) {
      std::vector<double> points;
      for (const double x : xs)
        points.insert(points.end(), {x * (1 - h), x * (1 + h)});
      const std::vector<double> f = values(points);
      std::vector<double>       quotient;
      for (std::size_t i = 0; i < xs.size(); ++i)
        quotient.push_back(ascent * (f[2 * i + 1] - f[2 * i]) / (2 * h * xs[i]));
      return quotient;
    };
    const std::vector<double> ends = quotients({lo, hi});
    if (!(ends[0] < 0 && ends[1] > 0))
      {
        std::ostringstream message;
        message.precision(3);
        message << what << ": the " << (kind == Extremum::minimum ? "minimum" : "maximum")
                << " lies at an end of the search interval [" << lo << ", " << hi << "]; " << remedy;
        throw std::runtime_error(message.str());
      }
    return bracketed_root([&](const double x) { return quotients({x})[0]; }, lo, hi, ends[0], ends[1], bits);
  }
} // namespace penny
