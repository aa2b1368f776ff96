// The paper's constants recovered from FE solves on test-sized meshes: the
// adhesionless root c/a = sqrt(3/2), the adhesive minimum (psi, c_min) and the
// stable-branch equilibrium radius, plus the closed forms they are checked by.
#include "closed_forms/adhesive_gap.h"
#include "numerics/root_finding.h"
#include "searches/gap_searches.h"
#include "test_support.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(test_adhesion)

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  // Test size: 16 tip levels; the searches use the ring of radius 0.75 c.
  PennyGapFamily test_size(dealii::TimerOutput &timer, const unsigned int degree = 3)
  {
    return PennyGapFamily({test_size_model(16, degree), 0.75}, timer);
  }

  const double R_p  = 7.8125e-7;
  const double K_Ic = 1.28e6;
} // namespace

BOOST_AUTO_TEST_CASE(closed_form_constants)
{
  // The root of the difference quotient of P(c) reproduces psi and c_min;
  // the quotients at the ends come in one batch of four, every other in a pair.
  const double        scale = adhesion_length(R_p, K_Ic);
  std::vector<size_t> batches;
  const auto          tensions = [&](const std::vector<double> &radii) {
    batches.push_back(radii.size());
    std::vector<double> P;
    for (const double c : radii)
      P.push_back(closed_form::adhesive_tension(c, R_p, K_Ic));
    return P;
  };
  const double c_min = fe_stationary_point(tensions, 0.25 * scale, 4 * scale, Extremum::minimum, "test", "");
  BOOST_TEST(c_min / scale == closed_form::c_min_factor, tt::tolerance(1e-8));
  BOOST_TEST(closed_form::adhesive_tension(c_min, R_p, K_Ic) / adhesion_tension(R_p, K_Ic) ==
                 closed_form::psi,
             tt::tolerance(1e-14));
  BOOST_TEST(batches.size() < 20u);
  BOOST_TEST(batches.front() == 4u);
  for (std::size_t i = 1; i < batches.size(); ++i)
    BOOST_TEST(batches[i] == 2u);

  // A maximum, and an interval without an interior extremum.
  const auto sines = [](const std::vector<double> &x) {
    std::vector<double> f;
    for (const double xi : x)
      f.push_back(std::sin(xi));
    return f;
  };
  BOOST_TEST(fe_stationary_point(sines, 1, 2, Extremum::maximum, "test", "") == M_PI / 2,
             tt::tolerance(1e-8));
  BOOST_CHECK_EXCEPTION(
      fe_stationary_point(sines, 0.5, 1.5, Extremum::maximum, "sine", "widen it"), std::runtime_error,
      [](const std::runtime_error &error) {
        return std::string(error.what()) ==
               "sine: the maximum lies at an end of the search interval [0.5, 1.5]; widen it";
      });
  BOOST_CHECK_THROW(fe_stationary_point(sines, 1, 2, Extremum::minimum, "sine", ""), std::runtime_error);

  const double c_t = *closed_form::stable_gap_radius(2e6, R_p, K_Ic);
  BOOST_TEST(closed_form::adhesive_tension(c_t, R_p, K_Ic) == 2e6, tt::tolerance(1e-12));
  BOOST_TEST(c_t > c_min);
  BOOST_TEST(!closed_form::stable_gap_radius(0.99 * closed_form::psi * adhesion_tension(R_p, K_Ic), R_p, K_Ic)
                  .has_value());
}

BOOST_AUTO_TEST_CASE(adhesionless_root)
{
  dealii::TimerOutput timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
  PennyGapFamily      gaps = test_size(timer);
  const double        a    = 0.6;
  BOOST_TEST(fe_adhesionless_gap_radius(gaps, 1e6, a, MPI_COMM_WORLD) / a ==
                 closed_form::adhesionless_c_over_a,
             tt::tolerance(1e-4));
}

BOOST_AUTO_TEST_CASE(adhesive_minimum_and_equilibrium)
{
  dealii::TimerOutput   timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
  PennyGapFamily        gaps    = test_size(timer);
  const AdhesiveMinimum minimum = fe_adhesive_minimum(gaps, R_p, K_Ic, MPI_COMM_WORLD);
  BOOST_TEST(minimum.tension / adhesion_tension(R_p, K_Ic) == closed_form::psi, tt::tolerance(1e-4));
  BOOST_TEST(minimum.gap_radius / adhesion_length(R_p, K_Ic) == closed_form::c_min_factor,
             tt::tolerance(1e-4));
  // On this rank alone the pairs of models are solved in turn: the same minimum to the last bit.
  const AdhesiveMinimum alone = fe_adhesive_minimum(gaps, R_p, K_Ic, MPI_COMM_SELF);
  BOOST_TEST(alone.gap_radius == minimum.gap_radius);
  BOOST_TEST(alone.tension == minimum.tension);

  const double P = 1.3 * minimum.tension;
  BOOST_TEST(*fe_stable_gap_radius(gaps, P, R_p, K_Ic, minimum, MPI_COMM_WORLD) ==
                 *closed_form::stable_gap_radius(P, R_p, K_Ic),
             tt::tolerance(1e-4));
  BOOST_TEST(
      !fe_stable_gap_radius(gaps, 0.999 * minimum.tension, R_p, K_Ic, minimum, MPI_COMM_WORLD).has_value());
}

// psi is a pure number: R_p and K_Ic over six orders of magnitude each give
// the same FE value, because each search builds meshes similar to one another.
BOOST_AUTO_TEST_CASE(psi_independent_of_scales)
{
  dealii::TimerOutput timer(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
  PennyGapFamily      gaps = test_size(timer, 2);
  const auto          psi  = [&](const double r_p, const double k_ic) {
    return fe_adhesive_minimum(gaps, r_p, k_ic, MPI_COMM_WORLD).tension / adhesion_tension(r_p, k_ic);
  };
  const double reference = psi(R_p, K_Ic);
  for (const double r_p : {1e-9, 1e-3})
    for (const double k_ic : {1e3, 1e9})
      BOOST_TEST(psi(r_p, k_ic) == reference, tt::tolerance(1e-8));
}

BOOST_AUTO_TEST_SUITE_END()
