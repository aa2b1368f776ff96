// The adhesive solver against problems with exact answers, small enough for
// a test (the scenes bem-johnson, jkr-sphere and bem-bisinusoid run them at full size): Johnson's
// sinusoid extrapolated to the JKR limit, the JKR sphere's pull-off moving
// towards -(3/2) pi w R as the range shrinks, and the bi-sinusoid near full
// contact against its isolated-gap limits.
#include "closed_forms/periodic_array.h"
#include "contact/adhesive_bisinusoid.h"
#include "contact/adhesive_sinusoid.h"
#include "contact/adhesive_sphere.h"
#include "contact/extrapolation.h"
#include "contact/half_space.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

BOOST_AUTO_TEST_SUITE(test_contact_verification)

namespace tt = boost::test_tools;
using namespace penny;

BOOST_AUTO_TEST_CASE(johnson_sinusoid_in_the_jkr_limit)
{
  // alpha = 0.2; l_pz/lambda = 4e-3 ... 5e-4, 16 points per zone (the full
  // run goes to 1.25e-4 and extrapolates in the grid too). Richardson in l_pz
  // (exponents 1, 3/2, 2 for p_bar(a), 2, 5/2, 3 for the jump's maximum, as
  // observed) lands within 1e-4 p* of Johnson's curve at a/lambda = 0.1, 0.2,
  // 0.3 and within its own error estimate plus 2e-5 (measured: at most
  // 4.4e-5, estimates 4e-5 to 9e-5), and within 1e-5 p* of the curve's
  // maximum (measured: 1.4e-6).
  const double                     alpha = 0.2;
  const std::vector<double>        zones = {4e-3, 2e-3, 1e-3, 5e-4}, ratios = {0.1, 0.2, 0.3};
  const ContactSolverControl       control{100000, 1e-11};
  std::vector<std::vector<double>> loads(ratios.size() + 1);
  for (const double zone : zones)
    {
      const adhesive_sinusoid::Model model({alpha, zone, static_cast<unsigned int>(std::lround(16 / zone))});
      const auto                     curve = model.loads_at_half_widths(ratios, control);
      for (std::size_t k = 0; k < ratios.size(); ++k)
        {
          BOOST_TEST(curve[k].contact_ratio == ratios[k], tt::tolerance(1e-8));
          loads[k].push_back(curve[k].load_ratio);
        }
      loads.back().push_back(model.jump_into_contact(control, curve).load_ratio);
    }
  for (std::size_t k = 0; k < ratios.size(); ++k)
    {
      const Extrapolated limit = extrapolate(zones, loads[k], {1, 1.5, 2});
      const double       exact = periodic_array::johnson_load(ratios[k], alpha);
      BOOST_TEST(std::abs(limit.value - exact) <= 1e-4);
      BOOST_TEST(std::abs(limit.value - exact) <= limit.error + 2e-5);
    }
  const Extrapolated jump = extrapolate(zones, loads.back(), {2, 2.5, 3});
  BOOST_TEST(std::abs(jump.value - periodic_array::jump_into_contact(alpha).load_ratio) <= 1e-5);
}

BOOST_AUTO_TEST_CASE(jkr_sphere_pull_off_approaches_jkr)
{
  // l_pz/a_pull-off = 0.4 and 0.2, 6.4 points per zone, period 8 a_pull-off:
  // the pull-off load exceeds JKR's -(3/2) pi w R in magnitude (the cohesive
  // zone adds attraction outside the contact) by less as the zone shrinks
  // (measured: 16 % and 11 %), and along the unloading path the load falls
  // with the contact radius.
  const ContactSolverControl control{100000, 1e-9};
  std::vector<double>        excess;
  for (const double zone : {0.4, 0.2})
    {
      const adhesive_sphere::Model model({zone, 8, static_cast<unsigned int>(std::lround(8 * 6.4 / zone))});
      const adhesive_sphere::State state = model.pull_off(control);
      excess.push_back(state.load / adhesive_sphere::pull_off_load - 1);
    }
  BOOST_TEST(excess[0] > excess[1]);
  BOOST_TEST(excess[1] > 0);
  BOOST_TEST(excess[1] < 0.13);
  const auto path = adhesive_sphere::Model({0.4, 8, 128}).unloading(control, 4, 0.1);
  for (std::size_t k = 1; k < path.size(); ++k)
    {
      BOOST_TEST(path[k].load < path[k - 1].load);
      BOOST_TEST(path[k].contact_radius < path[k - 1].contact_radius);
    }
}

