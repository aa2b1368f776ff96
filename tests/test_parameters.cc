// Parameter files: the entries listed once (declared and read from one list),
// defaults, a shipped scene, the R_p form of the parabola, the subsections
// each scene reads, and the one-line InputError for each kind of bad entry.
#include "input/input_error.h"
#include "scenes/scene.h"
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <fstream>
#include <sstream>

BOOST_AUTO_TEST_SUITE(test_parameters)

using namespace penny;

namespace
{
  // Writes `text` to a parameter file named `name` and reads it.
  SceneFile read_text(const std::string &text, const std::string &name = "scene.prm")
  {
    const ScratchFolder scratch;
    const auto          path = scratch.path / name;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(path) << text;
    MPI_Barrier(MPI_COMM_WORLD);
    return read_scene_file(path.string());
  }

  // The InputError message for `text`, which must be one line.
  std::string error_of(const std::string &text, const std::string &name = "scene.prm")
  {
    try
      {
        read_text(text, name);
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
    std::ostringstream out;
    print_parameters(find_scene(scene), out);
    return out.str();
  }
} // namespace

// One list declares and reads: a value set in the file reaches its variable,
// the others keep their defaults, and a range is checked where it is read.
BOOST_AUTO_TEST_CASE(entries_declared_and_read_from_one_list)
{
  double              number = 0;
  std::vector<double> list;
  int                 choice  = 0;
  bool                flag    = false;
  const auto          entries = [&](Sections &sections) {
    sections.subsection("Part", [&](Entries &entries) {
      entries.number("Number", number, 2.5, interval("(]", 0, 10, "m"), "A number. Units: m.");
      entries.numbers("List", list, {1, 2}, interval("()", 0, 1e3), "Numbers.");
      entries.choice("Choice", choice, 1, {{"one", 1}, {"two", 2}}, "A choice.");
      entries.flag("Flag", flag, true, "A flag.");
    });
  };
  dealii::ParameterHandler prm;
  Sections                 declaring(prm, false);
  entries(declaring);
  prm.parse_input_from_string("subsection Part\n set List = 3, 4, 5\nend\n");
  Sections reading(prm, true);
  entries(reading);
  BOOST_TEST(number == 2.5);
  BOOST_TEST(list == std::vector<double>({3, 4, 5}), boost::test_tools::per_element());

  prm.parse_input_from_string("subsection Part\n set Number = 0\nend\n");
  BOOST_CHECK_EXCEPTION(entries(reading), InputError, [](const InputError &error) {
    return std::string(error.what()) == "Part/Number = 0 is outside the allowed range (0, 10] m";
  });
  std::ostringstream printed;
  prm.print_parameters(printed, dealii::ParameterHandler::PRM);
  BOOST_TEST(mentions(printed.str(), "A number. Units: m. Allowed: (0, 10] m."));
  BOOST_TEST(mentions(printed.str(), "A choice. Allowed: one, two."));
  BOOST_TEST(mentions(printed.str(), "A flag. Allowed: true, false."));
}

BOOST_AUTO_TEST_CASE(defaults)
{
  const PennyGapModelParameters model = default_penny_gap_model();
  BOOST_TEST(model.geometry.gap_radius == 1.);
  BOOST_TEST(model.material.poissons_ratio == 0.3);
  BOOST_TEST(model.degree == 4u);
  BOOST_TEST(model.material.plane_strain_modulus() == 1e9 / 0.91, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(default_load().peak_tension == 1e6);
  BOOST_TEST(default_periodic_gap().ring_radii.size() == 3u);
}

// Every shipped parameter file reads without error.
BOOST_AUTO_TEST_CASE(every_shipped_scene_reads)
{
  unsigned int files = 0;
  for (const auto &entry : std::filesystem::directory_iterator(TEST_DIR "/../prms"))
    if (entry.path().extension() == ".prm")
      {
        BOOST_TEST_CONTEXT(entry.path().string())
        {
          BOOST_CHECK_NO_THROW(read_scene_file(entry.path().string()));
        }
        ++files;
      }
  BOOST_TEST(files >= 23u);
}

BOOST_AUTO_TEST_CASE(shipped_scene)
{
  const SceneFile file = read_scene_file(TEST_DIR "/../prms/penny-bueckner.prm");
  BOOST_TEST(file.type->name == "penny-gap");
  BOOST_TEST(file.output_directory == "output/penny-bueckner");
  BOOST_TEST(mentions(file.used_parameters, "set Type              = parabolic"));
  BOOST_TEST(mentions(file.used_parameters, "subsection Fields"));
  BOOST_TEST(!mentions(file.used_parameters, "subsection Convergence"));
}

BOOST_AUTO_TEST_CASE(parabola_from_summit_radius)
{
  dealii::ParameterHandler prm;
  const GeometryParameters geometry = default_penny_gap_model().geometry;
  LoadParameters           load;
  Sections                 declaring(prm, false);
  face_load_section(declaring, load, geometry);
  prm.parse_input_from_string("subsection Load\n set Type = parabolic\n set Peak tension P = 2e6\n"
                              " set Parabola given by = R_p\n set Summit radius R_p = 1e-6\nend\n");
  Sections reading(prm, true);
  face_load_section(reading, load, geometry);
  BOOST_TEST(load.tension_radius == 2., boost::test_tools::tolerance(1e-15));
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
  const std::string minimum = printed_parameters("adhesive-minimum");
  BOOST_TEST(mentions(minimum, "set Summit radius R_p"));
  BOOST_TEST(!mentions(minimum, "set Expression"));

  BOOST_TEST(mentions(error_of("subsection Convergence\n set Cycles = 3\nend\n"),
                      "line 1: subsection 'Convergence' is not read by Scene = penny-gap"));
  BOOST_TEST(
      mentions(error_of("set Scene = area-load\nsubsection Mesh\n set Tip refinement levels = 3\nend\n"),
               "line 2: subsection 'Mesh' is not read by Scene = area-load"));
  BOOST_TEST(mentions(error_of("set Scene = no-such-scene\n"), "Scene = 'no-such-scene' is not a scene"));
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
                      "line 1: subsection 'Geometry' has no 'end'"));
  BOOST_TEST(mentions(error_of("set Scene penny-gap\n"), "Invalid format of 'set'"));
  // One bound for every load: an expression beyond 1e30 Pa as for P itself.
  BOOST_TEST(mentions(error_of("subsection Load\n set Type = expression\n set Expression = 1e31\nend\n"),
                      "Load/Expression = '1e31' gives |p| up to 1e+31 Pa on the gap face"));
  // The depth study's depths, as the periodic gap's depth, from 0.05 lambda.
  BOOST_TEST(mentions(
      error_of("set Scene = periodic-gap-depth\nsubsection Depth study\n set Depths = 0.01, 1\nend\n"),
      "Depth study/Depths = 0.01 is outside the allowed range [0.05, 100] lambda"));
  // A list of cases holds no value twice.
  BOOST_TEST(
      mentions(error_of("set Scene = area-load\nsubsection Area-load\n set Hurst exponents = 0.5, 0.25, "
                        "0.5\nend\n"),
               "Area-load/Hurst exponents = '0.5, 0.25, 0.5' holds 0.5 twice: a list of distinct numbers in "
               "[0.01, 1)"));
  BOOST_TEST(
      mentions(error_of("subsection Load\n set Peak tension P = 1e31\nend\n"),
               "Load/Peak tension P = 1e+31 is outside the allowed range 0 or |x| in [1e-30, 1e30] Pa"));
}

