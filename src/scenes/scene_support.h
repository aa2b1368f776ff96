// What the scenes share: the relative error they report, their verdicts, the
// model their parameters describe, the phase timings of their summaries, and
// the opening lines of the scenes that search over gap radii.
#pragma once

#include "fe/penny_gap_model.h"
#include "fracture/gap_family.h"
#include "input/parameters.h"
#include "output/progress.h"
#include "output/table.h"

#include <deal.II/base/timer.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  // |value/reference - 1|, or |value| against a zero reference.
  inline double relative_error(const double value, const double reference)
  {
    return reference == 0 ? std::abs(value) : std::abs(value / reference - 1);
  }

  // A scene's judgement of its own results: a failed check is reported after
  // the results are written, and makes the run exit non-zero. A scene without
  // a check passes with an empty message.
  struct Verdict
  {
    bool        passed = true;
    std::string message;
  };

  // PASS when `error` (what it measures: `what`) is within `tolerance`.
  Verdict verdict(const std::string &what, double error, double tolerance);

  // The penny-gap model of the FE sections.
  PennyGapModelParameters penny_gap_model(const Parameters &parameters);

  // Wall time of every phase timed so far (s), of the rank that spent the
  // longest (collective on MPI_COMM_WORLD).
  double total_wall_time(const dealii::TimerOutput &timer);

  // Rows "wall time PHASE (s)" in the order the pipeline runs them, and the
  // total, each the longest over the ranks (collective on MPI_COMM_WORLD): for
  // a model shared by the ranks its phases' wall times, for models spread
  // over the ranks those of the busiest rank. Every rank lists the phases
  // that any rank ran, so the rows are the same on any number of ranks.
  void add_phase_times(Table &summary, const dealii::TimerOutput &timer);

  // The scenes that search over gap radii: a timer of the phases, the family
  // of models on the scene's model (using the last J-integral ring), and a
  // progress line as the solves go. Every model lives on one rank; a search
  // of its own shares its models out over all ranks, and a sweep of
  // independent searches gives each rank its share of them
  // (parallel/spread_over_ranks.h), each search on its rank alone. The
  // results do not depend on the number of ranks.
  struct GapSearch
  {
    GapSearch(const Parameters &parameters, std::ostream &log);
    GapSearch(const GapSearch &) = delete;

    // FE solves of all ranks (collective).
    unsigned int n_solves() const;

    dealii::TimerOutput timer;
    GapFamily           gaps;
    Progress            progress;
    const double        summit_radius;             // R_p (m^2/Pa)
    const double        critical_stress_intensity; // K_Ic (Pa m^1/2); 0 without an Adhesion section
  };
} // namespace penny
