// A measured surface's problem (doc/measured.md): the subsection `Measured
// surface` (the file, its format, what a text file does not state, how the
// map is prepared) and the prepared topography it describes.
#pragma once

#include "input/entries.h"
#include "topography/surface_preparation.h"

#include <ostream>
#include <string>

namespace penny
{
  struct MeasuredSurfaceInput
  {
    std::string      file;
    TopographyFormat format;
    TextTopography   text;
    double           crop[4];      // x0, x1, y0, y1: the part of the map kept, in fractions of its sides
    bool             fill_missing; // fill the points not measured, or refuse a map with any
    Detrending       detrending;
    bool             hann_window; // of the PSD
  };

  // Measured surface. Once read, the file must exist.
  void measured_surface_section(Sections &sections, MeasuredSurfaceInput &input);

  // The topography read and prepared (cropped, filled, detrended) as `input` says,
  // with a line on `log` of what was read and done. Throws InputError naming
  // Measured surface/File for a file that cannot be read, and Measured
  // surface/Missing points for a map with points not measured that is not to be filled.
  Topography prepared_topography(const MeasuredSurfaceInput &input, std::ostream &log);
} // namespace penny
