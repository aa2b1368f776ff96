// Measured topographies (src/topography/): each format read from the small
// files of tests/topography/ (written by make_files.py from the formats'
// specifications, not by penny), damaged files refused with the file named,
// and the preparation (filling, detrending, rms parameters, PSD fit) on
// surfaces whose answers are known in closed form.
#include "input/input_error.h"
#include "statistics/random_field.h"
#include "test_support.h"
#include "topography/surface_preparation.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>

BOOST_AUTO_TEST_SUITE(test_topography)

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  const std::string files = std::string(TEST_DIR) + "/topography/";

  // make_files.py's surface: 6 x 4 points of 0.5 um x 0.25 um, h = 0.5 nm (i^2 - 3 j + i j),
  // the point (2, 1) not measured in the files that say "missing".
  void check_test_surface(const Topography &topography, const bool with_missing_point)
  {
    BOOST_TEST(topography.grid.nx == 6u);
    BOOST_TEST(topography.grid.ny == 4u);
    BOOST_TEST(topography.grid.lx == 3e-6, tt::tolerance(1e-12));
    BOOST_TEST(topography.grid.ly == 1e-6, tt::tolerance(1e-12));
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 4; ++j)
        {
          const double h = topography.heights[i * 4 + j];
          if (with_missing_point && i == 2 && j == 1)
            BOOST_TEST(std::isnan(h));
          else
            BOOST_TEST(h == 0.5e-9 * (i * i - 3 * j + i * j), tt::tolerance(1e-12)
                                                                  << "at " << i << ", " << j);
        }
    BOOST_TEST(missing_points(topography) == (with_missing_point ? 1u : 0u));
  }

  Topography read(const std::string &file, const TextTopography &text = {})
  {
    return read_topography(file, TopographyFormat::automatic, text);
  }

  // A copy of a test file with its bytes changed by `damage`.
  std::string damaged_copy(const ScratchFolder &scratch, const std::string &name,
                           const std::function<void(std::string &)> &damage)
  {
    std::ifstream in(files + name, std::ios::binary);
    std::string   bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    damage(bytes);
    const std::string copy = (scratch.path / name).string();
    std::ofstream(copy, std::ios::binary) << bytes;
    return copy;
  }

  // Whether reading `file` fails with a message that names it and contains `what`.
  bool refused(const std::string &file, const std::string &what)
  {
    try
      {
        read(file);
      }
    catch (const InputError &error)
      {
        const std::string message = error.what();
        BOOST_TEST_MESSAGE(message);
        return message.find(file.substr(file.rfind('/') + 1)) != std::string::npos &&
               message.find(what) != std::string::npos;
      }
    return false;
  }
} // namespace

// One case per format (ctest runs each as topography_format_FORMAT): the
// test surface in metres, and the damaged copies refused naming the file.
BOOST_AUTO_TEST_CASE(matrix_text)
{
  check_test_surface(read(files + "matrix.txt"), false);
  check_test_surface(read(files + "matrix-missing.txt"), true);
  ScratchFolder scratch;
  BOOST_TEST(refused(damaged_copy(scratch, "matrix.txt", [](std::string &b) { b.erase(b.rfind('\t')); }),
                     "row 4 of the heights has 5 numbers, the first 6"));
  BOOST_TEST(refused(damaged_copy(scratch, "matrix.txt", [](std::string &b) { b += "1 2 x\n"; }),
                     "line 9: '1 2 x' is neither numbers nor a '#' comment"));
  BOOST_TEST(refused(
      damaged_copy(scratch, "matrix.txt", [](std::string &b) { b.replace(b.find("nm"), 2, "furlong"); }),
      "the length unit 'furlong'"));
}

BOOST_AUTO_TEST_CASE(xyz_text)
{
  TextTopography micrometres;
  micrometres.unit = "um";
  check_test_surface(read(files + "missing.xyz", micrometres), true);
  ScratchFolder scratch;
  BOOST_TEST(refused(
      damaged_copy(scratch, "missing.xyz", [](std::string &b) { b += b.substr(0, b.find('\n') + 1); }),
      "appears twice"));
  BOOST_TEST(refused(damaged_copy(scratch, "missing.xyz", [](std::string &b) { b += "0.1 0 0\n"; }),
                     "positions are not evenly spaced"));
}

BOOST_AUTO_TEST_CASE(x3p)
{
  check_test_surface(read(files + "doubles.x3p"), false);
  check_test_surface(read(files + "integers-missing.x3p"), true);
  ScratchFolder scratch;
  BOOST_TEST(refused(damaged_copy(scratch, "doubles.x3p", [](std::string &b) { b.resize(b.size() - 30); }),
                     "is not a readable zip archive"));
  // A byte of the compressed heights changed: the member's CRC does not match.
  BOOST_TEST(refused(damaged_copy(scratch, "integers-missing.x3p",
                                  [](std::string &b) { b[b.find("bindata/data.bin") + 20] ^= 0x5a; }),
                     "bindata/data.bin"));
}