BOOST_AUTO_TEST_CASE(bisinusoid_full_contact_pressure)
{
  // h = Delta cos(kx) cos(ky) needs p_fc = p* cos(kx) cos(ky) (heights
  // towards the half-space) with p* = sqrt(2) pi E* Delta/lambda: the mode
  // has |q| = sqrt(2) k. Checked on a lambda x lambda grid, E* = 2, Delta = 3,
  // lambda = 5, to rounding.
  const double           E_star = 2, Delta = 3, lambda = 5, k = 2 * M_PI / lambda;
  const unsigned int     n = 32;
  const FourierTransform transform(square_grid(n, lambda));
  GridField              h(transform.grid().n_points());
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      h[i * n + j] = Delta * std::cos(k * i * lambda / n) * std::cos(k * j * lambda / n);
  const GridField p      = full_contact_pressure(transform, h, E_star);
  const double    p_star = std::sqrt(2.) * M_PI * E_star * Delta / lambda;
  double          error  = 0;
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      error = std::max(error, std::abs(p[i * n + j] -
                                       p_star * std::cos(k * i * lambda / n) * std::cos(k * j * lambda / n)));
  BOOST_TEST(error <= 1e-12 * p_star);
}

BOOST_AUTO_TEST_CASE(bisinusoid_near_full_contact)
{
  // Without adhesion, 256 points per cell: A_nc/A_0 within 3 % of
  // (3/(2 pi))(1 - p_bar/p*) at p_bar/p* = 0.95 (measured: 1 %). With adhesion
  // (alpha = 0.1, l_pz = c_min/4 and c_min/8, 6 points per zone) the gap
  // snaps shut on loading within 15 % of the isolated-gap load margin and
  // nearer to it as the zone shrinks; before, its radius is near the penny
  // gap's of its summit (within 15 %).
  const ContactSolverControl control{100000, 1e-9};
  const auto                 states = adhesive_bisinusoid::Model({0, 0, 256}).loading({0.9, 0.95}, control);
  BOOST_TEST(states[1].noncontact_fraction / adhesive_bisinusoid::isolated_noncontact_fraction(0.95) == 1.,
             tt::tolerance(0.03));
  BOOST_TEST(states[0].noncontact_fraction > states[1].noncontact_fraction);

  const double        alpha = 0.1, c_min = 0.19519 * std::pow(alpha, 0.4);
  const double        isolated = adhesive_bisinusoid::isolated_closure_margin(alpha);
  std::vector<double> ratios;
  for (const double fraction : {0.125, 0.0625})
    {
      const double       zone   = fraction * c_min;
      const unsigned int n      = 32 * static_cast<unsigned int>(std::ceil(6 / zone / std::sqrt(2.) / 32));
      const double       load   = 1 - 1.5 * isolated;
      const auto         states = adhesive_bisinusoid::Model({alpha, zone, n}).loading({load}, control, true);
      ratios.push_back((1 - states.back().load_ratio) / isolated);
      if (fraction == 0.125)
        {
          BOOST_TEST_REQUIRE(states.front().gap_radius.has_value());
          BOOST_TEST(
              *states.front().gap_radius / *adhesive_bisinusoid::isolated_gap_radius(1 - load, alpha) == 1.,
              tt::tolerance(0.15));
        }
    }
  BOOST_TEST(std::abs(ratios[1] - 1) < std::abs(ratios[0] - 1));
  BOOST_TEST(std::abs(ratios[1] - 1) < 0.15);
  BOOST_TEST(!adhesive_bisinusoid::isolated_gap_radius(0.5 * isolated, alpha).has_value());
}

BOOST_AUTO_TEST_SUITE_END()
