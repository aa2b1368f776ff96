// The area-load curve aggregated with the FE gap function g, tabulated from
// FE solves, beside the closed-form g's.
#pragma once

#include "input/parameters.h"
#include "output/result_folder.h"

#include <ostream>

namespace penny
{
  // Returns the largest |A_nc(FE g)/A_nc(closed-form g) - 1| over the mean pressures.
  double run_fe_gap_area_scene(const Parameters &parameters, const ResultFolder &results, std::ostream &log);
} // namespace penny
