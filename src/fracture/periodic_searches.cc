#include "fracture/periodic_searches.h"

#include "fracture/root_finding.h"

#include <boost/math/tools/minima.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace penny
{
  namespace
  {
    // The maximum of f on [lo, hi] by Brent's parabolic search on -f, to half
    // the double digits (the most a maximum allows); it must lie inside.
    template <typename F>
    std::pair<double, double> interior_maximum(F &&f, const double lo, const double hi,
                                               const std::string &what)
    {
      std::uintmax_t iterations = 100;
      const auto [x, minus_f]   = boost::math::tools::brent_find_minima([&](const double c) { return -f(c); },
                                                                      lo, hi, 26, iterations);
      if (iterations >= 100)
        throw std::runtime_error(what + ": Brent's method did not converge in 100 steps");
      const double margin = 1e-3 * (hi - lo);
      if (x < lo + margin || x > hi - margin)
        throw std::runtime_error(what + ": the maximum lies at the end of the search interval");
      return {x, -minus_f};
    }
  } // namespace

  double fe_johnson_load(const SinusoidUnitSifs &K, const double wavelength, const double alpha)
  {
    return (K.cosine - alpha * std::sqrt(wavelength)) / K.uniform;
  }

  // K_cosine/K_uniform falls from 1 at c = 0 to 0 at c = lambda/2: the bracket
  // starts at lambda/4 and moves towards the end beyond which the root lies,
  // halving its distance to it each step.
  double fe_westergaard_contact_half_width(PeriodicGapFamily &gaps, const double load_ratio)
  {
    if (!(load_ratio > 0 && load_ratio < 1))
      throw std::invalid_argument("Westergaard contact: p_bar/p* must lie in (0, 1)");
    const double half   = gaps.wavelength() / 2;
    const auto   excess = [&](const double c) {
      const SinusoidUnitSifs K = gaps.unit_load_sifs(c);
      return K.cosine / K.uniform - load_ratio;
    };
    double lo = half / 2, f_lo = excess(lo), hi = lo, f_hi = f_lo;
    for (double step = half / 4; (f_lo > 0) == (f_hi > 0); step /= 2)
      {
        if (step < 1e-9 * half)
          throw std::runtime_error("Westergaard contact: no sign change of K_I within (0, lambda/2)");
        if (f_hi > 0)
          {
            lo   = hi;
            f_lo = f_hi;
            f_hi = excess(hi = half - step);
          }
        else
          {
            hi   = lo;
            f_hi = f_lo;
            f_lo = excess(lo = step);
          }
      }
    return half - bracketed_root(excess, lo, hi, f_lo, f_hi, fe_root_bits);
  }

  FeLoadExtremum fe_jump_into_contact(PeriodicGapFamily &gaps, const double alpha)
  {
    const double lambda   = gaps.wavelength();
    const double adhesion = lambda * std::pow(alpha, 0.4);
    const auto [c, load]  = interior_maximum(
        [&](const double c) { return fe_johnson_load(gaps.unit_load_sifs(c), lambda, alpha); }, adhesion / 16,
        std::min(adhesion / 2, lambda / 4), "jump into contact");
    return {lambda / 2 - c, load};
  }

  FeCriticalAdhesion fe_critical_alpha(PeriodicGapFamily &gaps)
  {
    const double lambda = gaps.wavelength();
    const auto [c, alpha] =
        interior_maximum([&](const double c) { return gaps.unit_load_sifs(c).cosine / std::sqrt(lambda); },
                         lambda / 16, 7 * lambda / 16, "critical alpha");
    return {lambda / 2 - c, alpha};
  }
} // namespace penny
