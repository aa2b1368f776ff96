// The scenes of the 3D elliptical-gap model (doc/theory.md, section 8): one
// gap under uniform pressure, K_I(phi) along its front from the
// front-localised domain integral beside the Green-Sneddon/Irwin closed form.
#pragma once

#include "fe/elliptical_gap_model.h"
#include "input/parameters.h"
#include "output/result_folder.h"

#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  // The elliptical-gap model of the scene's sections.
  EllipticalGapModelParameters elliptical_gap_model(const Parameters &parameters);

  struct EllipticalGapResults
  {
    std::vector<double>              angles;        // parametric angles phi of the front points
    std::vector<double>              ring_radii;    // in units of b^2/a
    std::vector<std::vector<double>> signed_sifs;   // per ring and point (Pa m^1/2)
    std::vector<double>              exact_sifs;    // Green-Sneddon/Irwin, per point
    double                           largest_error; // |K_FE/K_exact - 1| over rings and points
    double                           opening_at_centre, exact_opening_at_centre; // w(0) (m)
    double                           gap_volume, exact_gap_volume;               // m^3
    unsigned long long               n_cells, n_dofs;
    unsigned int                     iterations;
    double                           relative_residual;
    std::string                      solver;
    double                           wall_time;   // s
    double                           peak_memory; // sum over the ranks of the peak resident size (MB)
  };

  // One solve of the uniform pressure; K_I at every front point and ring.
  EllipticalGapResults run_elliptical_gap_scene(const Parameters &parameters, const ResultFolder &results,
                                                std::ostream &log);
} // namespace penny
