#include "input/input_error.h"
#include "topography/topography_formats.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>

namespace penny
{
  void bad_file(const std::string &filename, const std::string &what)
  {
    // The file's name is the end of its path: a long path loses its beginning.
    const std::size_t longest = 160;
    throw InputError(
        "'" + (filename.size() <= longest ? filename : "..." + filename.substr(filename.size() - longest)) +
        "': " + what);
  }

  Topography empty_topography(const std::string &filename, const long long nx, const long long ny,
                              const double dx, const double dy)
  {
    // 2^31 points (16 GiB of heights) is beyond what a rank can hold with the work arrays of a contact.
    // Three points a side at least: the rms curvature's stencil needs an interior point.
    if (nx < 3 || ny < 3 || nx * ny > (1ll << 31))
      bad_file(filename, "a grid of " + std::to_string(nx) + " x " + std::to_string(ny) +
                             " points (a height map needs 3 x 3 to 2^31 points)");
    if (!(dx > 0 && dy > 0 && std::isfinite(dx) && std::isfinite(dy)))
      bad_file(filename,
               "pixel size " + shortest(dx) + " x " + shortest(dy) + " m (must be positive and finite)");
    Topography topography;
    topography.grid = {static_cast<unsigned int>(nx), static_cast<unsigned int>(ny), nx * dx, ny * dy};
    topography.heights.assign(topography.grid.n_points(), 0.);
    return topography;
  }

  double metres_per(const std::string &unit)
  {
    static const std::map<std::string, double> units = {
        {"km", 1e3},       {"m", 1},          {"cm", 1e-2},      {"mm", 1e-3},     {"um", 1e-6},
        {"\u00b5m", 1e-6}, {"\xb5m", 1e-6},   {"\u03bcm", 1e-6}, {"micron", 1e-6}, {"nm", 1e-9},
        {"A", 1e-10},      {"\u00c5", 1e-10}, {"pm", 1e-12}};
    const auto found = units.find(unit);
    if (found == units.end())
      throw InputError("the length unit " + in_quotes(one_line(unit)) +
                       " is none of km, m, cm, mm, um (\u00b5m), nm, A (\u00c5), pm");
    return found->second;
  }

  std::size_t missing_points(const Topography &topography)
  {
    return std::count_if(topography.heights.begin(), topography.heights.end(),
                         [](const double h) { return std::isnan(h); });
  }

  TopographyFormat format_of(const std::string &filename)
  {
    std::string extension = std::filesystem::path(filename).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
    for (const auto &[ending, format] :
         std::map<std::string, TopographyFormat>{{".txt", TopographyFormat::matrix_text},
                                                 {".asc", TopographyFormat::matrix_text},
                                                 {".dat", TopographyFormat::matrix_text},
                                                 {".csv", TopographyFormat::matrix_text},
                                                 {".xyz", TopographyFormat::xyz_text},
                                                 {".x3p", TopographyFormat::x3p},
                                                 {".sur", TopographyFormat::sur},
                                                 {".nc", TopographyFormat::netcdf}})
      if (extension == ending)
        return format;
    bad_file(filename,
             "the extension " + in_quotes(extension) +
                 " names no format read here (.txt .asc .dat .csv .xyz .x3p .sur .nc; or set the format)");
  }

  namespace
  {
    Topography read_format(const std::string &filename, const TopographyFormat format,
                           const TextTopography &text)
    {
      switch (format == TopographyFormat::automatic ? format_of(filename) : format)
        {
        case TopographyFormat::matrix_text:
          return read_matrix_text(filename, text);
        case TopographyFormat::xyz_text:
          return read_xyz_text(filename, text);
        case TopographyFormat::x3p:
          return read_x3p(filename);
        case TopographyFormat::sur:
          return read_sur(filename);
        default:
          return read_netcdf(filename);
        }
    }
  } // namespace