// The .prm scan reads lines as deal.II does: trimmed (CR too) before a
// continuation, tabs as spaces, keywords in lower or upper case.
BOOST_AUTO_TEST_CASE(prm_lines_read_as_deal_ii_reads_them)
{
  const SceneFile file =
      read_text("set Scene = area-load\r\nsubsection Area-load\r\n set Magnifications = 1, \\ \r\n"
                "\t100\r\nEND\r\n");
  BOOST_TEST(mentions(file.used_parameters, "= 1, 100"));
  BOOST_TEST(mentions(
      error_of("subsection Mesh\n set Tip refinement levels = 12\n set Tip\trefinement levels = 14\nend\n"),
      "line 3: Mesh/Tip refinement levels is set a second time (first on line 2)"));
  BOOST_TEST(mentions(
      error_of(
          "subsection Mesh\n set Tip refinement levels = 12 # was 10 \\\n set Grading distance = 3\nend\n"),
      "line 2: a comment ends in '\\', which would join the next line to the comment"));
  BOOST_TEST(
      mentions(error_of("Subsection Mesh\nend\n"),
               "line 1: 'Subsection': a keyword is all lower or all upper case (subsection or SUBSECTION)"));
  BOOST_TEST(mentions(error_of("subsection Mesh\nend Mesh\n"), "line 2: 'end' takes nothing after it"));
  BOOST_TEST(mentions(error_of("include\n"), "line 1: 'include' without a file name"));
  // Only a line that ends in a backslash joins the next: a value ending in
  // one keeps it when the next line is blank; the file's last line may end in one.
  BOOST_TEST(read_text("subsection Output\n set Directory = o\\\\\n\nend\\").output_directory == "o\\");
}

// The file's kind by its extension in any case, as deal.II's parse_input tells it.
BOOST_AUTO_TEST_CASE(extension_of_any_case)
{
  BOOST_TEST(read_text("set Scene = area-load\n", "scene.PRM").type->name == "area-load");
  BOOST_TEST(read_text("{\"Scene\": \"area-load\"}", "scene.Json").type->name == "area-load");
  BOOST_TEST(
      read_text("<ParameterHandler><Scene>area-load</Scene></ParameterHandler>", "scene.XML").type->name ==
      "area-load");
  BOOST_TEST(mentions(error_of("set Scene = area-load\n", "scene.txt"), "is neither .prm, .json nor .xml"));
  BOOST_TEST(mentions(
      error_of("<ParameterHandler><Scene kind=\"x\">area-load</Scene></ParameterHandler>", "scene.xml"),
      "an XML attribute in "));
}

