// The size of a model known before it is built, against the meshes and
// systems actually built: the quadtree's cells from the parameters, and the
// degrees of freedom and matrix entries from the cells.
#include "fe/elliptical_gap_model.h"
#include "fe/penny_gap_mesh.h"
#include "fe/penny_gap_model.h"
#include "fe/problem_size.h"
#include "input/input_error.h"
#include "problems/elliptical_gap.h"
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <iostream>

BOOST_AUTO_TEST_SUITE(test_problem_size)

using namespace penny;

namespace
{
  struct Case
  {
    unsigned int tip_levels;
    double       grading_distance;
    double       R_over_c, H_over_c;
    double       aspect_ratio;
    unsigned int global_refinements;
  };

  PennyGapModelParameters model_of(const Case &c, const unsigned int degree)
  {
    PennyGapModelParameters model = test_size_model(c.tip_levels, degree);
    model.mesh.grading_distance   = c.grading_distance;
    model.mesh.cell_aspect_ratio  = c.aspect_ratio;
    model.mesh.global_refinements = c.global_refinements;
    model.geometry.gap_radius     = 0.3;
    model.geometry.domain_radius  = c.R_over_c * 0.3;
    model.geometry.domain_height  = c.H_over_c * 0.3;
    return model;
  }

  const std::vector<Case> cases = {
      {30, 2, 1000, 1000, 1, 0}, {12, 2, 1000, 1000, 1, 2}, {20, 0.5, 10, 10, 1, 0},
      {20, 5, 1000, 3, 1, 0},    {8, 10, 50, 2000, 1, 1},   {25, 2, 1000, 1000, 10, 0},
      {40, 2, 1e6, 1e6, 1, 0},   {6, 1.5, 1.5, 0.2, 1, 0},  {30, 3.7, 4000, 100, 100, 0}};
} // namespace

// Balancing the levels across vertices adds cells the count leaves out: the
// estimate may be below the mesh by that much (16 % where a grading distance
// of 0.5 meets the refined gap face), never above it by more than the
// rounding of the last coarse cells.
BOOST_AUTO_TEST_CASE(quadtree_cells_against_built_meshes)
{
  for (const Case &c : cases)
    {
      const PennyGapModelParameters model = model_of(c, 1);
      dealii::Triangulation<2> triangulation(dealii::Triangulation<2>::limit_level_difference_at_vertices);
      const double             estimate = quadtree_cells(model.geometry, model.mesh);
      make_penny_gap_mesh(triangulation, model.geometry, model.mesh);
      const double built = triangulation.n_active_cells();
      BOOST_TEST_MESSAGE("levels " << c.tip_levels << " grading " << c.grading_distance << " R/c "
                                   << c.R_over_c << " H/c " << c.H_over_c << ": estimate " << estimate
                                   << ", built " << built);
      BOOST_TEST(estimate >= 0.8 * built);
      BOOST_TEST(estimate <= 1.05 * built);
    }
}

// Degrees of freedom and matrix entries from the cells, against the system:
// never much below, and above by at most the share of hanging nodes and
// constrained rows the estimate assumes.
BOOST_AUTO_TEST_CASE(dofs_and_matrix_entries_against_built_systems)
{
  for (const auto &[c, degree] : std::vector<std::pair<Case, unsigned int>>{
           {cases[0], 1}, {cases[0], 2}, {cases[0], 4}, {cases[3], 1}, {cases[3], 2}})
    {
      dealii::TimerOutput timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
      const PennyGapModel gap(model_of(c, degree), timer);
      const auto         &system = gap.get_system();
      const ProblemSize   size   = problem_size(system.get_triangulation().n_global_active_cells(), degree,
                                                LinearSolverParameters::Type::direct, 1);
      const double        dofs   = system.get_dof_handler().n_dofs();
      BOOST_TEST_MESSAGE("degree " << degree << ": DoFs estimate " << size.dofs << ", built " << dofs
                                   << "; matrix entries estimate " << size.matrix_entries << ", built "
                                   << system.n_matrix_entries());
      BOOST_TEST(size.dofs >= 0.9 * dofs);
      BOOST_TEST(size.dofs <= 1.3 * dofs);
      BOOST_TEST(size.matrix_entries >= 0.9 * system.n_matrix_entries());
      BOOST_TEST(size.matrix_entries <= 2.0 * system.n_matrix_entries());
    }
}

// Where its entries are read, before any mesh is built.
BOOST_AUTO_TEST_CASE(a_model_too_large_is_refused_before_it_is_built)
{
  auto model                    = test_size_model(30, 4);
  model.mesh.global_refinements = 10;
  BOOST_CHECK_THROW(check_model_size(model, model_cells(model)), InputError);
  model.mesh.global_refinements = 0;
  BOOST_CHECK_NO_THROW(check_model_size(model, model_cells(model)));
}

