// The periodic-gap model of Johnson's sinusoid on test-sized meshes: K_I on
// every ring and its sign against the closed form, with the tip near either
// symmetry line, at other scales and on 1 or 2 MPI ranks; and each of its
// scenes' computations: the truncation study, the Westergaard and Johnson
// curves, the critical alpha and the jump into contact.
#define BOOST_TEST_MODULE periodic_gap
#define BOOST_TEST_NO_MAIN
#include "fe/boundary_ids.h"
#include "fe/tip_graded_mesh.h"
#include "fracture/periodic_array.h"
#include "fracture/periodic_searches.h"
#include "scenes/sinusoid_scenes.h"
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <iostream>
#include <set>

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  // The scene's parameters at test size: the model checks on 14 tip levels at
  // degree 3 (K_I within about 4e-6), the searches, dozens of solves each, on
  // 10 levels at degree 2 (about 1e-4).
  Parameters test_size_parameters(const std::string &scene, const bool search = false)
  {
    Parameters parameters                     = default_parameters(scene);
    parameters.periodic_gap->tip_levels       = search ? 10 : 14;
    parameters.periodic_gap->grading_distance = 2;
    parameters.finite_element->degree         = search ? 2 : 3;
    return parameters;
  }

  PeriodicGapResults solve(const Parameters &parameters, const double c_over_lambda, const double load_ratio)
  {
    dealii::TimerOutput timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    const double        lambda = parameters.periodic_gap->wavelength;
    const double        p_star = 1e6;
    return solve_periodic_gap(periodic_gap_model(parameters, c_over_lambda * lambda),
                              {lambda, p_star, load_ratio * p_star}, parameters.periodic_gap->ring_radii,
                              timer);
  }

  void check_against_closed_form(const PeriodicGapResults &results, const double tolerance)
  {
    for (const auto &ring : results.rings)
      {
        BOOST_TEST(ring.signed_stress_intensity_factor == results.exact_stress_intensity_factor,
                   tt::tolerance(tolerance));
        BOOST_TEST(ring.stress_intensity_factor == std::abs(results.exact_stress_intensity_factor),
                   tt::tolerance(tolerance));
      }
    BOOST_TEST(results.cosine_sif == results.exact_cosine_sif, tt::tolerance(tolerance));
    BOOST_TEST(results.uniform_sif == results.exact_uniform_sif, tt::tolerance(tolerance));
  }

  const double sif_tolerance = 1e-5, search_tolerance = 3e-4;
} // namespace

// The coarse grid is laid from x = 0 for c < lambda/4 and from x = lambda/2
// beyond: both symmetry lines carry the tip zone in turn. K_I of a short gap
// is nearly the isolated crack's, of a long one (short ligament) far above it.
BOOST_AUTO_TEST_CASE(stress_intensity_factor_on_every_ring)
{
  const Parameters parameters = test_size_parameters("periodic-gap");
  for (const double c_over_lambda : {0.05, 0.2, 0.3, 0.45})
    check_against_closed_form(solve(parameters, c_over_lambda, 0.1), sif_tolerance);
}

// p_bar/p* above cos^2(pi c/lambda): the faces would interpenetrate, K_I < 0.
BOOST_AUTO_TEST_CASE(negative_stress_intensity_factor)
{
  const PeriodicGapResults results = solve(test_size_parameters("periodic-gap"), 0.4, 0.3);
  BOOST_TEST(results.exact_stress_intensity_factor < 0);
  check_against_closed_form(results, sif_tolerance);
}

// The degree graded down towards the tip (hp, Finite element/Degree grading):
// degree 6 lowered every 8 tip levels, 32 levels, grading distance 1.5, the
// default depth 3 lambda. K_I on every ring within 1e-10 (measured: 4.8e-12),
// with fewer degrees of freedom than degree 6 on every cell.
BOOST_AUTO_TEST_CASE(graded_degree_ten_digits)
{
  Parameters parameters                        = default_parameters("periodic-gap");
  parameters.periodic_gap->tip_levels          = 32;
  parameters.periodic_gap->grading_distance    = 1.5;
  parameters.finite_element->degree            = 6;
  parameters.finite_element->levels_per_degree = 8;
  const PeriodicGapResults graded              = solve(parameters, 0.2, 0.1);
  check_against_closed_form(graded, 1e-10);
  parameters.finite_element->levels_per_degree = 0;
  BOOST_TEST(graded.n_dofs < 0.6 * solve(parameters, 0.2, 0.1).n_dofs);
}

