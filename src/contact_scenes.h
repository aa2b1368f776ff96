// Scenes of the statistical layer: the paper's figures 1, 3, 4 and 5, the
// summit statistics of a rough surface, the magnification exponent theta and
// the area-load curve aggregated with the FE gap function. Each writes a CSV
// table to the output folder and a summary to the log.
#pragma once

#include "parameters.h"

#include <ostream>

namespace penny
{
  void run_sinusoid_contact_scene(const Parameters &parameters, std::ostream &log);

  // Returns the largest |integral/closed form - 1| of the linear law.
  double run_zero_load_gap_area_scene(const Parameters &parameters, std::ostream &log);
  double run_area_load_scene(const Parameters &parameters, std::ostream &log);

  void run_rough_surface_scene(const Parameters &parameters, std::ostream &log);

  // Returns the largest |theta fitted - (2/5)(2H - 1)| over the Hurst exponents.
  double run_magnification_scaling_scene(const Parameters &parameters, std::ostream &log);

  // Returns the largest |A_nc(FE g)/A_nc(closed-form g) - 1| over the mean pressures.
  double run_fe_gap_area_scene(const Parameters &parameters, std::ostream &log);
} // namespace penny
