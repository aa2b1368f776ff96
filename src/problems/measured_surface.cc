#include "problems/measured_surface.h"

#include "input/input_error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace penny
{
  void measured_surface_section(Sections &sections, MeasuredSurfaceInput &input)
  {
    sections.subsection("Measured surface", [&](Entries &entries) {
      entries.file("File", input.file, "surface.x3p",
                   "The topography file (relative paths start at the parameter file's folder).");
      entries.choice("Format", input.format, TopographyFormat::automatic,
                     {{"automatic", TopographyFormat::automatic},
                      {"matrix text", TopographyFormat::matrix_text},
                      {"xyz text", TopographyFormat::xyz_text},
                      {"x3p", TopographyFormat::x3p},
                      {"sur", TopographyFormat::sur},
                      {"netcdf", TopographyFormat::netcdf}},
                     "The file's format; automatic: from its extension (.txt .asc .dat .csv: matrix text, "
                     ".xyz: xyz text, .x3p, .sur, .nc: netcdf).");
      entries.number("Text size x", input.text.lx, 0, interval("[]", 0, largest_magnitude, "m"),
                     "The physical size along x (along a row) of a matrix text file that states none "
                     "(a Gwyddion header's '# Width:' takes precedence); 0: none given. Units: m.");
      entries.number("Text size y", input.text.ly, 0, interval("[]", 0, largest_magnitude, "m"),
                     "The same along y (down the rows; '# Height:'). Units: m.");
      entries.text("Text unit", input.text.unit, "m",
                   "The length unit of the numbers of a text file that states none ('# Value units:'): "
                   "km, m, cm, mm, um, nm, A or pm; of x, y and z in xyz text.");
      std::string crop_text;
      entries.text(
          "Crop", crop_text, "0, 1, 0, 1",
          "x0, x1, y0, y1: the part of the map kept, x0 lx <= x < x1 lx and y0 ly <= y < y1 ly "
          "(rounded to whole points, 3 a side at least), before it is filled and detrended; 0, 1, 0, 1: "
          "the whole map. Units: fractions of the map's sides.");
      if (entries.reading())
        {
          std::istringstream numbers(crop_text);
          char               comma;
          double            *c = input.crop;
          if (!(numbers >> c[0] >> comma >> c[1] >> comma >> c[2] >> comma >> c[3]) ||
              !(numbers >> std::ws).eof() ||
              !(0 <= c[0] && c[0] < c[1] && c[1] <= 1 && 0 <= c[2] && c[2] < c[3] && c[3] <= 1))
            throw InputError("Measured surface/Crop = " + in_quotes(crop_text) +
                             " is outside the allowed range x0, x1, y0, y1 with 0 <= x0 < x1 <= 1 and "
                             "0 <= y0 < y1 <= 1");
        }
      entries.choice("Missing points", input.fill_missing, false, {{"refuse", false}, {"fill", true}},
                     "Points the file marks as not measured: refuse the map, or fill them by harmonic "
                     "interpolation from the measured ones (how many is printed).");
      entries.choice(
          "Detrending", input.detrending, Detrending::plane,
          {{"mean", Detrending::mean}, {"plane", Detrending::plane}, {"curvature", Detrending::curvature}},
          "The least-squares trend removed from the heights: the mean, a plane, or a curvature "
          "(a quadratic in x and y).");
      entries.flag("Hann window", input.hann_window, true,
                   "Whether the PSD is taken of the map times a Hann window (in x and y, normalised to keep "
                   "the mean square), which keeps the jump between opposite edges of a map that is not "
                   "periodic out of the spectrum.");
    });
    sections.check([&] {
      if (!std::filesystem::is_regular_file(input.file))
        throw InputError("Measured surface/File = " + in_quotes(input.file) +
                         " does not exist or is not a file");
      sections.input_file(input.file);
      try
        {
          metres_per(input.text.unit);
        }
      catch (const InputError &error)
        {
          throw InputError("Measured surface/Text unit = " + in_quotes(input.text.unit) + ": " +
                           error.what());
        }
    });
  }

  Topography prepared_topography(const MeasuredSurfaceInput &input, std::ostream &log)
  {
    Topography topography;
    try
      {
        topography = read_topography(input.file, input.format, input.text);
      }
    catch (const InputError &error)
      {
        throw InputError("Measured surface/File = " + std::string(error.what()));
      }
    if (input.crop[0] > 0 || input.crop[1] < 1 || input.crop[2] > 0 || input.crop[3] < 1)
      {
        const PeriodicGrid &whole = topography.grid;
        const unsigned int  i0    = std::lround(input.crop[0] * whole.nx),
                           i1     = std::lround(input.crop[1] * whole.nx),
                           j0     = std::lround(input.crop[2] * whole.ny),
                           j1     = std::lround(input.crop[3] * whole.ny);
        if (i1 < i0 + 3 || j1 < j0 + 3)
          throw InputError("Measured surface/Crop = " + shortest(input.crop[0]) + ", " +
                           shortest(input.crop[1]) + ", " + shortest(input.crop[2]) + ", " +
                           shortest(input.crop[3]) + " keeps " + std::to_string(i1 - i0) + " x " +
                           std::to_string(j1 - j0) + " of the " + std::to_string(whole.nx) + " x " +
                           std::to_string(whole.ny) + " points (the allowed range: 3 a side at least)");
        log << "Cropped to points " << i0 << " ... " << i1 - 1 << " along x and " << j0 << " ... " << j1 - 1
            << " along y of the map's " << whole.nx << " x " << whole.ny << '\n';
        topography = cropped(topography, i0, i1, j0, j1);
      }
    const PeriodicGrid &grid    = topography.grid;
    const std::size_t   missing = missing_points(topography);
    log << "Measured surface: " << input.file << " (" << topography.description << "), " << grid.nx << " x "
        << grid.ny << " points on " << grid.lx << " m x " << grid.ly << " m (pixels " << grid.lx / grid.nx
        << " m x " << grid.ly / grid.ny << " m), heights in " << topography.height_unit
        << ", points not measured: " << missing << '\n';
    if (missing > 0 && !input.fill_missing)
      throw InputError("Measured surface/Missing points = refuse, and " + in_quotes(input.file) + " marks " +
                       std::to_string(missing) + " of its " + std::to_string(grid.n_points()) +
                       " points as not measured (the allowed choice for this file: fill)");
    if (missing > 0)
      {
        try
          {
            fill_missing_points(topography);
          }
        catch (const InputError &error)
          {
            throw InputError("Measured surface/File = " + in_quotes(input.file) + ": " + error.what());
          }
        log << "  filled " << missing << " points (" << 100. * missing / grid.n_points()
            << " %) by harmonic interpolation\n";
      }
    // A map that is flat once its trend is gone has no roughness to describe or contact to solve.
    double largest = 0;
    for (const double h : topography.heights)
      largest = std::max(largest, std::abs(h));
    detrend(topography, input.detrending);
    double rms = 0;
    for (const double h : topography.heights)
      rms += h * h / grid.n_points();
    if (!(std::sqrt(rms) > 1e-12 * largest))
      throw InputError("Measured surface/File = " + in_quotes(input.file) +
                       " is flat once Measured surface/Detrending removes its trend (rms height " +
                       shortest(std::sqrt(rms)) + " m): there is no roughness to describe");
    return topography;
  }
} // namespace penny
