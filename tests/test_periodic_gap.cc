// The periodic-gap model of Johnson's sinusoid on test-sized meshes: K_I on
// every ring and its sign against the closed form, with the tip near either
// symmetry line, at other scales and on 1 or 2 MPI ranks; and the
// computations its scenes build on: the truncation study, the Westergaard and
// Johnson curves, the critical alpha and the jump into contact.
#include "closed_forms/periodic_array.h"
#include "fe/boundary_ids.h"
#include "fe/tip_graded_mesh.h"
#include "numerics/relative_error.h"
#include "searches/periodic_searches.h"
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <iostream>
#include <set>

BOOST_AUTO_TEST_SUITE(test_periodic_gap)

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  // The model at test size: the model checks on 14 tip levels at degree 3
  // (K_I within about 4e-6), the searches, dozens of solves each, on 10
  // levels at degree 2 (about 1e-4).
  PeriodicGapInput test_size(const bool search = false)
  {
    PeriodicGapInput gap       = default_periodic_gap();
    gap.model.tip_levels       = search ? 10 : 14;
    gap.model.grading_distance = 2;
    gap.model.degree           = search ? 2 : 3;
    return gap;
  }

  PeriodicGapMeasurement solve(const PeriodicGapInput &gap, const double c_over_lambda,
                               const double load_ratio)
  {
    dealii::TimerOutput timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    const double        lambda = gap.model.wavelength;
    const double        p_star = 1e6;
    return solve_periodic_gap(gap.model.with_gap_half_width(c_over_lambda * lambda),
                              {lambda, p_star, load_ratio * p_star}, gap.ring_radii, timer);
  }

  void check_against_closed_form(const PeriodicGapMeasurement &results, const double tolerance)
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

  // The searches' family of models, on the last ring.
  PeriodicGapFamily test_size_family(dealii::TimerOutput &timer)
  {
    const PeriodicGapInput gap = test_size(true);
    return PeriodicGapFamily({gap.model, gap.ring_radii.back()}, timer);
  }

  const double sif_tolerance = 1e-5, search_tolerance = 3e-4;
} // namespace

// The coarse grid is laid from x = 0 for c < lambda/4 and from x = lambda/2
// beyond: both symmetry lines carry the tip zone in turn. K_I of a short gap
// is nearly the isolated crack's, of a long one (short ligament) far above it.
BOOST_AUTO_TEST_CASE(stress_intensity_factor_on_every_ring)
{
  const PeriodicGapInput gap = test_size();
  for (const double c_over_lambda : {0.05, 0.2, 0.3, 0.45})
    check_against_closed_form(solve(gap, c_over_lambda, 0.1), sif_tolerance);
}

// p_bar/p* above cos^2(pi c/lambda): the faces would interpenetrate, K_I < 0.
BOOST_AUTO_TEST_CASE(negative_stress_intensity_factor)
{
  const PeriodicGapMeasurement results = solve(test_size(), 0.4, 0.3);
  BOOST_TEST(results.exact_stress_intensity_factor < 0);
  check_against_closed_form(results, sif_tolerance);
}

// The degree graded down towards the tip (hp, Finite element/Degree grading):
// degree 6 lowered every 8 tip levels, 32 levels, grading distance 1.5, the
// default depth 3 lambda. K_I on every ring within 1e-10 (measured: 4.8e-12),
// with fewer degrees of freedom than degree 6 on every cell.
BOOST_AUTO_TEST_CASE(graded_degree_ten_digits)
{
  PeriodicGapInput gap                = default_periodic_gap();
  gap.model.tip_levels                = 32;
  gap.model.grading_distance          = 1.5;
  gap.model.degree                    = 6;
  gap.model.levels_per_degree         = 8;
  const PeriodicGapMeasurement graded = solve(gap, 0.2, 0.1);
  check_against_closed_form(graded, 1e-10);
  gap.model.levels_per_degree = 0;
  BOOST_TEST(graded.n_dofs < 0.6 * solve(gap, 0.2, 0.1).n_dofs);
}

