// The paper's constants found from FE solves alone, by root finding and
// minimisation over the gap radius c of a PennyGapFamily. Closed-form values never
// enter a search, which only uses the natural length scale (R_p K_Ic)^(2/5)
// to place its first bracket. `ranks` share a search's FE models (see
// GapFamily): all ranks for a search of its own, MPI_COMM_SELF for a search
// inside one piece of a sweep. The result is the same on any number of ranks.
#pragma once

#include "searches/gap_family.h"

#include <optional>

namespace penny
{
  struct AdhesiveMinimum
  {
    double gap_radius;  // c_min (m)
    double tension;     // p0 = P(c_min) (Pa)
    double uniform_sif; // K_I of unit uniform pressure on the gap c_min (Pa m^1/2 per Pa)
  };

  // Adhesionless gap: the root of the FE K_I(c) of the parabola (P, a).
  double fe_adhesionless_gap_radius(PennyGapFamily &gaps, double P, double a, MPI_Comm ranks);

  // Minimum over c of the FE P(c) = [K_Ic + K_quadratic(c)/(2 R_p)] / K_uniform(c):
  // the root of its difference quotient (fe_stationary_point; the two
  // models of each quotient are solved side by side on two ranks), then P
  // at that c from one more model.
  AdhesiveMinimum fe_adhesive_minimum(PennyGapFamily &gaps, double R_p, double K_Ic, MPI_Comm ranks);

  // FE g: the radius c >= c_min where P K_uniform(c) - K_quadratic(c)/(2 R_p) = K_Ic,
  // or nothing when P < p0 (the gap closes: full contact).
  std::optional<double> fe_stable_gap_radius(PennyGapFamily &gaps, double P, double R_p, double K_Ic,
                                             const AdhesiveMinimum &minimum, MPI_Comm ranks);
} // namespace penny