BOOST_AUTO_TEST_CASE(sur)
{
  check_test_surface(read(files + "heights.sur"), false);
  check_test_surface(read(files + "missing.sur"), true);
  ScratchFolder scratch;
  BOOST_TEST(refused(damaged_copy(scratch, "heights.sur", [](std::string &b) { b.resize(b.size() - 10); }),
                     "is truncated"));
  BOOST_TEST(refused(damaged_copy(scratch, "missing.sur", [](std::string &b) { b[0] = 'X'; }),
                     "does not start with 'DIGITAL SURF'"));
}

BOOST_AUTO_TEST_CASE(netcdf)
{
  check_test_surface(read(files + "missing.nc"), true);
  ScratchFolder scratch;
  // Cut in its last variable, or in its heights: libnetcdf would read zeros.
  BOOST_TEST(refused(damaged_copy(scratch, "missing.nc", [](std::string &b) { b.resize(b.size() - 8); }),
                     "is truncated"));
  BOOST_TEST(
      refused(damaged_copy(scratch, "missing.nc", [](std::string &b) { b.resize(384); }), "is truncated"));
  BOOST_TEST(refused(damaged_copy(scratch, "missing.nc", [](std::string &b) { b.resize(100); }), "NetCDF"));
}

// The files of a hostile campaign (tests/topography/damaged/, see its
// README.md): each crashed penny, read damaged data as good, took gigabytes
// or refused a good file before it was mended.
BOOST_AUTO_TEST_CASE(the_hostile_campaign_files)
{
  const std::string                           damaged    = files + "damaged/";
  const std::pair<const char *, const char *> refusals[] = {
      {"crc-damaged.x3p", "'bindata/data.bin' is damaged or truncated (CRC error)"},
      {"deep-nesting.x3p", "nests its elements deeper than 64 levels"},
      {"huge-main-xml.x3p", "'main.xml' holds 4294967280 bytes, not at most 16777216"},
      {"huge-grid.x3p", "holds 48 bytes, not the 800000000 its grid needs"},
      {"huge-grid.sur", "is truncated: it holds fewer than the 400000000 points"},
      {"nan-offset.sur", "states the Z offset nan m"},
      {"length-ten-values.nc", "the attribute 'length' of 'x' holds 10 values, not one"},
      {"record-truncated.nc", "is truncated or its header damaged"},
      {"flipped-header.nc", "NetCDF header"},
      {"infinite-height.nc", "is outside the allowed range [-1e3, 1e3] m"},
      {"nul-bytes.txt", "is neither numbers nor a '#' comment"}};
  for (const auto &[file, what] : refusals)
    BOOST_TEST(refused(damaged + file, what), file);
  // Good files it refused or misread: a comment before the root element, and heights(y, x).
  BOOST_TEST(read(damaged + "comment-before-root.x3p").grid.nx == 6u);
  // Its first row (y = 0) holds 0.18905338, 1.79970738, ..., its first column (x = 0) 0.18905338,
  // -0.52274844, ...
  const Topography transposed = read(damaged + "heights-y-x.nc");
  BOOST_TEST(transposed.grid.nx == 6u);
  BOOST_TEST(transposed.grid.ny == 4u);
  BOOST_TEST(transposed.heights[1 * 4 + 0] / transposed.heights[0] == 1.79970738 / 0.18905338,
             tt::tolerance(1e-6));
  BOOST_TEST(transposed.heights[0 * 4 + 1] / transposed.heights[0] == -0.52274844 / 0.18905338,
             tt::tolerance(1e-6));

  // xyz written with six digits is evenly spaced to 1e-3 of a step; a
  // diagonal of points is not a map.
  ScratchFolder scratch;
  std::ofstream(scratch.path / "six-digits.xyz") << [] {
    std::ostringstream text;
    text.precision(6);
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 5; ++j)
        text << i * (10. / 256) << ' ' << j * (10. / 256) << ' ' << i * j << '\n';
    return text.str();
  }();
  BOOST_TEST(read((scratch.path / "six-digits.xyz").string()).grid.nx == 40u);
  std::ofstream(scratch.path / "diagonal.xyz") << "0 0 1\n1 1 2\n2 2 3\n3 3 4\n";
  BOOST_TEST(refused((scratch.path / "diagonal.xyz").string(), "fewer than half of them measured"));
}

BOOST_AUTO_TEST_CASE(a_text_file_without_a_header_takes_the_size_and_unit_given)
{
  ScratchFolder scratch;
  const auto    file = damaged_copy(scratch, "matrix.txt", [](std::string &bytes) {
    bytes.erase(0, bytes.find("\n0\t")); // the four header lines
  });
  BOOST_TEST(refused(file, "states no physical size"));
  TextTopography text;
  text.lx = 3e-6, text.ly = 1e-6, text.unit = "nm";
  check_test_surface(read_topography(file, TopographyFormat::matrix_text, text), false);
}

