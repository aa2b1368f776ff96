// What the scenes share: the relative error they report, their verdicts, the
// model their parameters describe, the phase timings of their summaries, and
// the opening lines of the scenes that search over gap radii.
#pragma once

#include "fe/penny_gap_model.h"
#include "fracture/gap_family.h"
#include "input/parameters.h"
#include "output/progress.h"
#include "output/table.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <cstring>
#include <ostream>
#include <string>
#include <type_traits>
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

  // Wall time of every phase timed so far (s).
  double total_wall_time(const dealii::TimerOutput &timer);

  // Rows "wall time PHASE (s)" in the order the pipeline runs them, and the total.
  void add_phase_times(Table &summary, const dealii::TimerOutput &timer);

  // The scenes that search over gap radii: a timer of the phases, the family
  // of models on the scene's model (using the last J-integral ring), and a
  // progress line as the solves go. Every model lives on one rank
  // (MPI_COMM_SELF): a search is sequential, so each rank runs it alike, and a
  // sweep of independent searches gives each rank its share
  // (spread_over_ranks). The results do not depend on the number of ranks.
  struct GapSearch
  {
    GapSearch(const Parameters &parameters, std::ostream &log);
    GapSearch(const GapSearch &) = delete;

    // FE solves of all ranks.
    unsigned int n_solves() const;

    dealii::TimerOutput timer;
    GapFamily           gaps;
    Progress            progress;
    const double        summit_radius;             // R_p (m^2/Pa)
    const double        critical_stress_intensity; // K_Ic (Pa m^1/2); 0 without an Adhesion section
  };

  // f(0), ..., f(n - 1) on every rank: rank k evaluates the i with
  // i mod (number of ranks) = k, and the values are gathered. T must be
  // trivially copyable.
  template <typename T, typename F> std::vector<T> spread_over_ranks(const unsigned int n, const F &f)
  {
    static_assert(std::is_trivially_copyable_v<T>, "the values travel between ranks as bytes");
    const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int rank  = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    std::vector<char>  mine;
    for (unsigned int i = rank; i < n; i += ranks)
      {
        const T value = f(i);
        mine.insert(mine.end(), reinterpret_cast<const char *>(&value),
                    reinterpret_cast<const char *>(&value) + sizeof(T));
      }
    const auto     shares = dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, mine);
    std::vector<T> all(n);
    for (unsigned int i = 0; i < n; ++i)
      std::memcpy(&all[i], shares[i % ranks].data() + (i / ranks) * sizeof(T), sizeof(T));
    return all;
  }
} // namespace penny
