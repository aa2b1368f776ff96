// Parameter files: defaults, a shipped scene, the R_p form of the parabola, and
// the one-line InputError for each kind of bad entry.
#define BOOST_TEST_MODULE parameters
#define BOOST_TEST_NO_MAIN
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>

using namespace penny;

namespace
{
  // Writes `text` to a parameter file and reads it.
  Parameters read_text(const std::string &text)
  {
    const auto path = std::filesystem::temp_directory_path() / "penny-test-parameters.prm";
    std::ofstream(path) << text;
    dealii::ParameterHandler prm;
    return Parameters::read(path.string(), prm);
  }

  // The InputError message for `text`, which must be one line.
  std::string error_of(const std::string &text)
  {
    try
      {
        read_text(text);
      }
    catch (const InputError &error)
      {
        const std::string message = error.what();
        BOOST_TEST(message.find('\n') == std::string::npos);
        return message;
      }
    return "no error";
  }

  bool mentions(const std::string &message, const std::string &part)
  {
    const bool found = message.find(part) != std::string::npos;
    if (!found)
      BOOST_TEST_MESSAGE("'" << message << "' lacks '" << part << "'");
    return found;
  }
} // namespace

BOOST_AUTO_TEST_CASE(defaults)
{
  const Parameters parameters = default_parameters();
  BOOST_TEST(parameters.scene == "penny-gap");
  BOOST_TEST(parameters.geometry.gap_radius == 1.);
  BOOST_TEST(parameters.material.poissons_ratio == 0.3);
  BOOST_TEST(parameters.finite_element.degree == 4u);
  BOOST_TEST(parameters.j_integral.ring_radii.size() == 3u);
  BOOST_TEST(parameters.material.plane_strain_modulus() == 1e9 / 0.91, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(shipped_scene)
{
  dealii::ParameterHandler prm;
  const Parameters parameters = Parameters::read(TEST_DIR "/../prms/penny-bueckner.prm", prm);
  BOOST_TEST((parameters.load.type == LoadParameters::Type::parabolic));
  BOOST_TEST(parameters.load.tension_radius == 1.25);
  BOOST_TEST(parameters.output.directory == "output/penny-bueckner");
}

BOOST_AUTO_TEST_CASE(parabola_from_summit_radius)
{
  const Parameters parameters = read_text("subsection Load\n set Type = parabolic\n set Peak tension P = 2e6\n"
                                          " set Parabola given by = R_p\n set Summit radius R_p = 1e-6\nend\n");
  BOOST_TEST(parameters.load.tension_radius == 2., boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(bad_entries)
{
  BOOST_TEST(mentions(error_of("subsection Geometry\n set Gap size = 1\nend\n"), "Gap size"));
  BOOST_TEST(mentions(error_of("subsection Material\n set Young's modulus E = stiff\nend\n"), "Young's modulus E"));
  BOOST_TEST(mentions(error_of("subsection Material\n set Poisson's ratio nu = 0.5\nend\n"), "Poisson's ratio nu = 0.5 is outside the allowed range (-1, 0.5)"));
  BOOST_TEST(mentions(error_of("subsection Material\n set Poisson's ratio nu = -1.5\nend\n"), "Poisson's ratio nu"));
  BOOST_TEST(mentions(error_of("subsection Material\n set Young's modulus E = 0\nend\n"), "Material/Young's modulus E = 0 is outside the allowed range (0, inf)"));
  BOOST_TEST(mentions(error_of("subsection Geometry\n set Gap radius c = 0\nend\n"), "Geometry/Gap radius c = 0"));
  BOOST_TEST(mentions(error_of("subsection Geometry\n set Gap radius c = 5\n set Domain radius R = 5\nend\n"), "Geometry/Domain radius R = 5"));
  BOOST_TEST(mentions(error_of("subsection Geometry\n set Domain height H = 0.5\nend\n"), "J-integral/Ring radii"));
  BOOST_TEST(mentions(error_of("subsection Mesh\n set Generator = gmsh\n set Mesh file = no-such.msh\nend\n"), "Mesh/Mesh file"));
  BOOST_TEST(mentions(error_of("subsection Geometry\n set Gap radius c = 1\n"), "unequal numbers of 'subsection' and 'end'"));
  BOOST_TEST(mentions(error_of("set Scene penny-gap\n"), "Invalid format of 'set'"));
}
