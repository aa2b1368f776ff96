// Scenes that recover the paper's constants from FE solves alone: the
// adhesionless gap size c/a = sqrt(3/2), the adhesive minimum psi and c_min,
// the gap-tension curve p_hat(c_hat) (paper Fig. 2) and the adhesive
// equilibrium radius on the stable branch.
#pragma once

#include "input/parameters.h"
#include "output/result_folder.h"

#include <optional>
#include <ostream>

namespace penny
{
  struct GapSizeResult
  {
    double       c_over_a;
    unsigned int n_solves;
  };
  GapSizeResult run_gap_size_scene(const Parameters &parameters, const ResultFolder &results,
                                   std::ostream &log);

  struct AdhesiveMinimumResult
  {
    double       psi, c_min_over_length; // p0/(K_Ic^4/R_p)^(1/5), c_min/(R_p K_Ic)^(2/5)
    unsigned int n_solves;
  };
  AdhesiveMinimumResult run_adhesive_minimum_scene(const Parameters &parameters, const ResultFolder &results,
                                                   std::ostream &log);

  // Largest relative deviation of the FE p_hat from (c_hat^2 + 4/sqrt(c_hat))/5.
  double run_gap_tension_curve_scene(const Parameters &parameters, const ResultFolder &results,
                                     std::ostream &log);

  // The FE equilibrium radius, or nothing when the gap closes (P < p0).
  std::optional<double> run_adhesive_equilibrium_scene(const Parameters   &parameters,
                                                       const ResultFolder &results, std::ostream &log);
} // namespace penny
