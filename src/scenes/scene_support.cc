#include "scenes/scene_support.h"

#include <iostream>

namespace penny
{
  PennyGapModelParameters
  penny_gap_model(const Parameters &parameters)
  {
    return { parameters.geometry.value(),
             parameters.material.value(),
             parameters.mesh.value(),
             parameters.finite_element.value().degree,
             parameters.linear_solver.value() };
  }

  double
  total_wall_time(const dealii::TimerOutput &timer)
  {
    double total = 0;
    for (const auto &phase : timer.get_summary_data(dealii::TimerOutput::total_wall_time))
      total += phase.second;
    return total;
  }

  GapSearch::GapSearch(const Parameters &parameters)
      : timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times),
        gaps(penny_gap_model(parameters), parameters.j_integral.value().ring_radii.back(), timer),
        summit_radius(parameters.load.value().summit_radius),
        critical_stress_intensity(parameters.adhesion ? parameters.adhesion->critical_stress_intensity : 0)
  {
  }
} // namespace penny
