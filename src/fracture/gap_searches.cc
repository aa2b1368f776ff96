#include "fracture/gap_searches.h"

#include "fracture/adhesive_gap.h"
#include "fracture/root_finding.h"

#include <boost/math/tools/minima.hpp>

#include <limits>
#include <stdexcept>

namespace penny
{
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
    // Brent's method returns the evaluated point of least tension: kept with its K_I.
    AdhesiveMinimum least{0, std::numeric_limits<double>::infinity(), 0};
    const auto      tension = [&](const double c) {
      const UnitLoadSifs K = gaps.unit_load_sifs(c);
      const double       P = (K_Ic + K.quadratic / (2 * R_p)) / K.uniform;
      if (P <= least.tension) // as Boost keeps the later of equal values
        least = {c, P, K.uniform};
      return P;
    };
    const double   scale      = adhesion_length(R_p, K_Ic);
    std::uintmax_t iterations = 100;
    // Brent's parabolic minimiser to half the double digits, the most a minimum allows.
    const auto [c_min, p0] =
        boost::math::tools::brent_find_minima(tension, 0.25 * scale, 4 * scale, 26, iterations);
    if (iterations >= 100)
      throw std::runtime_error("adhesive minimum: Brent's method did not converge in 100 steps");
    if (c_min < 0.26 * scale || c_min > 3.9 * scale)
      throw std::runtime_error("adhesive minimum: the minimum lies at the end of the search interval");
    if (c_min != least.gap_radius || p0 != least.tension)
      throw std::logic_error(
          "adhesive minimum: Brent's method returned a point other than the least it evaluated");
    return least;
  }

  std::optional<double> fe_stable_gap_radius(GapFamily &gaps, const double P, const double R_p,
                                             const double K_Ic, const AdhesiveMinimum &minimum)
  {
    if (P < minimum.tension)
      return std::nullopt;
    const auto excess = [&](const double c) {
      const UnitLoadSifs K = gaps.unit_load_sifs(c);
      return P * K.uniform - K.quadratic / (2 * R_p) - K_Ic;
    };
    if (P == minimum.tension)
      return minimum.gap_radius;
    // At the minimum's gap the excess is (P - p0) K_uniform, positive: no solve needed.
    return root_above(excess, minimum.gap_radius, (P - minimum.tension) * minimum.uniform_sif);
  }
} // namespace penny