  Topography read_topography(const std::string &filename, const TopographyFormat format,
                             const TextTopography &text)
  {
    if (!std::filesystem::is_regular_file(filename))
      bad_file(filename, "does not exist or is not a file");
    Topography topography = read_format(filename, format, text);
    // What a surface measurement can be, and what the roughness and contact
    // computations hold in double precision (their squares and curvatures).
    const double dx = topography.grid.lx / topography.grid.nx, dy = topography.grid.ly / topography.grid.ny;
    if (!(dx >= 1e-12 && dx <= 1e3 && dy >= 1e-12 && dy <= 1e3))
      bad_file(filename, "pixels of " + shortest(dx) + " m x " + shortest(dy) +
                             " m (the allowed range: 1e-12 m to 1e3 m a side)");
    for (std::size_t k = 0; k < topography.heights.size(); ++k)
      if (const double h = topography.heights[k]; !std::isnan(h) && !(std::abs(h) <= 1e3))
        bad_file(filename, "the height " + shortest(h) + " m at point (" +
                               std::to_string(k / topography.grid.ny) + ", " +
                               std::to_string(k % topography.grid.ny) +
                               ") is outside the allowed range [-1e3, 1e3] m");
    return topography;
  }

  namespace
  {
    // The numbers of a line separated by blanks, tabs, commas or semicolons
    // ("nan" is a point not measured); false if the line holds anything else.
    bool numbers_of(const std::string &line, std::vector<double> &numbers)
    {
      numbers.clear();
      if (line.find('\0') != std::string::npos)
        return false;
      const char *p = line.c_str();
      while (true)
        {
          while (*p == ' ' || *p == '\t' || *p == ',' || *p == ';' || *p == '\r')
            ++p;
          if (*p == '\0')
            return true;
          char        *end;
          const double value = std::strtod(p, &end);
          if (end == p || std::isinf(value))
            return false;
          numbers.push_back(value);
          p = end;
        }
    }

    // A Gwyddion header line "# Key: value unit": the key and the rest.
    bool header_entry(const std::string &line, std::string &key, std::string &value)
    {
      const auto colon = line.find(':');
      if (line.empty() || line[0] != '#' || colon == std::string::npos)
        return false;
      const auto trim = [](const std::string &s) {
        const auto first = s.find_first_not_of(" \t\r"), last = s.find_last_not_of(" \t\r");
        return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
      };
      key   = trim(line.substr(1, colon - 1));
      value = trim(line.substr(colon + 1));
      return true;
    }

    // "12.34 µm" in metres.
    double length_in(const std::string &filename, const std::string &key, const std::string &value)
    {
      char        *end;
      const double number = std::strtod(value.c_str(), &end);
      std::string  unit   = end;
      unit.erase(0, unit.find_first_not_of(' '));
      double scale = 0;
      try
        {
          scale = metres_per(unit);
        }
      catch (const InputError &error)
        {
          bad_file(filename, "'# " + key + ": " + one_line(value) + "': " + error.what());
        }
      if (!(number * scale > 0 && std::isfinite(number * scale)))
        bad_file(filename, "'# " + key + ": " + one_line(value) + "' is not a positive length");
      return number * scale;
    }

    struct TextLines
    {
      std::vector<std::vector<double>> rows;
      double                           lx = 0, ly = 0;
      std::string                      unit;
    };

