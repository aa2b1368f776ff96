#include "problems/stability_cases.h"

#include "input/input_error.h"
#include "output/progress.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"

#include <deal.II/base/mpi.h>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>

#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace penny
{
  std::string StabilityCase::status(const StabilityOutcome &outcome, const std::string &failure) const
  {
    const bool        passes = failure.empty() && outcome.error <= tolerance;
    const std::string reason = passes ? pass_flag(outcome) : expected_miss(outcome);
    const std::string why    = failure.empty() ? "error above tolerance" : "no result: " + failure;
    if (!reason.empty())
      return "flagged: " + reason + (failure.empty() ? "" : " (" + why + ")");
    return passes ? "pass" : "FAIL: " + why;
  }

  std::string setting_text(const std::string &label, const double value)
  {
    std::ostringstream text;
    text << label << value;
    return text.str();
  }

  unsigned int run_stability_cases(const std::vector<StabilityCase> &cases, const CaseSharing sharing,
                                   const ResultFolder &results, std::ostream &log)
  {
    const bool spread = sharing == CaseSharing::one_rank_each;
    Progress   progress(log, "cases");
    // Why a case this rank ran gave no result, by case.
    std::map<unsigned int, std::string> failures_here;
    const auto                          run = [&](const unsigned int i) {
      StabilityOutcome o;
      std::string      failure;
      try
        {
          o = cases[i].run();
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const std::runtime_error &error)
        {
          const double nan = std::numeric_limits<double>::quiet_NaN();
          o                = {nan, nan, nan, nan};
          failure          = error.what();
          failures_here[i] = failure;
        }
      progress.step(cases[i].name + ", " + cases[i].setting + ": " + cases[i].status(o, failure));
      return std::vector<double>{o.error, o.residual, o.condition, o.extra};
    };
    // Gathered in case order on every rank.
    std::vector<std::vector<double>> outcomes;
    if (spread)
      outcomes = spread_over_ranks(MPI_COMM_WORLD, cases.size(), run);
    else
      for (unsigned int i = 0; i < cases.size(); ++i)
        outcomes.push_back(run(i));
    std::map<unsigned int, std::string> failures;
    for (const auto &part : dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, failures_here))
      failures.insert(part.begin(), part.end());

    const Table::Format digits{3, true};
    Table               table({"case",
                               "setting",
                               {"error", digits},
                               "measure",
                               {"tolerance", digits},
                               {"relative residual", digits},
                               {"condition estimate", digits},
                               "status"});
    unsigned int        n_failed = 0;
    for (unsigned int i = 0; i < cases.size(); ++i)
      {
        const StabilityOutcome o{outcomes[i][0], outcomes[i][1], outcomes[i][2], outcomes[i][3]};
        const std::string      status = cases[i].status(o, failures[i]);
        n_failed += status.rfind("FAIL", 0) == 0;
        table.add_row({cases[i].name, cases[i].setting, o.error, cases[i].measure, cases[i].tolerance,
                       o.residual, o.condition, status});
      }
    publish(table, "stability.csv", results, log);
    return n_failed;
  }
} // namespace penny
