// Scenes of the statistical layer (no FE): the paper's figures 1, 3, 4 and 5,
// the summit statistics of a rough surface and the magnification exponent
// theta. Each writes a CSV table and prints a summary.
#pragma once

#include "input/parameters.h"
#include "output/result_folder.h"

#include <ostream>

namespace penny
{
  void run_sinusoid_contact_scene(const Parameters &parameters, const ResultFolder &results,
                                  std::ostream &log);

  // Return the largest |integral/closed form - 1| of the linear law.
  double run_zero_load_gap_area_scene(const Parameters &parameters, const ResultFolder &results,
                                      std::ostream &log);
  double run_area_load_scene(const Parameters &parameters, const ResultFolder &results, std::ostream &log);

  void run_rough_surface_scene(const Parameters &parameters, const ResultFolder &results, std::ostream &log);

  // Returns the largest |theta fitted - (2/5)(2H - 1)| over the Hurst exponents.
  double run_magnification_scaling_scene(const Parameters &parameters, const ResultFolder &results,
                                         std::ostream &log);
} // namespace penny
