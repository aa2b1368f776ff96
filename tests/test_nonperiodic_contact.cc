// The contact of a patch that is not periodic (contact/nonperiodic_contact.h):
// Love's influence coefficient, the DC-FFT convolution against the direct
// sum, and Hertz's sphere.
#include "contact/nonperiodic_contact.h"

#include <boost/test/unit_test.hpp>

#include <cmath>

BOOST_AUTO_TEST_SUITE(test_nonperiodic_contact)

namespace tt = boost::test_tools;
using namespace penny;

BOOST_AUTO_TEST_CASE(love_influence_and_the_dc_fft_convolution)
{
  // At the centre of a square of side s: 4 s ln(1 + sqrt 2)/(pi E*); far away
  // a point load's 1/(pi E* r) times the area.
  const double s = 0.3, E_star = 2.;
  BOOST_TEST(NonperiodicContact::rectangle_influence(0, 0, s, s, E_star) ==
                 4 * s * std::log(1 + std::sqrt(2.)) / (M_PI * E_star),
             tt::tolerance(1e-14));
  BOOST_TEST(NonperiodicContact::rectangle_influence(300, -400, s, 2 * s, E_star) ==
                 2 * s * s / (M_PI * E_star * 500),
             tt::tolerance(1e-6));

  // The displacement of a few loaded pixels by FFT equals the direct sum
  // over them (the padding removes the periodic images), to rounding.
  const PeriodicGrid patch{7, 5, 3.5, 1.5};
  NonperiodicContact contact(patch, GridField(patch.n_points(), 0.), E_star);
  GridField          pressure(patch.n_points(), 0.);
  pressure[0]                    = 1.;
  pressure[3 * 5 + 2]            = -0.5;
  pressure[patch.n_points() - 1] = 2.;
  const GridField u              = contact.displacement(pressure);
  const double    dx = 0.5, dy = 0.3;
  for (unsigned int i = 0; i < 7; ++i)
    for (unsigned int j = 0; j < 5; ++j)
      {
        double direct = 0;
        for (unsigned int k = 0; k < 7; ++k)
          for (unsigned int l = 0; l < 5; ++l)
            direct += pressure[k * 5 + l] * NonperiodicContact::rectangle_influence(
                                                (double(i) - k) * dx, (double(j) - l) * dy, dx, dy, E_star);
        BOOST_TEST(u[i * 5 + j] == direct, tt::tolerance(1e-12));
      }
}

namespace
{
  // A rigid sphere h = -r^2/(2 R) on an n x n patch of side `side`, the pixel
  // centres at x = (i - (n - 1)/2) dx.
  GridField sphere(const unsigned int n, const double side, const double R)
  {
    const double dx = side / n;
    GridField    h(std::size_t(n) * n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        h[i * n + j] =
            -(std::pow((i - (n - 1) / 2.) * dx, 2) + std::pow((j - (n - 1) / 2.) * dx, 2)) / (2 * R);
    return h;
  }
} // namespace

BOOST_AUTO_TEST_CASE(hertz_sphere)
{
  // On a patch of side 4 a, 129^2 points (32 a point across the contact
  // radius): Hertz's approach delta = a^2/R, hence the contact radius
  // sqrt(delta R), and the central pressure 3 W/(2 pi a^2) within 1e-4
  // (measured 2.3e-5 and 3.6e-5; 8e-5 and 1.6e-4 at 65^2, 4.7e-6 and 1.1e-5 at
  // 257^2); the radius of the contact points' area within 1e-2 (4.5e-3: a
  // pixel's share of the edge, O(dx/a)); the radius where the pressure field's
  // p^2, fitted linear in r^2, vanishes within 1e-3 (measured 6.1e-5).
  const double              R = 1e-2, E_star = 1e7, W = 1e-1;
  const double              a = std::cbrt(3 * W * R / (4 * E_star)), p0 = 3 * W / (2 * M_PI * a * a);
  const unsigned int        n    = 129;
  const double              side = 4 * a;
  const NonperiodicContact  contact({n, n, side, side}, sphere(n, side, R), E_star);
  const NonperiodicSolution solution = contact.solve(W / (side * side), {2000, 1e-10});
  BOOST_TEST(std::sqrt(solution.approach * R) == a, tt::tolerance(1e-4));
  BOOST_TEST(solution.pressure[(n - 1) / 2 * n + (n - 1) / 2] == p0, tt::tolerance(1e-4));
  BOOST_TEST(std::sqrt(solution.contact_fraction * side * side / M_PI) == a, tt::tolerance(1e-2));
  // The contact radius from the pressure field itself: Hertz's p^2 = p0^2 (1 - r^2/a^2)
  // is linear in r^2; its least-squares line over the contact points vanishes at r = a.
  double n_points = 0, sum_x = 0, sum_y = 0, sum_xx = 0, sum_xy = 0;
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      if (const double p = solution.pressure[i * n + j]; p > 0)
        {
          const double r2 =
              (std::pow(i - (n - 1) / 2., 2) + std::pow(j - (n - 1) / 2., 2)) * std::pow(side / n, 2);
          n_points += 1, sum_x += r2, sum_y += p * p, sum_xx += r2 * r2, sum_xy += r2 * p * p;
        }
  const double slope     = (n_points * sum_xy - sum_x * sum_y) / (n_points * sum_xx - sum_x * sum_x),
               intercept = (sum_y - slope * sum_x) / n_points;
  BOOST_TEST_MESSAGE("contact radius from p^2: " << std::sqrt(-intercept / slope) / a - 1);
  BOOST_TEST(std::sqrt(-intercept / slope) == a, tt::tolerance(1e-3));
  for (std::size_t k = 0; k < solution.pressure.size(); ++k)
    BOOST_TEST((solution.pressure[k] > 0) == (solution.separation[k] == 0));
}

BOOST_AUTO_TEST_CASE(the_periodic_solver_agrees_where_the_images_are_far)
{
  // The same sphere on a periodic cell of side 8 a (the periodic solver,
  // HalfSpaceContact) and on the patch of that side: the images of a
  // periodic array move the contact by O((a/L)^3); the central pressures
  // agree within 1e-2 (measured 2.2e-3) and the contact points within 1 %
  // (the same 829).
  const double              R = 1e-2, E_star = 1e7, W = 1e-1;
  const double              a = std::cbrt(3 * W * R / (4 * E_star)), side = 8 * a;
  const unsigned int        n = 129;
  const GridField           h = sphere(n, side, R);
  const PeriodicGrid        grid{n, n, side, side};
  const NonperiodicSolution isolated =
      NonperiodicContact(grid, h, E_star).solve(W / (side * side), {2000, 1e-10});
  const FourierTransform transform(grid);
  const ContactSolution  periodic =
      HalfSpaceContact(transform, h, E_star).solve(W / (side * side), {2000, 1e-10});
  const std::size_t centre = (n - 1) / 2 * n + (n - 1) / 2;
  BOOST_TEST(periodic.pressure[centre] == isolated.pressure[centre], tt::tolerance(1e-2));
  BOOST_TEST(periodic.contact_fraction == isolated.contact_fraction, tt::tolerance(0.01));
  BOOST_TEST_MESSAGE("central pressure periodic/isolated - 1 = "
                     << periodic.pressure[centre] / isolated.pressure[centre] - 1 << ", contact points "
                     << periodic.contact_fraction * n * n << " and " << isolated.contact_fraction * n * n);
}

BOOST_AUTO_TEST_SUITE_END()