// JSON and XML files: comments skipped, deal.II's entry records read by their
// value alone, and what they cannot hold refused by name.
BOOST_AUTO_TEST_CASE(json_xml_files)
{
  const std::string xml_scene = "<ParameterHandler><Scene>area-load</Scene>";
  BOOST_TEST(
      read_text("<!-- a --><ParameterHandler><!-- b --><Scene>area-load</Scene><Output><Directory>o<!-- "
                "c -->ut</Directory></Output></ParameterHandler>",
                "scene.xml")
          .output_directory == "out");
  BOOST_TEST(
      mentions(error_of(xml_scene + "<Output k=\"x\"><Directory>out</Directory></Output></ParameterHandler>",
                        "scene.xml"),
               "an XML attribute in Output;"));
  BOOST_TEST(mentions(
      error_of("<ParameterHandler><Scene><value k=\"x\">area-load</value></Scene></ParameterHandler>",
               "scene.xml"),
      "an XML attribute in Scene/value;"));
  BOOST_TEST(mentions(error_of("<!DOCTYPE ParameterHandler [<!ENTITY d \"out\">]>" + xml_scene +
                                   "<Output><Directory>&d;</Directory></Output></ParameterHandler>",
                               "scene.xml"),
                      "a DOCTYPE or other declaration"));
  BOOST_TEST(
      read_text("{\"Scene\": {\"value\": \"area-load\", \"default_value\": \"penny-gap\"}}", "scene.json")
          .type->name == "area-load");
  BOOST_TEST(mentions(error_of("{\"Scene\": {\"value\": \"area-load\", \"junk\": \"x\"}}", "scene.json"),
                      "'junk' in the entry record of Scene"));
  BOOST_TEST(mentions(error_of("{\"Scene\": {\"x\": \"area-load\"}}", "scene.json"),
                      "Scene holds entries, not a scene's name"));
  BOOST_TEST(mentions(
      error_of("{\"Scene\": \"penny-gap\", \"Geometry\": {\"Far boundary\": \"Free\"}}", "scene.json"),
      "Geometry/Far boundary = 'Free' is not one of free, clamped, far field"));
  BOOST_TEST(mentions(
      error_of(xml_scene + "</ParameterHandler><Output><Directory>x</Directory></Output>", "scene.xml"),
      "is not one element <ParameterHandler> holding the entries"));
  // Boost reads a null as the text "null", and {} as an empty entry; an
  // error of syntax names the file and the line.
  BOOST_TEST(
      mentions(error_of("{\"Scene\": \"area-load\",\n \"Output\": {\"Directory\": null}}", "scene.json"),
               "a null on line 2: a value is text"));
  BOOST_TEST(read_text("{\"Scene\": \"area-load\", \"Output\": {}}", "scene.json").output_directory ==
             "output");
  BOOST_TEST(read_text(xml_scene + "<Output/></ParameterHandler>", "scene.xml").output_directory == "output");
  BOOST_TEST(mentions(error_of("{\"Scene\": \"area-load\",\n \"Output\" {}}", "scene.json"),
                      "is not valid JSON: line 2: expected ':'"));
}

// The sinusoid's scenes: the shipped periodic gap, the sections each reads,
// and the checks across entries.
BOOST_AUTO_TEST_CASE(sinusoid_scenes)
{
  const SceneFile file = read_scene_file(TEST_DIR "/../prms/periodic-gap.prm");
  BOOST_TEST(file.type->name == "periodic-gap");
  BOOST_TEST(mentions(file.used_parameters, "set Gap half-width c/lambda = 0.2"));
  BOOST_TEST(!mentions(file.used_parameters, "subsection Geometry"));
  const std::string johnson = printed_parameters("johnson-curves");
  BOOST_TEST(mentions(johnson, "subsection Johnson curves"));
  BOOST_TEST(mentions(johnson, "subsection Periodic gap"));
  BOOST_TEST(!mentions(johnson, "subsection Gap and load"));
  BOOST_TEST(!mentions(johnson, "subsection Mesh"));

  BOOST_TEST(mentions(
      error_of("set Scene = johnson-curves\nsubsection Gap and load\n set Peak tension p* = 1\nend\n"),
      "line 2: subsection 'Gap and load' is not read by Scene = johnson-curves"));
  BOOST_TEST(mentions(
      error_of("set Scene = periodic-gap-depth\nsubsection Depth study\n set Depths = 0.125, 1\nend\n"),
      "Depth study/Depths = 0.125 is outside the allowed range (largest ring radius/4 = 0.1875, 100] "
      "lambda"));
  BOOST_TEST(
      mentions(error_of("set Scene = periodic-gap\nsubsection Gap and load\n set Peak tension p* = 0\nend\n"),
               "Gap and load/Peak tension p* = 0 is outside the allowed range [1e-30, 1e30] Pa"));
  BOOST_TEST(
      mentions(error_of("set Scene = jump-into-contact\nsubsection Jump into contact\n set Smallest alpha = "
                        "0.25\n set Largest alpha = 0.125\nend\n"),
               "Jump into contact/Largest alpha = 0.125"));
}

BOOST_AUTO_TEST_SUITE_END()