BOOST_AUTO_TEST_CASE(other_scales)
{
  Parameters parameters               = test_size_parameters("periodic-gap");
  parameters.periodic_gap->wavelength = 2e-6;
  parameters.periodic_gap->depth      = 1.5;
  parameters.material->youngs_modulus = 3e6;
  parameters.material->poissons_ratio = 0.45;
  check_against_closed_form(solve(parameters, 0.15, -0.5), sif_tolerance);
}

// Boundary ids of the half period: both symmetry lines, the far side, and the
// plane z = 0 split at the tip, which is a vertex.
BOOST_AUTO_TEST_CASE(mesh_and_boundary_ids)
{
  const Parameters parameters = test_size_parameters("periodic-gap");
  for (const double c_over_lambda : {0.01, 0.25, 0.49})
    {
      dealii::TimerOutput    timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
      const auto             model = periodic_gap_model(parameters, c_over_lambda);
      const PeriodicGapModel gap(model, timer);
      const auto            &triangulation = gap.get_system().get_triangulation();
      std::set<dealii::types::boundary_id> ids;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            ids.insert(face->boundary_id());
            const auto x = face->center();
            if (face->boundary_id() == boundary_id::gap_face)
              BOOST_TEST(x[0] < model.gap_half_width);
            if (face->boundary_id() == boundary_id::ligament)
              BOOST_TEST(x[0] > model.gap_half_width);
            if (face->boundary_id() == boundary_id::second_symmetry)
              BOOST_TEST(x[0] == 0.5, tt::tolerance(1e-14));
            if (face->boundary_id() == boundary_id::far)
              BOOST_TEST(x[1] == model.depth, tt::tolerance(1e-14));
          }
      BOOST_TEST(ids.size() == 5u);
      BOOST_TEST(has_vertex_at(triangulation, gap.crack_tip(), 1e-14));
    }
}

BOOST_AUTO_TEST_CASE(depth_study_errors_fall_with_depth)
{
  Parameters parameters          = test_size_parameters("periodic-gap-depth");
  parameters.depth_study->depths = {0.5, 1, 1.5};
  const ScratchFolder scratch;
  ResultFolder        results(scratch.path / "depth", {});
  std::ostringstream  log;
  const auto          rows = run_periodic_gap_depth_scene(parameters, results, log);
  BOOST_TEST(rows.size() == 3u);
  BOOST_TEST(rows[0].error > 10 * rows[1].error);
  BOOST_TEST(rows[1].error > 10 * rows[2].error);
  BOOST_TEST(rows[2].error < sif_tolerance);
}

BOOST_AUTO_TEST_CASE(westergaard_curve)
{
  Parameters parameters                  = test_size_parameters("westergaard-curve", true);
  parameters.westergaard_curve->n_points = 3;
  const ScratchFolder scratch;
  ResultFolder        results(scratch.path / "westergaard", {});
  std::ostringstream  log;
  const CurveErrors   errors = run_westergaard_curve_scene(parameters, results, log);
  BOOST_TEST(errors.largest_load_error < search_tolerance);
  BOOST_TEST(errors.largest_contact_ratio_error < search_tolerance);
}

BOOST_AUTO_TEST_CASE(johnson_curves)
{
  Parameters parameters               = test_size_parameters("johnson-curves"); // five solves: the finer size
  parameters.johnson_curves->n_points = 5;
  const ScratchFolder scratch;
  ResultFolder        results(scratch.path / "johnson", {});
  std::ostringstream  log;
  const CurveErrors   errors = run_johnson_curves_scene(parameters, results, log);
  BOOST_TEST(errors.largest_load_error < 2 * sif_tolerance);
  BOOST_TEST(errors.n_solves == 10u); // one factorisation, two loads, per contact half-width
  results.commit();
  for (const char *file : {"johnson-curves.csv", "johnson-closed-form.csv", "johnson-extremes.csv"})
    BOOST_TEST(std::filesystem::is_regular_file(scratch.path / "johnson" / file), file);
}

BOOST_AUTO_TEST_CASE(critical_alpha_and_jump_into_contact)
{
  Parameters parameters                        = test_size_parameters("jump-into-contact", true);
  parameters.jump_into_contact->smallest_alpha = 1e-3;
  parameters.jump_into_contact->largest_alpha  = 0.3;
  parameters.jump_into_contact->n_alphas       = 2;
  const ScratchFolder          scratch;
  ResultFolder                 results(scratch.path / "jump", {});
  std::ostringstream           log;
  const JumpIntoContactResults jump = run_jump_into_contact_scene(parameters, results, log);
  BOOST_TEST(jump.critical_alpha == periodic_array::critical_alpha, tt::tolerance(search_tolerance));
  BOOST_TEST(jump.critical_contact_ratio == periodic_array::critical_contact_ratio, tt::tolerance(1e-2));
  BOOST_TEST(jump.largest_jump_error < search_tolerance);
}
