// Penny-gap scenes on test-sized meshes: K_I on every ring, the face opening
// at the centre and the gap volume within 1e-4 of Sneddon's closed forms.
#include "output/table.h"
#include "scenes/scene.h"
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <fstream>
#include <iostream>

BOOST_AUTO_TEST_SUITE(test_scenes)

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  const std::vector<double> rings = {0.25, 0.5, 0.75};

  PennyGapMeasurement solve(const PennyGapModelParameters &model, const LoadParameters &load)
  {
    dealii::TimerOutput timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    return solve_penny_gap(model, load, rings, timer);
  }

  void check_against_closed_form(const PennyGapModelParameters &model, const LoadParameters &load,
                                 const double tolerance = 1e-4)
  {
    const PennyGapMeasurement results = solve(model, load);
    for (const auto &ring : results.rings)
      {
        BOOST_TEST(ring.stress_intensity_factor == results.exact_stress_intensity_factor.value,
                   tt::tolerance(tolerance));
        BOOST_TEST(ring.signed_stress_intensity_factor == ring.stress_intensity_factor, tt::tolerance(1e-6));
      }
    BOOST_TEST(results.opening_at_centre == results.exact_opening_at_centre.value, tt::tolerance(tolerance));
    BOOST_TEST(results.gap_volume == results.exact_gap_volume.value, tt::tolerance(tolerance));
  }

} // namespace

BOOST_AUTO_TEST_CASE(uniform_pressure)
{
  check_against_closed_form(test_size_model(20, 3), default_load());
}

// The degree graded down towards the tip (hp, Finite element/Degree grading):
// degree 6 lowered every 8 tip levels, 36 levels, a domain of 1e5 c. K_I,
// w(0) and the volume within 1e-10 (measured: 4.2e-11, 3.9e-11, 4.6e-11).
BOOST_AUTO_TEST_CASE(graded_degree_ten_digits)
{
  auto model                   = test_size_model(36, 6);
  model.mesh.grading_distance  = 1.5;
  model.geometry.domain_radius = 1e5;
  model.geometry.domain_height = 1e5;
  model.levels_per_degree      = 8;
  check_against_closed_form(model, default_load(), 1e-10);
}

BOOST_AUTO_TEST_CASE(bueckner_tension)
{
  const auto     model = test_size_model(20, 3);
  LoadParameters load  = default_load();
  load.type            = LoadParameters::Type::parabolic;
  load.tension_radius  = model.geometry.gap_radius / 0.8;
  check_against_closed_form(model, load);
}

BOOST_AUTO_TEST_CASE(quartic_expression)
{
  LoadParameters load = default_load();
  load.type           = LoadParameters::Type::expression;
  load.expression     = "P * (r/c)^4";
  check_against_closed_form(test_size_model(20, 4), load); // w(0) needs the coarse cells near the axis
}

BOOST_AUTO_TEST_CASE(clamped_far_boundary_and_other_scales)
{
  auto model                    = test_size_model(20, 3);
  model.geometry.far_boundary   = FarBoundary::clamped;
  model.geometry.gap_radius     = 0.01;
  model.geometry.domain_radius  = 10;
  model.geometry.domain_height  = 7;
  model.material.youngs_modulus = 7e10;
  model.material.poissons_ratio = 0.2;
  check_against_closed_form(model, default_load());
}

// Beyond c/a = sqrt(3/2) the faces would interpenetrate: K_I < 0, which only
// the signed (interaction) form can tell.
BOOST_AUTO_TEST_CASE(negative_stress_intensity_factor)
{
  const auto     model              = test_size_model(20, 3);
  LoadParameters load               = default_load();
  load.type                         = LoadParameters::Type::parabolic;
  load.tension_radius               = model.geometry.gap_radius / 1.6;
  const PennyGapMeasurement results = solve(model, load);
  BOOST_TEST(results.exact_stress_intensity_factor.value < 0);
  for (const auto &ring : results.rings)
    BOOST_TEST(ring.signed_stress_intensity_factor == results.exact_stress_intensity_factor.value,
               tt::tolerance(1e-4));
}

BOOST_AUTO_TEST_CASE(gmsh_mesh)
{
  auto model           = test_size_model(20, 3);
  model.mesh.generator = MeshParameters::Generator::gmsh;
  model.mesh.mesh_file = TEST_DIR "/../meshes/penny-gap.geo";
  check_against_closed_form(model, default_load());
}

// The whole scene, read from its file: its tables appear in the output
// folder, and only on commit.
BOOST_AUTO_TEST_CASE(scene_writes_its_results_as_a_set)
{
  const ScratchFolder scratch;
  const auto          prm = scratch.path / "scene.prm";
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream(prm) << "set Scene = penny-gap\nsubsection Mesh\n set Tip refinement levels = 12\nend\n"
                          "subsection Finite element\n set Polynomial degree = 2\nend\n"
                          "subsection Verification\n set Tolerance = 1e-3\nend\n";
  MPI_Barrier(MPI_COMM_WORLD);
  const SceneFile    file      = read_scene_file(prm.string());
  const auto         directory = scratch.path / "results";
  ResultFolder       results(directory, file.input_files);
  std::ostringstream log;
  BOOST_TEST(file.scene->run(results, log).passed);
  BOOST_TEST(!std::filesystem::exists(directory));
  MPI_Barrier(MPI_COMM_WORLD); // every rank looked before any commits
  results.commit();
  for (const char *name : {"rings.csv", "summary.csv", "solution.vtu", "solution.pvd"})
    BOOST_TEST(std::filesystem::is_regular_file(directory / name), name);
  BOOST_TEST(log.str().find("|K_I| relative error") != std::string::npos);
}

// CSV cells and column names holding a comma or a quote are quoted (RFC 4180),
// so that a reader finds as many fields in every line as there are columns.
BOOST_AUTO_TEST_CASE(csv_quotes_commas_and_quotes)
{
  Table table({{"ring (min(c, lambda/2 - c))"}, {"note"}});
  table.add_row({0.25, "a \"b\", c"});
  BOOST_TEST(table.csv() == "\"ring (min(c, lambda/2 - c))\",note\n0.25,\"a \"\"b\"\", c\"\n");
}

// The traction of the gap's far field on the far boundary (Far boundary =
// far field) makes a cylinder of 10 c answer the infinite solid: K_I, w(0)
// and the volume within 2e-5 of Sneddon's (measured at degree 4, 30 tip
// levels: 6.9e-6; the free cylinder is off by 1.1e-3, the clamped one by
// more), on 1 and 2 ranks alike.
BOOST_AUTO_TEST_CASE(far_field_boundary)
{
  auto model                   = test_size_model(30, 4);
  model.geometry.domain_radius = 10;
  model.geometry.domain_height = 10;
  model.geometry.far_boundary  = FarBoundary::far_field;
  check_against_closed_form(model, default_load(), 2e-5);
  model.geometry.far_boundary    = FarBoundary::free;
  const PennyGapMeasurement free = solve(model, default_load());
  BOOST_TEST(std::abs(free.rings.back().stress_intensity_factor / free.exact_stress_intensity_factor.value -
                      1) > 1e-3);
}

BOOST_AUTO_TEST_SUITE_END()
