// The cases of the stability scenes: each runs one or more models and gives
// an error held to a tolerance. A case passes, or is flagged with the reason
// it is expected to miss (or with a caveat on its pass), or fails. All cases
// in one table, stability.csv.
#pragma once

#include "output/result_folder.h"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  // What a case's solves give: its error, the largest relative residual,
  // CG's condition estimate (0 where not available) and one more number a
  // case may need for its status.
  struct StabilityOutcome
  {
    double error, residual, condition, extra = 0;
  };

  struct StabilityCase
  {
    std::string                       name, setting, measure; // measure: what the error is
    double                            tolerance;
    std::function<StabilityOutcome()> run;
    // Why the case may miss the tolerance (from its outcome); empty: it must pass.
    std::function<std::string(const StabilityOutcome &)> expected_miss = [](const StabilityOutcome &) {
      return std::string();
    };
    // A flag that replaces a pass (from its outcome); empty: none.
    std::function<std::string(const StabilityOutcome &)> pass_flag = [](const StabilityOutcome &) {
      return std::string();
    };

    // "pass", "flagged: <reason>" or "FAIL: <reason>". `failure`: why the
    // case's models gave no result (its error is then NaN); empty if they did.
    std::string status(const StabilityOutcome &outcome, const std::string &failure = "") const;
  };

  // The text `label` followed by `value`, e.g. "nu = 0.49".
  std::string setting_text(const std::string &label, double value);

  // How the cases share the MPI ranks: each case's models on one rank and the
  // cases spread over the ranks, or each case's models on all the ranks and
  // the cases one after the other.
  enum class CaseSharing
  {
    one_rank_each,
    all_ranks
  };

  // Runs the cases, writes stability.csv (and the table to `log`) and
  // returns how many cases failed. A case whose models give no result (a
  // solver that does not converge, a J-integral that cannot sign K_I) is
  // flagged if it is expected to miss, and fails otherwise, with the reason;
  // the other cases still run. Input errors stop the scene.
  unsigned int run_stability_cases(const std::vector<StabilityCase> &cases, CaseSharing sharing,
                                   const ResultFolder &results, std::ostream &log);
} // namespace penny
