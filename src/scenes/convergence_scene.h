// The convergence scene: one penny-gap solve over a sequence of
// discretisations, with K_I errors, observed rates against DoFs, wall time per
// phase and peak memory in one table.
#pragma once

#include "input/parameters.h"
#include "output/result_folder.h"

#include <ostream>
#include <vector>

namespace penny
{
  struct ConvergenceRow
  {
    unsigned int        cycle, n_cells, n_dofs;
    double              setting; // what the sequence varies: refinements, levels, degree or R/c
    std::vector<double> stress_intensity_factors; // signed, one per ring
    double              error;                    // largest relative error over the rings
    double              rate;                     // -d log(error) / d log(DoFs) from the previous cycle
    double              wall_time;
  };

  std::vector<ConvergenceRow> run_convergence_scene(const Parameters &parameters, const ResultFolder &results,
                                                    std::ostream &log);
} // namespace penny
