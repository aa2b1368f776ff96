// The scenes of the 3D elliptical-gap model (doc/theory.md, section 8): one
// gap under uniform pressure, K_I(phi) along its front from the
// front-localised domain integral beside the Green-Sneddon/Irwin closed form
// (and, for the circle, the axisymmetric model); and the gaps of summits with
// two principal radii, with and without adhesion, beside Galin's closed form.
#pragma once

#include "fe/elliptical_gap_model.h"
#include "fracture/elliptical_summits.h"
#include "input/parameters.h"
#include "output/result_folder.h"

#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  // The elliptical-gap model of the scene's sections for the semi-axes (a, b) (m).
  EllipticalGapModelParameters elliptical_gap_model(const Parameters &parameters, double a, double b);

  struct EllipticalGapResults
  {
    std::vector<double>              angles;            // parametric angles phi of the front points
    std::vector<double>              ring_radii;        // in units of b^2/a
    std::vector<std::vector<double>> signed_sifs;       // per ring and point (Pa m^1/2)
    std::vector<double>              exact_sifs;        // Green-Sneddon/Irwin, per point
    std::vector<double>              axisymmetric_sifs; // the axisymmetric FE model's, for b/a = 1
    double                           largest_error;     // |K_FE/K_exact - 1| over rings and points
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

  // The gaps of one summit Ay/Ax by one method (FE or Galin's closed form).
  struct SummitGaps
  {
    AdhesionlessSummitGap adhesionless;
    AdhesiveSummitGap     adhesive;
    std::vector<double>
        adhesionless_front;             // K_I/(P K_uniform) at the front points: 0 if the ellipse is exact
    std::vector<double> adhesive_front; // K_I/K_Ic at the front points: 1 at both ends
  };

  struct EllipticalSummitsResults
  {
    std::vector<double>     tension_aspect_ratios; // Ay/Ax
    std::vector<double>     angles;                // front points
    std::vector<SummitGaps> fe, coarse_fe, exact;  // per Ay/Ax; coarse_fe: cells and sectors halved
    double                  largest_error;         // of b/a, the area ratio and psi, FE against exact
    unsigned int            fe_models;
  };

  // For each Ay/Ax of 'Elliptical summits': the adhesionless gap (K_I = 0 at
  // both ends) and the adhesive minimum (K_I = K_Ic at both ends, least P),
  // searched with FE models on the discretisation of 'Elliptical model' and
  // on one with half its cells along and around the front (the error
  // estimate), and with Galin's closed form.
  EllipticalSummitsResults run_elliptical_summits_scene(const Parameters   &parameters,
                                                        const ResultFolder &results, std::ostream &log);
} // namespace penny
