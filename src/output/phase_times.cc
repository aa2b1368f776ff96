#include "output/phase_times.h"

#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

namespace penny
{
  namespace
  {
    // This rank's wall time of every phase timed so far (s).
    double own_total_wall_time(const dealii::TimerOutput &timer)
    {
      double total = 0;
      for (const auto &phase : timer.get_summary_data(dealii::TimerOutput::total_wall_time))
        total += phase.second;
      return total;
    }
  } // namespace

  double total_wall_time(const dealii::TimerOutput &timer)
  {
    return dealii::Utilities::MPI::max(own_total_wall_time(timer), MPI_COMM_WORLD);
  }

  void add_phase_times(Table &summary, const dealii::TimerOutput &timer)
  {
    const std::vector<std::string> phases = {
        "mesh", "setup", "assembly", "solve", "J-integral", "axisymmetric model", "closed form", "output"};
    const auto          times = timer.get_summary_data(dealii::TimerOutput::total_wall_time);
    std::vector<double> seconds; // -1: a phase this rank did not run
    for (const auto &phase : phases)
      seconds.push_back(times.count(phase) ? times.at(phase) : -1.);
    seconds.push_back(own_total_wall_time(timer));
    dealii::Utilities::MPI::max(seconds, MPI_COMM_WORLD, seconds);
    const Table::Format format{3, false};
    for (std::size_t i = 0; i < phases.size(); ++i)
      if (seconds[i] >= 0)
        summary.add_row({"wall time " + phases[i] + " (s)", Table::Cell(seconds[i], format)});
    summary.add_row({"wall time total (s)", Table::Cell(seconds.back(), format)});
  }
} // namespace penny
