// The penny-gap scene: one FE solve of the scene's load, the J-integral on
// every ring, and the FE figures beside Sneddon's closed forms, printed and
// written to the output folder.
#pragma once

#include "fe/face_load.h"
#include "fe/penny_gap_model.h"
#include "fracture/sneddon_solution.h"
#include "input/parameters.h"
#include "output/result_folder.h"

#include <deal.II/base/timer.h>

#include <ostream>
#include <vector>

namespace penny
{
  struct RingResult
  {
    double radius;                         // in units of c
    double energy_release_rate;            // J (J/m^2)
    double stress_intensity_factor;        // |K_I| = sqrt(E' J) (Pa m^1/2)
    double signed_stress_intensity_factor; // from B(u, u_ref), u_ref under unit pressure
  };

  struct PennySceneResults
  {
    std::vector<RingResult> rings;
    ClosedForm              exact_stress_intensity_factor;
    double                  opening_at_centre; // one face (m)
    ClosedForm              exact_opening_at_centre;
    double                  gap_volume; // both faces (m^3)
    ClosedForm              exact_gap_volume;
    unsigned int            n_cells;
    unsigned int            n_dofs;
    double                  relative_residual;  // the larger of the two solves
    double                  condition_estimate; // CG's estimate; 0 for the direct solver
    std::string             solver;
  };

  // Solve, J-integrals on the rings (radii in units of c) and closed forms on
  // a model already built (perhaps adaptively refined); the fields go to
  // `fields` unless it is null.
  PennySceneResults measure_penny_gap(PennyGapModel &model, const FaceLoad &load,
                                      const std::vector<double> &ring_radii, dealii::TimerOutput &timer,
                                      const ResultFolder *fields = nullptr);

  // The same on a model built for `model`.
  PennySceneResults solve_penny_gap(const PennyGapModelParameters &model, const LoadParameters &load,
                                    const std::vector<double> &ring_radii, dealii::TimerOutput &timer);

  // The scene: the table printed and the result files written.
  PennySceneResults run_penny_gap_scene(const Parameters &parameters, const ResultFolder &results,
                                        std::ostream &log);
} // namespace penny
