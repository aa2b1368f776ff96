// The wall times of a run's phases (mesh, setup, assembly, solve, J-integral,
// ...), as timed by a TimerOutput, for the summaries of the scenes.
#pragma once

#include "output/table.h"

#include <deal.II/base/timer.h>

namespace penny
{
  // Wall time of every phase timed so far (s), of the rank that spent the
  // longest (collective on MPI_COMM_WORLD).
  double total_wall_time(const dealii::TimerOutput &timer);

  // Rows "wall time PHASE (s)" in the order the pipeline runs them, and the
  // total, each the longest over the ranks (collective on MPI_COMM_WORLD): for
  // a model shared by the ranks its phases' wall times, for models spread
  // over the ranks those of the busiest rank. Every rank lists the phases
  // that any rank ran, so the rows are the same on any number of ranks.
  void add_phase_times(Table &summary, const dealii::TimerOutput &timer);
} // namespace penny
