// What the scenes share: the relative error they report, the model their
// parameters describe, and the opening lines of every FE scene.
#pragma once

#include "fe/penny_gap_model.h"
#include "fracture/gap_family.h"
#include "input/parameters.h"

#include <deal.II/base/timer.h>

#include <cmath>
#include <ostream>

namespace penny
{
  // |value/reference - 1|, or |value| against a zero reference.
  inline double
  relative_error(const double value, const double reference)
  {
    return reference == 0 ? std::abs(value) : std::abs(value / reference - 1);
  }

  // The penny-gap model of the FE sections.
  PennyGapModelParameters penny_gap_model(const Parameters &parameters);

  // Wall time of every phase timed so far (s).
  double total_wall_time(const dealii::TimerOutput &timer);

  // The scenes that search over gap radii: a timer of the phases and the
  // family of models on the scene's model, using the last J-integral ring.
  struct GapSearch
  {
    explicit GapSearch(const Parameters &parameters);

    dealii::TimerOutput timer;
    GapFamily           gaps;
    const double        summit_radius;             // R_p (m^2/Pa)
    const double        critical_stress_intensity; // K_Ic (Pa m^1/2); 0 without an Adhesion section
  };
} // namespace penny