BOOST_AUTO_TEST_CASE(harmonic_filling_and_detrending_are_exact_on_polynomials)
{
  // A plane with holes inside the map: the harmonic fill reproduces it (at
  // the map's edges the no-flux condition would bend it), and removing the
  // plane leaves zero.
  Topography plane;
  plane.grid = {8, 5, 4., 1.};
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 5; ++j)
      plane.heights.push_back(0.3 + 0.2 * i * 0.5 - 0.7 * j * 0.2);
  const GridField exact = plane.heights;
  for (const int k : {6, 7, 12, 18, 27})
    plane.heights[k] = std::nan("");
  BOOST_TEST(fill_missing_points(plane) == 5u);
  for (std::size_t k = 0; k < exact.size(); ++k)
    BOOST_TEST(plane.heights[k] == exact[k], tt::tolerance(1e-12));
  detrend(plane, Detrending::plane);
  for (const double h : plane.heights)
    BOOST_TEST(std::abs(h) < 1e-14);

  // A paraboloid 3 x^2 + y^2: its curvature removed, nothing is left; its
  // Laplacian 8 on the three-point stencil is exact, so the rms curvature is 4.
  Topography bowl;
  bowl.grid = {6, 7, 3., 2.1};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 7; ++j)
      bowl.heights.push_back(3 * std::pow(i * 0.5, 2) + std::pow(j * 0.3, 2));
  BOOST_TEST(surface_roughness(bowl).rms_curvature == 4., tt::tolerance(1e-12));
  detrend(bowl, Detrending::curvature);
  for (const double h : bowl.heights)
    BOOST_TEST(std::abs(h) < 1e-13);

  Topography none = plane;
  std::fill(none.heights.begin(), none.heights.end(), std::nan(""));
  BOOST_CHECK_THROW(fill_missing_points(none), InputError);
}

BOOST_AUTO_TEST_CASE(a_crop_keeps_its_points_on_its_own_rectangle)
{
  const Topography whole = read(files + "doubles.x3p"), part = cropped(whole, 1, 4, 2, 4);
  BOOST_TEST(part.grid.nx == 3u);
  BOOST_TEST(part.grid.ny == 2u);
  BOOST_TEST(part.grid.lx == 1.5e-6, tt::tolerance(1e-12));
  BOOST_TEST(part.grid.ly == 0.5e-6, tt::tolerance(1e-12));
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 2; ++j)
      BOOST_TEST(part.heights[i * 2 + j] == whole.heights[(i + 1) * 4 + j + 2]);
}

BOOST_AUTO_TEST_CASE(rms_parameters_on_their_stencils)
{
  // h = a x + b y on non-square pixels: forward differences are exact, the
  // slope is sqrt(a^2 + b^2), the curvature zero; the rms height of a ramp of n
  // evenly spaced values is its step times sqrt((n^2 - 1)/12).
  Topography ramp;
  ramp.grid = {10, 3, 5., 0.6};
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 3; ++j)
      ramp.heights.push_back(0.3 * i * 0.5 - 0.4 * j * 0.2);
  const SurfaceRoughness rms = surface_roughness(ramp);
  BOOST_TEST(rms.rms_slope == 0.5, tt::tolerance(1e-12));
  BOOST_TEST(rms.rms_curvature < 1e-12);
  Topography line = ramp;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 3; ++j)
      line.heights[i * 3 + j] = i;
  BOOST_TEST(surface_roughness(line).rms_height == std::sqrt(99. / 12), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(the_psd_fit_recovers_the_hurst_exponent_of_a_sampled_power_law)
{
  // A periodic Gaussian surface of the power law H = 0.7 over q0 ... 64 q0 on
  // 256^2 points: the fit over the reliable range (q from 2 q0 to 64 q0)
  // finds H within 0.05 (the scatter of one realisation's shells).
  const double q0 = 2 * M_PI;
  Topography   surface;
  surface.grid = square_grid(256, 1.);
  const FourierTransform transform(surface.grid);
  surface.heights       = gaussian_field(transform, power_law_spectrum(0.7, q0, 64, 1e-6), 3);
  const PowerLawFit fit = fit_power_law(isotropic_spectrum(surface, false), reliable_range(surface));
  BOOST_TEST(fit.hurst == 0.7, tt::tolerance(0.05 / 0.7));
  BOOST_TEST(fit.r_squared > 0.99);
  BOOST_TEST(fit.q_low == 2 * q0, tt::tolerance(1e-12));
  BOOST_TEST(fit.q_high == 64 * q0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
