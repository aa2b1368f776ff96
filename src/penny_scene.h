// The penny-gap scene: one FE solve of the scene's load, the J-integral on
// every ring, and the FE figures beside Sneddon's closed forms, printed and
// written to the output folder.
#pragma once

#include "parameters.h"
#include "penny_gap_model.h"

#include <deal.II/base/timer.h>

#include <ostream>
#include <vector>

namespace penny
{
  struct RingResult
  {
    double radius;                   // in units of c
    double energy_release_rate;      // J (J/m^2)
    double stress_intensity_factor;  // |K_I| = sqrt(E' J) (Pa m^1/2)
    double signed_stress_intensity_factor; // from B(u, u_ref), u_ref under unit pressure
  };

  struct PennySceneResults
  {
    std::vector<RingResult> rings;
    double                  exact_stress_intensity_factor;
    double                  opening_at_centre, exact_opening_at_centre; // one face (m)
    double                  gap_volume, exact_gap_volume;               // both faces (m^3)
    unsigned int            n_cells;
    unsigned int            n_dofs;
    double                  relative_residual;  // the larger of the two solves
    double                  condition_estimate; // CG's estimate; 0 for the direct solver
  };

  // The computation of the scene: solve, J-integrals, closed forms, and the
  // fields when the parameters ask for them.
  PennySceneResults solve_penny_gap(const Parameters &parameters, dealii::TimerOutput &timer);

  // The same on a model already built (and perhaps adaptively refined).
  PennySceneResults measure_penny_gap(PennyGapModel &model, dealii::TimerOutput &timer);

  // solve_penny_gap, then the table printed and the result files written.
  PennySceneResults run_penny_scene(const Parameters &parameters, std::ostream &log);
} // namespace penny
