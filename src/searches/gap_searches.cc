#include "searches/gap_searches.h"

#include "closed_forms/adhesive_gap.h"
#include "input/input_error.h"
#include "numerics/root_finding.h"

#include <stdexcept>

namespace penny
{
  namespace
  {
    // Both unit load cases at one radius (a batch of one: the first rank of `ranks` solves it).
    PennyUnitSifs sifs_at(PennyGapFamily &gaps, const double c, const MPI_Comm ranks)
    {
      return gaps.unit_load_sifs({c}, ranks)[0];
    }
  } // namespace

  // Starts below the root at c = a/2 (halving until K_I > 0), then brackets upwards.
  double fe_adhesionless_gap_radius(PennyGapFamily &gaps, const double P, const double a,
                                    const MPI_Comm ranks)
  {
    const auto K_I = [&](const double c) {
      const PennyUnitSifs K = sifs_at(gaps, c, ranks);
      return P * K.uniform - P / (a * a) * K.quadratic;
    };
    double lo = 0.5 * a, K_lo = K_I(lo);
    for (unsigned int k = 0; K_lo <= 0; ++k, K_lo = K_I(lo))
      {
        if (k == 20)
          throw std::runtime_error("gap size: K_I(c) is not positive for any c down to 2^-20 a");
        lo /= 2;
      }
    return root_above(K_I, lo, K_lo, "gap size");
  }

  AdhesiveMinimum fe_adhesive_minimum(PennyGapFamily &gaps, const double R_p, const double K_Ic,
                                      const MPI_Comm ranks)
  {
    const auto tension = [&](const PennyUnitSifs &K) { return (K_Ic + K.quadratic / (2 * R_p)) / K.uniform; };
    const auto tensions = [&](const std::vector<double> &radii) {
      std::vector<double> P;
      for (const PennyUnitSifs &K : gaps.unit_load_sifs(radii, ranks))
        P.push_back(tension(K));
      return P;
    };
    const double scale = adhesion_length(R_p, K_Ic);
    const double c_min = fe_stationary_point(
        tensions, 0.25 * scale, 4 * scale, Extremum::minimum, "adhesive minimum of P(c), c in m",
        "the FE models are too coarse (more tip refinement levels or a higher degree)");
    const PennyUnitSifs K = sifs_at(gaps, c_min, ranks);
    return {c_min, tension(K), K.uniform};
  }

  std::optional<double> fe_stable_gap_radius(PennyGapFamily &gaps, const double P, const double R_p,
                                             const double K_Ic, const AdhesiveMinimum &minimum,
                                             const MPI_Comm ranks)
  {
    if (P < minimum.tension)
      return std::nullopt;
    if (P == minimum.tension)
      return minimum.gap_radius;
    const auto excess = [&](const double c) {
      const PennyUnitSifs K = sifs_at(gaps, c, ranks);
      return P * K.uniform - K.quadratic / (2 * R_p) - K_Ic;
    };
    // At the minimum's gap the excess is (P - p0) K_uniform, positive: no solve needed.
    return root_above(excess, minimum.gap_radius, (P - minimum.tension) * minimum.uniform_sif,
                      "stable gap radius at the peak tension P = " + shortest(P) + " Pa");
  }
} // namespace penny