    // The rows of numbers of a text file, and the size and unit a Gwyddion header states.
    TextLines text_lines(const std::string &filename, const TextTopography &text)
    {
      std::ifstream in(filename);
      if (!in)
        bad_file(filename, "cannot be opened");
      TextLines           lines{{}, text.lx, text.ly, text.unit};
      std::string         line, key, value;
      std::vector<double> numbers;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          if (number == 1 && line.compare(0, 3, "\xef\xbb\xbf") == 0)
            line.erase(0, 3); // a UTF-8 byte order mark
          if (header_entry(line, key, value))
            {
              if (key == "Width" || key == "Breite")
                lines.lx = length_in(filename, key, value);
              else if (key == "Height" || key == "H\u00f6he")
                lines.ly = length_in(filename, key, value);
              else if (key == "Value units")
                lines.unit = value;
              continue;
            }
          if (!line.empty() && line[0] == '#')
            continue;
          if (!numbers_of(line, numbers))
            bad_file(filename, "line " + std::to_string(number) + ": " + in_quotes(one_line(line)) +
                                   " is neither numbers nor a '#' comment");
          if (!numbers.empty())
            lines.rows.push_back(numbers);
        }
      if (in.bad())
        bad_file(filename, "could not be read to its end");
      try
        {
          metres_per(lines.unit);
        }
      catch (const InputError &error)
        {
          bad_file(filename, error.what());
        }
      return lines;
    }
  } // namespace

  Topography read_matrix_text(const std::string &filename, const TextTopography &text)
  {
    const TextLines lines = text_lines(filename, text);
    if (lines.rows.empty())
      bad_file(filename, "holds no heights");
    const std::size_t nx = lines.rows[0].size(), ny = lines.rows.size();
    for (std::size_t j = 0; j < ny; ++j)
      if (lines.rows[j].size() != nx)
        bad_file(filename, "row " + std::to_string(j + 1) + " of the heights has " +
                               std::to_string(lines.rows[j].size()) + " numbers, the first " +
                               std::to_string(nx));
    if (!(lines.lx > 0 && lines.ly > 0))
      bad_file(filename,
               "states no physical size (no '# Width:' and '# Height:' lines; give the size in x and y)");
    Topography   topography = empty_topography(filename, nx, ny, lines.lx / nx, lines.ly / ny);
    const double scale      = metres_per(lines.unit);
    // A row of the file is a line of constant y, its columns along x.
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
        topography.heights[i * ny + j] = lines.rows[j][i] * scale;
    topography.height_unit = lines.unit;
    topography.description = "matrix text";
    return topography;
  }

  Topography read_xyz_text(const std::string &filename, const TextTopography &text)
  {
    const TextLines lines = text_lines(filename, text);
    if (lines.rows.empty())
      bad_file(filename, "holds no points");
    std::vector<double> xs, ys;
    for (std::size_t k = 0; k < lines.rows.size(); ++k)
      {
        if (lines.rows[k].size() != 3)
          bad_file(filename, "point " + std::to_string(k + 1) + " has " +
                                 std::to_string(lines.rows[k].size()) + " numbers, not the three x y z");
        if (!std::isfinite(lines.rows[k][0]) || !std::isfinite(lines.rows[k][1]))
          bad_file(filename, "point " + std::to_string(k + 1) + " has no finite position x y");
        xs.push_back(lines.rows[k][0]);
        ys.push_back(lines.rows[k][1]);
      }
    // The distinct positions along each axis, which must be evenly spaced.
    const auto positions = [&](std::vector<double> values, const char *axis) {
      std::sort(values.begin(), values.end());
      values.erase(std::unique(values.begin(), values.end()), values.end());
      if (values.size() < 2)
        bad_file(filename, std::string("the points have one ") + axis + " only");
      const double step = (values.back() - values.front()) / (values.size() - 1);
      for (std::size_t k = 1; k < values.size(); ++k)
        // Within 1e-3 of a step: exports print positions to six digits or so.
        if (std::abs(values[k] - values[k - 1] - step) > 1e-3 * step)
          bad_file(filename, std::string("the ") + axis + " positions are not evenly spaced (" +
                                 shortest(values[k - 1]) + " to " + shortest(values[k]) + ", the mean step " +
                                 shortest(step) + ")");
      return std::make_pair(values.front(), step);
    };
    const auto [x0, dx] = positions(xs, "x");
    const auto [y0, dy] = positions(ys, "y");
    const long long nx  = std::llround((*std::max_element(xs.begin(), xs.end()) - x0) / dx) + 1,
                    ny  = std::llround((*std::max_element(ys.begin(), ys.end()) - y0) / dy) + 1;
    // A grid position without a point is not measured; a grid mostly empty is not a map.
    if (2. * lines.rows.size() < double(nx) * ny)
      bad_file(filename, std::to_string(lines.rows.size()) + " points on a grid of " + std::to_string(nx) +
                             " x " + std::to_string(ny) + " positions: fewer than half of them measured");
    const double scale      = metres_per(lines.unit);
    Topography   topography = empty_topography(filename, nx, ny, dx * scale, dy * scale);
    std::fill(topography.heights.begin(), topography.heights.end(), std::numeric_limits<double>::infinity());
    for (const auto &row : lines.rows)
      {
        const std::size_t i = std::llround((row[0] - x0) / dx), j = std::llround((row[1] - y0) / dy);
        double           &h = topography.heights[i * ny + j];
        if (!std::isinf(h))
          bad_file(filename, "the point (" + shortest(row[0]) + ", " + shortest(row[1]) + ") appears twice");
        h = row[2] * scale;
      }
    // A position of the grid without a point: not measured.
    for (double &h : topography.heights)
      if (std::isinf(h))
        h = std::numeric_limits<double>::quiet_NaN();
    topography.height_unit = lines.unit;
    topography.description = "xyz text";
    return topography;
  }
} // namespace penny
