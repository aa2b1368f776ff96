// Measured topographies: the height map of an instrument's file (doc/measured.md),
// on the grid the file states, in metres, with the points it marks as not
// measured kept as NaN for the caller to fill or refuse.
#pragma once

#include "fourier/fourier_transform.h"

#include <cstddef>
#include <string>

namespace penny
{
  // The height map: grid.nx x grid.ny points with spacings dx = lx/nx and
  // dy = ly/ny (m; the pixels need not be square), heights (m) stored as a
  // GridField (x the slow index: the height at (i dx, j dy) is heights[i * ny + j]),
  // NaN where the file marks a point as not measured.
  struct Topography
  {
    PeriodicGrid grid;
    GridField    heights;
    std::string  height_unit; // the unit the file states the heights in
    std::string  description; // what the file says it is, for the log
  };

  enum class TopographyFormat
  {
    automatic,   // from the file name's extension
    matrix_text, // rows of heights, a row per y, a column per x (Gwyddion's ASCII export)
    xyz_text,    // three columns x y z on a regular grid, in any order
    x3p,         // ISO 25178-72 (ISO 5436-2) XML: a zip of main.xml and binary heights
    sur,         // Digital Surf's binary .sur (one surface object)
    netcdf       // ContactEngineering's NetCDF: heights(x, y), its length in x and y
  };

  // What a text file may not state: its physical size and units. A Gwyddion
  // header ("# Width: 10 um", "# Height: ...", "# Value units: m") states
  // them and takes precedence.
  struct TextTopography
  {
    double      lx = 0, ly = 0; // physical size (m) of a matrix; 0: not given
    std::string unit = "m";     // of the heights, and of the positions of xyz text
  };

  // Reads a topography file. Throws InputError "'FILE': what is wrong" for a
  // file that is missing, damaged or truncated, or that states what this
  // reader does not take (another studiable type, absolute x positions, ...).
  Topography read_topography(const std::string &filename, TopographyFormat format,
                             const TextTopography &text);

  // The format a file name's extension names (.txt .asc .dat .csv: matrix
  // text, .xyz: xyz text, .x3p, .sur, .nc); throws InputError for another.
  TopographyFormat format_of(const std::string &filename);

  // Metres in one unit of length ("m", "mm", "um" or "µm", "nm", "A" or "Å",
  // ...); throws InputError naming the unit for one it does not know.
  double metres_per(const std::string &unit);

  // The points of the map the file marks as not measured.
  std::size_t missing_points(const Topography &topography);
} // namespace penny
