#include "scenes/scene_support.h"

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace penny
{
  Verdict verdict(const std::string &what, const double error, const double tolerance)
  {
    std::ostringstream message;
    message.precision(2);
    message << std::scientific << what << ' ' << error << (error <= tolerance ? " <= " : " > ")
            << "Verification/Tolerance = " << tolerance;
    return {error <= tolerance, message.str()};
  }

  PennyGapModelParameters penny_gap_model(const Parameters &parameters)
  {
    PennyGapModelParameters model{parameters.geometry.value(), parameters.material.value(),
                                  parameters.mesh.value(), parameters.finite_element.value().degree,
                                  parameters.linear_solver.value()};
    model.levels_per_degree = parameters.finite_element.value().levels_per_degree;
    return model;
  }

  unsigned int GapSearch::n_solves() const
  {
    return dealii::Utilities::MPI::sum(gaps.n_solves(), MPI_COMM_WORLD);
  }

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

  GapSearch::GapSearch(const Parameters &parameters, std::ostream &log)
      : timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times),
        gaps(penny_gap_model(parameters), parameters.j_integral.value().ring_radii.back(), timer),
        progress(log, "gap radii solved"), summit_radius(parameters.load.value().summit_radius),
        critical_stress_intensity(parameters.adhesion ? parameters.adhesion->critical_stress_intensity : 0)
  {
    gaps.observe([this](const double c) {
      std::ostringstream state;
      state.precision(10);
      state << "last c = " << c << " m";
      progress.step(state.str());
    });
  }
} // namespace penny
