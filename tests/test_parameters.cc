// Parameter files: defaults, a shipped scene, the R_p form of the parabola, the
// sections each scene reads, and the one-line InputError for each kind of bad
// entry.
#define BOOST_TEST_MODULE parameters
#define BOOST_TEST_NO_MAIN
#include "input/input_error.h"
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <fstream>
#include <sstream>

using namespace penny;

namespace
{
  // Writes `text` to a parameter file and reads it.
  SceneFile read_text(const std::string &text)
  {
    const ScratchFolder scratch;
    const auto          path = scratch.path / "scene.prm";
    std::ofstream(path) << text;
    return read_scene_file(path.string());
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

  std::string printed_parameters(const std::string &scene)
  {
    dealii::ParameterHandler prm;
    declare_scene(prm, find_scene(scene));
    std::ostringstream out;
    prm.print_parameters(out, dealii::ParameterHandler::PRM);
    return out.str();
  }
} // namespace

BOOST_AUTO_TEST_CASE(defaults)
{
  const Parameters parameters = default_parameters();
  BOOST_TEST(parameters.scene == "penny-gap");
  BOOST_TEST(parameters.geometry->gap_radius == 1.);
  BOOST_TEST(parameters.material->poissons_ratio == 0.3);
  BOOST_TEST(parameters.finite_element->degree == 4u);
  BOOST_TEST(parameters.j_integral->ring_radii.size() == 3u);
  BOOST_TEST(parameters.material->plane_strain_modulus() == 1e9 / 0.91, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(!parameters.convergence.has_value());
  BOOST_TEST(!parameters.roughness.has_value());
}

BOOST_AUTO_TEST_CASE(shipped_scene)
{
  const SceneFile file = read_scene_file(TEST_DIR "/../prms/penny-bueckner.prm");
  BOOST_TEST(file.scene->name == "penny-gap");
  BOOST_TEST((file.parameters.load->type == LoadParameters::Type::parabolic));
  BOOST_TEST(file.parameters.load->tension_radius == 1.25);
  BOOST_TEST(file.parameters.output->directory == "output/penny-bueckner");
  BOOST_TEST(mentions(file.used_parameters, "subsection Fields"));
  BOOST_TEST(!mentions(file.used_parameters, "subsection Convergence"));
}

BOOST_AUTO_TEST_CASE(parabola_from_summit_radius)
{
  const SceneFile file = read_text("subsection Load\n set Type = parabolic\n set Peak tension P = 2e6\n"
                                   " set Parabola given by = R_p\n set Summit radius R_p = 1e-6\nend\n");
  BOOST_TEST(file.parameters.load->tension_radius == 2., boost::test_tools::tolerance(1e-15));
}

// A scene declares, prints and accepts only the subsections it reads.
BOOST_AUTO_TEST_CASE(scenes_read_only_their_sections)
{
  const std::string penny_gap = printed_parameters("penny-gap");
  BOOST_TEST(mentions(penny_gap, "subsection Geometry"));
  BOOST_TEST(!mentions(penny_gap, "subsection Convergence"));
  BOOST_TEST(!mentions(penny_gap, "subsection Roughness"));
  const std::string area_load = printed_parameters("area-load");
  BOOST_TEST(!mentions(area_load, "subsection Mesh"));
  BOOST_TEST(mentions(area_load, "subsection Area-load"));

  BOOST_TEST(mentions(error_of("subsection Convergence\n set Cycles = 3\nend\n"),
                      "line 1: subsection 'Convergence' is not read by Scene = penny-gap"));
  BOOST_TEST(
      mentions(error_of("set Scene = area-load\nsubsection Mesh\n set Tip refinement levels = 3\nend\n"),
               "line 2: subsection 'Mesh' is not read by Scene = area-load"));
  BOOST_TEST(mentions(error_of("set Scene = no-such-scene\n"), "Scene"));
}

BOOST_AUTO_TEST_CASE(bad_entries)
{
  BOOST_TEST(mentions(error_of("subsection Geometry\n set Gap size = 1\nend\n"), "Gap size"));
  BOOST_TEST(
      mentions(error_of("subsection Material\n set Young's modulus E = stiff\nend\n"), "Young's modulus E"));
  BOOST_TEST(mentions(error_of("subsection Material\n set Poisson's ratio nu = 0.5\nend\n"),
                      "Poisson's ratio nu = 0.5 is outside the allowed range (-1, 0.5)"));
  BOOST_TEST(
      mentions(error_of("subsection Material\n set Poisson's ratio nu = -1.5\nend\n"), "Poisson's ratio nu"));
  BOOST_TEST(mentions(error_of("subsection Material\n set Young's modulus E = 0\nend\n"),
                      "Material/Young's modulus E = 0 is outside the allowed range [1e-30, 1e30] Pa"));
  BOOST_TEST(
      mentions(error_of("subsection Geometry\n set Gap radius c = 0\nend\n"), "Geometry/Gap radius c = 0"));
  BOOST_TEST(mentions(error_of("subsection Geometry\n set Gap radius c = 5\n set Domain radius R = 5\nend\n"),
                      "Geometry/Domain radius R = 5"));
  BOOST_TEST(
      mentions(error_of("subsection Geometry\n set Domain height H = 0.5\nend\n"), "J-integral/Ring radii"));
  BOOST_TEST(mentions(error_of("subsection Mesh\n set Generator = gmsh\n set Mesh file = no-such.msh\nend\n"),
                      "Mesh/Mesh file"));
  BOOST_TEST(mentions(error_of("subsection Geometry\n set Gap radius c = 1\n"),
                      "unequal numbers of 'subsection' and 'end'"));
  BOOST_TEST(mentions(error_of("set Scene penny-gap\n"), "Invalid format of 'set'"));
}

// The sinusoid's scenes: the shipped periodic gap, the sections each reads,
// and the checks across entries.
BOOST_AUTO_TEST_CASE(sinusoid_scenes)
{
  const SceneFile file = read_scene_file(TEST_DIR "/../prms/periodic-gap.prm");
  BOOST_TEST(file.scene->name == "periodic-gap");
  BOOST_TEST(file.parameters.gap_and_load->gap_ratio == 0.2);
  BOOST_TEST(file.parameters.periodic_gap->depth == 3.);
  BOOST_TEST(!file.parameters.geometry.has_value());
  const std::string johnson = printed_parameters("johnson-curves");
  BOOST_TEST(mentions(johnson, "subsection Johnson curves"));
  BOOST_TEST(mentions(johnson, "subsection Periodic gap"));
  BOOST_TEST(!mentions(johnson, "subsection Gap and load"));
  BOOST_TEST(!mentions(johnson, "subsection Mesh"));

  BOOST_TEST(mentions(
      error_of("set Scene = johnson-curves\nsubsection Gap and load\n set Peak tension p* = 1\nend\n"),
      "line 2: subsection 'Gap and load' is not read by Scene = johnson-curves"));
  BOOST_TEST(mentions(
      error_of("set Scene = periodic-gap-depth\nsubsection Depth study\n set Depths = 1, 0.125\nend\n"),
      "Depth study/Depths = 0.125 is outside the allowed range (largest ring radius/4 = 0.1875, 100] lambda"));
  BOOST_TEST(
      mentions(error_of("set Scene = periodic-gap\nsubsection Gap and load\n set Peak tension p* = 0\nend\n"),
               "Gap and load/Peak tension p* = 0 is outside the allowed range [1e-30, 1e30] Pa"));
  BOOST_TEST(
      mentions(error_of("set Scene = jump-into-contact\nsubsection Jump into contact\n set Smallest alpha = "
                        "0.25\n set Largest alpha = 0.125\nend\n"),
               "Jump into contact/Largest alpha = 0.125"));
}