namespace
{
  // The small elliptical model (test_support.h) of degree p, on CG with AMG.
  EllipticalGapModelParameters small_elliptical_model(const double b_over_a, const unsigned int degree)
  {
    EllipticalGapModelParameters model;
    model.mesh          = small_elliptical_mesh(b_over_a);
    model.degree        = degree;
    model.material      = {1e9, 0.3};
    model.linear_solver = {LinearSolverParameters::Type::cg_amg, 1e-10, 1000};
    return model;
  }
} // namespace

// The 3D estimate from the built model's cells, against its system (the
// small mesh refined once, about 700 cells): degrees of freedom within 10 %,
// matrix entries never below and at most 1.6 times above (the estimate's
// mean couplings are those of a large mesh's interior).
BOOST_AUTO_TEST_CASE(elliptical_dofs_and_matrix_entries_against_built_systems)
{
  for (const unsigned int degree : {1u, 2u})
    {
      EllipticalGapModelParameters model = small_elliptical_model(0.5, degree);
      model.global_refinements           = 1;
      dealii::TimerOutput      timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
      const EllipticalGapModel gap(model, timer);
      const auto              &system = gap.get_system();
      const ProblemSize size = elliptical_problem_size(system.get_triangulation().n_global_active_cells(),
                                                       degree, LinearSolverParameters::Type::cg_amg, 1);
      const double      dofs = system.get_dof_handler().n_dofs(), entries = system.n_matrix_entries();
      BOOST_TEST_MESSAGE("degree " << degree << ": DoFs estimate " << size.dofs << ", built " << dofs
                                   << "; matrix entries estimate " << size.matrix_entries << ", built "
                                   << entries);
      BOOST_TEST(size.dofs >= 0.9 * dofs);
      BOOST_TEST(size.dofs <= 1.1 * dofs);
      BOOST_TEST(size.matrix_entries >= entries);
      BOOST_TEST(size.matrix_entries <= 1.6 * entries);
    }
}

// The cells known before the mesh is refined: exact for uniform refinement,
// an upper bound within 50 % with the tip's (the coarse cells that meet its ball count whole).
BOOST_AUTO_TEST_CASE(elliptical_cells_against_built_meshes)
{
  for (const unsigned int tip_refinements : {0u, 1u})
    {
      EllipticalGapModelParameters model = small_elliptical_model(0.25, 1);
      model.global_refinements           = 1;
      model.tip_refinements              = tip_refinements;
      model.tip_refinement_radius        = 0.3;
      dealii::TimerOutput      timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
      const EllipticalGapModel gap(model, timer);
      const double             built    = gap.get_system().get_triangulation().n_global_active_cells();
      const double             estimate = elliptical_model_cells(model);
      BOOST_TEST_MESSAGE(tip_refinements << " tip refinement(s): estimate " << estimate << ", built "
                                         << built);
      if (tip_refinements == 0)
        BOOST_TEST(estimate == built);
      else
        {
          BOOST_TEST(estimate >= built);
          BOOST_TEST(estimate <= 1.5 * built);
        }
    }
}

// The coarse mesh's cells counted without building it, against the built
// mesh: the default one and a fine web around a slender front.
BOOST_AUTO_TEST_CASE(elliptical_coarse_cells_counted)
{
  EllipticalGapMeshParameters fine_web;
  fine_web.semi_axis_b        = 0.1;
  fine_web.cells_along_front  = 24;
  fine_web.cells_around_front = 12;
  fine_web.ring_ratio         = 1.3;
  for (const auto &mesh : {EllipticalGapMeshParameters(), fine_web})
    {
      dealii::Triangulation<3> built;
      make_elliptical_gap_mesh(built, mesh);
      BOOST_TEST(elliptical_gap_mesh_cells(mesh) == built.n_active_cells());
    }
}

// Its cells known before it is refined, and refused on every rank.
BOOST_AUTO_TEST_CASE(an_elliptical_model_too_large_is_refused_before_it_is_refined)
{
  EllipticalGapModelParameters model = small_elliptical_model(0.5, 4);
  model.linear_solver.type           = LinearSolverParameters::Type::cg_multigrid;
  model.global_refinements           = 6;
  BOOST_CHECK_THROW(check_elliptical_model_size(model), InputError);
  model.global_refinements = 1;
  BOOST_CHECK_NO_THROW(check_elliptical_model_size(model));
}

BOOST_AUTO_TEST_SUITE_END()
