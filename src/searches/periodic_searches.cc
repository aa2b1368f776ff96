#include "searches/periodic_searches.h"

#include "input/input_error.h"
#include "numerics/root_finding.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace penny
{
  namespace
  {
    // The maximum of f(K(c)) over c in [lo, hi], where K are the unit load
    // SIFs at c: its place and value (one more model at the place).
    template <typename F>
    std::pair<double, double> interior_maximum(PeriodicGapFamily &gaps, F &&f, const double lo,
                                               const double hi, const MPI_Comm ranks, const std::string &what)
    {
      const auto values = [&](const std::vector<double> &half_widths) {
        std::vector<double> values;
        for (const SinusoidUnitSifs &K : gaps.unit_load_sifs(half_widths, ranks))
          values.push_back(f(K));
        return values;
      };
      const double c = fe_stationary_point(values, lo, hi, Extremum::maximum, what,
                                           "the FE models are too coarse or too shallow (more tip "
                                           "refinement levels, a deeper solid or a higher degree)");
      return {c, values({c})[0]};
    }
  } // namespace

  double fe_johnson_load(const SinusoidUnitSifs &K, const double wavelength, const double alpha)
  {
    return (K.cosine - alpha * std::sqrt(wavelength)) / K.uniform;
  }

  // K_cosine/K_uniform falls from 1 at c = 0 to 0 at c = lambda/2: the bracket
  // starts at lambda/4 and moves towards the end beyond which the root lies,
  // halving its distance to it each step.
  double fe_westergaard_contact_half_width(PeriodicGapFamily &gaps, const double load_ratio,
                                           const MPI_Comm ranks)
  {
    if (!(load_ratio > 0 && load_ratio < 1))
      throw std::invalid_argument("Westergaard contact: p_bar/p* must lie in (0, 1)");
    const double half   = gaps.members().model.wavelength / 2;
    const auto   excess = [&](const double c) {
      const SinusoidUnitSifs K = gaps.unit_load_sifs({c}, ranks)[0];
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

  FeLoadExtremum fe_jump_into_contact(PeriodicGapFamily &gaps, const double alpha, const MPI_Comm ranks)
  {
    const double lambda   = gaps.members().model.wavelength;
    const double adhesion = lambda * std::pow(alpha, 0.4);
    const auto [c, load]  = interior_maximum(
         gaps, [&](const SinusoidUnitSifs &K) { return fe_johnson_load(K, lambda, alpha); }, adhesion / 16,
         std::min(adhesion / 2, lambda / 4), ranks,
         "jump into contact at alpha = " + shortest(alpha) + ", maximum over the gap half-width c in m");
    return {lambda / 2 - c, load};
  }

  FeCriticalAdhesion fe_critical_alpha(PeriodicGapFamily &gaps, const MPI_Comm ranks)
  {
    const double lambda   = gaps.members().model.wavelength;
    const auto [c, alpha] = interior_maximum(
        gaps, [&](const SinusoidUnitSifs &K) { return K.cosine / std::sqrt(lambda); }, lambda / 16,
        7 * lambda / 16, ranks, "critical alpha, maximum over the gap half-width c in m");
    return {lambda / 2 - c, alpha};
  }
} // namespace penny
