// Penny-gap scenes on test-sized meshes: K_I on every ring, the face opening
// at the centre and the gap volume within 1e-4 of Sneddon's closed forms.
#define BOOST_TEST_MODULE scenes
#define BOOST_TEST_NO_MAIN
#include "penny_scene.h"
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <sstream>

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  Parameters test_size(const std::string &name)
  {
    Parameters parameters             = default_parameters();
    parameters.mesh.tip_levels        = 20;
    parameters.finite_element.degree  = 3;
    parameters.output.write_fields    = false;
    parameters.output.directory       = (std::filesystem::temp_directory_path() / ("penny-test-" + name)).string();
    return parameters;
  }

  void check_against_closed_form(const Parameters &parameters, const double tolerance = 1e-4)
  {
    std::filesystem::create_directories(parameters.output.directory);
    std::ostringstream      log;
    const PennySceneResults results = run_penny_scene(parameters, log);
    BOOST_TEST_MESSAGE(log.str());
    for (const auto &ring : results.rings)
      {
        BOOST_TEST(ring.stress_intensity_factor == results.exact_stress_intensity_factor, tt::tolerance(tolerance));
        BOOST_TEST(ring.signed_stress_intensity_factor == ring.stress_intensity_factor, tt::tolerance(1e-6));
      }
    BOOST_TEST(results.opening_at_centre == results.exact_opening_at_centre, tt::tolerance(tolerance));
    BOOST_TEST(results.gap_volume == results.exact_gap_volume, tt::tolerance(tolerance));
    BOOST_TEST(std::filesystem::is_regular_file(parameters.output.directory + "/rings.csv"));
  }
} // namespace

BOOST_AUTO_TEST_CASE(uniform_pressure)
{
  check_against_closed_form(test_size("uniform"));
}

BOOST_AUTO_TEST_CASE(bueckner_tension)
{
  Parameters parameters          = test_size("bueckner");
  parameters.load.type           = LoadParameters::Type::parabolic;
  parameters.load.tension_radius = parameters.geometry.gap_radius / 0.8;
  check_against_closed_form(parameters);
}

BOOST_AUTO_TEST_CASE(quartic_expression)
{
  Parameters parameters      = test_size("quartic");
  parameters.load.type       = LoadParameters::Type::expression;
  parameters.load.expression = "P * (r/c)^4";
  parameters.finite_element.degree = 4; // w(0) needs the coarse cells near the axis
  check_against_closed_form(parameters);
}

BOOST_AUTO_TEST_CASE(clamped_far_boundary_and_other_scales)
{
  Parameters parameters                    = test_size("clamped");
  parameters.geometry.clamped_far_boundary = true;
  parameters.geometry.gap_radius           = 0.01;
  parameters.geometry.domain_radius        = 10;
  parameters.geometry.domain_height        = 7;
  parameters.material.youngs_modulus       = 7e10;
  parameters.material.poissons_ratio       = 0.2;
  check_against_closed_form(parameters);
}

// Beyond c/a = sqrt(3/2) the faces would interpenetrate: K_I < 0, which only
// the signed (interaction) form can tell.
BOOST_AUTO_TEST_CASE(negative_stress_intensity_factor)
{
  Parameters parameters          = test_size("negative");
  parameters.load.type           = LoadParameters::Type::parabolic;
  parameters.load.tension_radius = parameters.geometry.gap_radius / 1.6;
  std::filesystem::create_directories(parameters.output.directory);
  std::ostringstream      log;
  const PennySceneResults results = run_penny_scene(parameters, log);
  BOOST_TEST(results.exact_stress_intensity_factor < 0);
  for (const auto &ring : results.rings)
    BOOST_TEST(ring.signed_stress_intensity_factor == results.exact_stress_intensity_factor, tt::tolerance(1e-4));
}

BOOST_AUTO_TEST_CASE(gmsh_mesh)
{
  Parameters parameters       = test_size("gmsh");
  parameters.mesh.generator   = MeshParameters::Generator::gmsh;
  parameters.mesh.mesh_file   = TEST_DIR "/../meshes/penny-gap.geo";
  check_against_closed_form(parameters);
}
