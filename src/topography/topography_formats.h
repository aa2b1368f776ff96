// The readers of topography.h, one file per format, and what they share.
#pragma once

#include "topography/topography.h"

#include <string>

namespace penny
{
  Topography read_matrix_text(const std::string &filename, const TextTopography &text);
  Topography read_xyz_text(const std::string &filename, const TextTopography &text);
  Topography read_x3p(const std::string &filename);
  Topography read_sur(const std::string &filename);
  Topography read_netcdf(const std::string &filename);

  // Throws InputError "'FILE': WHAT".
  [[noreturn]] void bad_file(const std::string &filename, const std::string &what);

  // A topography of nx x ny points at spacings dx, dy (m), heights to be filled;
  // refuses grids of fewer than 3 x 3 points and spacings that are not positive and finite.
  Topography empty_topography(const std::string &filename, long long nx, long long ny, double dx, double dy);
} // namespace penny
