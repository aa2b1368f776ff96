#include "output/progress.h"

#include <deal.II/base/mpi.h>

#include <iomanip>

namespace penny
{
  Progress::Progress(std::ostream &log, std::string unit, const double interval)
      : log(log),
        unit(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1 ? unit + " by rank 0" : unit),
        interval(interval), last_line(start)
  {
  }

  void Progress::step(const std::string &state)
  {
    ++steps;
    const auto now = Clock::now();
    if (steps > 1 && std::chrono::duration<double>(now - last_line).count() < interval)
      return;
    last_line = now;
    log << "  [" << std::fixed << std::setprecision(1) << std::setw(6)
        << std::chrono::duration<double>(now - start).count() << " s] " << steps << ' ' << unit << ", "
        << state << std::defaultfloat << std::endl;
  }
} // namespace penny
