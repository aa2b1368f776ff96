// The stability scene: one table of stiff and extreme cases around the
// scene's own parameters, each either passing its accuracy check or flagged
// with the reason it is expected to miss it. A case that misses without such a
// reason is a failure.
#pragma once

#include "input/parameters.h"
#include "output/result_folder.h"

#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  struct StabilityRow
  {
    std::string case_name;
    std::string setting;
    double      error;     // see measure
    std::string measure;   // what `error` is
    double      tolerance; // the check the error is held to
    double      residual;  // largest relative residual of the solves
    double      condition; // CG's estimate, 0 where not available
    std::string status;    // "pass", "flagged: <reason>" or "FAIL: <reason>"
  };

  std::vector<StabilityRow> run_stability_scene(const Parameters &parameters, const ResultFolder &results,
                                                std::ostream &log);
} // namespace penny