BOOST_AUTO_TEST_CASE(other_scales)
{
  PeriodicGapInput gap              = test_size();
  gap.model.wavelength              = 2e-6;
  gap.model.depth                   = 1.5 * gap.model.wavelength;
  gap.model.material.youngs_modulus = 3e6;
  gap.model.material.poissons_ratio = 0.45;
  check_against_closed_form(solve(gap, 0.15, -0.5), sif_tolerance);
}

// Boundary ids of the half period: both symmetry lines, the far side, and the
// plane z = 0 split at the tip, which is a vertex.
BOOST_AUTO_TEST_CASE(mesh_and_boundary_ids)
{
  const PeriodicGapInput gap = test_size();
  for (const double c_over_lambda : {0.01, 0.25, 0.49})
    {
      dealii::TimerOutput    timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
      const auto             model = gap.model.with_gap_half_width(c_over_lambda);
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

// The truncation study: K_I of the gap in solids of depth 0.5, 1 and 1.5
// lambda, its error falling tenfold with each step.
BOOST_AUTO_TEST_CASE(depth_study_errors_fall_with_depth)
{
  PeriodicGapInput    gap = test_size();
  std::vector<double> errors;
  for (const double depth : {0.5, 1., 1.5})
    {
      gap.model.depth                      = depth * gap.model.wavelength;
      const PeriodicGapMeasurement results = solve(gap, 0.2, 0);
      errors.push_back(relative_error(results.rings.back().signed_stress_intensity_factor,
                                      results.exact_stress_intensity_factor));
    }
  BOOST_TEST(errors[0] > 10 * errors[1]);
  BOOST_TEST(errors[1] > 10 * errors[2]);
  BOOST_TEST(errors[2] < sif_tolerance);
}

// Westergaard's curve: the FE contact half-width at three loads.
BOOST_AUTO_TEST_CASE(westergaard_curve)
{
  dealii::TimerOutput timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
  PeriodicGapFamily   gaps = test_size_family(timer);
  for (const double load : {0.25, 0.5, 0.75})
    {
      const double a = fe_westergaard_contact_half_width(gaps, load, MPI_COMM_WORLD);
      BOOST_TEST(std::abs(a - periodic_array::westergaard_contact_ratio(load)) < search_tolerance);
      BOOST_TEST(std::abs(periodic_array::johnson_load(a, 0) - load) < search_tolerance);
    }
}

// Johnson's curves: one factorisation, two loads, per contact half-width,
// shared by every alpha.
BOOST_AUTO_TEST_CASE(johnson_curves)
{
  dealii::TimerOutput    timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
  const PeriodicGapInput gap = test_size(); // five solves: the finer size
  PeriodicGapFamily      gaps({gap.model, gap.ring_radii.back()}, timer);
  std::vector<double>    half_widths;
  for (unsigned int i = 1; i <= 5; ++i)
    half_widths.push_back(0.5 - 0.5 * i / 6);
  const auto sifs = gaps.unit_load_sifs(half_widths, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < 5; ++i)
    for (const double alpha : {0., 0.2, 0.4})
      BOOST_TEST(std::abs(fe_johnson_load(sifs[i], 1, alpha) -
                          periodic_array::johnson_load(0.5 * (i + 1) / 6, alpha)) < 2 * sif_tolerance);
  BOOST_TEST(dealii::Utilities::MPI::sum(gaps.n_solves(), MPI_COMM_WORLD) == 10u);
}

BOOST_AUTO_TEST_CASE(critical_alpha_and_jump_into_contact)
{
  dealii::TimerOutput      timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
  PeriodicGapFamily        gaps     = test_size_family(timer);
  const FeCriticalAdhesion critical = fe_critical_alpha(gaps, MPI_COMM_WORLD);
  BOOST_TEST(critical.alpha == periodic_array::critical_alpha, tt::tolerance(search_tolerance));
  BOOST_TEST(critical.contact_half_width == periodic_array::critical_contact_ratio, tt::tolerance(1e-2));
  for (const double alpha : {1e-3, 0.3})
    {
      const FeLoadExtremum fe = fe_jump_into_contact(gaps, alpha, MPI_COMM_WORLD);
      BOOST_TEST(std::abs(fe.load_ratio - periodic_array::jump_into_contact(alpha).load_ratio) <
                 search_tolerance);
    }
}

BOOST_AUTO_TEST_SUITE_END()
