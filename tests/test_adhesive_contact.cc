// The contact solver with adhesion: equilibrium checked pointwise against an
// independent evaluation of the traction, prescribed mean gap against
// prescribed mean pressure, hysteresis and jumps along loading and unloading
// paths, the shape measures, Richardson extrapolation, and bad input.
#include "contact/contact_geometry.h"
#include "contact/contact_path.h"
#include "contact/extrapolation.h"
#include "contact/half_space_contact.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <string>

BOOST_AUTO_TEST_SUITE(test_adhesive_contact)

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  // Johnson's sinusoid in units E* = lambda = p* = 1 (h = 2 h0 sin^2(pi x),
  // h0 = 1/pi) on an n x 1 grid, alpha = 0.2 (w = alpha^2/2), cohesive zone
  // l_pz = 4e-3 (16 points at n = 4096).
  const unsigned int n      = 4096;
  const double       alpha  = 0.2;
  const Adhesion     sticky = {alpha * alpha / 2, alpha *std::sqrt(M_PI * 4e-3 / 2)};

  GridField sinusoid(const PeriodicGrid &grid)
  {
    GridField h(grid.n_points());
    for (unsigned int i = 0; i < grid.nx; ++i)
      h[i] = 2 / M_PI * std::pow(std::sin(M_PI * i / grid.nx), 2);
    return h;
  }

  bool says(const std::exception &e, const std::string &text)
  {
    return std::string(e.what()).find(text) != std::string::npos;
  }

  // The largest violation of equilibrium, in units of the adhesive strength
  // w/rho: the elastic traction p_el = p_bar + K (g + h), evaluated here
  // independently of the solver, must equal the attraction -phi'(g) in the
  // gaps and the reported pressure on the contact points, whose wall
  // reaction p + phi'(0) must not be negative.
  double equilibrium_violation(const HalfSpaceContact &contact, const ContactSolution &solution)
  {
    const FourierTransform &transform = contact.transform();
    const double            E_star    = contact.plane_strain_modulus();
    const Adhesion         &adhesion  = contact.adhesion();
    const auto              stiffness =
        transform.tabulate([=](const Wavevector &q) { return std::complex<double>(E_star / 2 * q.norm()); });
    GridField displacement(solution.gap), traction;
    for (std::size_t i = 0; i < displacement.size(); ++i)
      displacement[i] += contact.heights()[i];
    transform.apply(stiffness, displacement, traction);
    double worst = 0;
    for (std::size_t i = 0; i < traction.size(); ++i)
      {
        const double p = solution.mean_pressure + traction[i], attraction = adhesion.slope(solution.gap[i]);
        if (solution.gap[i] > 0)
          worst = std::max(worst, std::abs(p + attraction));
        else
          worst = std::max({worst, std::abs(p - solution.pressure[i]), -(solution.pressure[i] + attraction)});
      }
    return worst / adhesion.strength();
  }
} // namespace

BOOST_AUTO_TEST_CASE(equilibrium_on_the_sinusoid_and_a_random_surface)
{
  // Within 1e-6 of the strength w/rho (measured: 1.1e-8 on the sinusoid,
  // 2.9e-8 on the random surface), each started from the adhesionless contact
  // at the same load; adhesion pulls more of the surface into contact
  // (measured on the random surface: 0.74 of the points without, 0.88 with).
  {
    const FourierTransform transform(PeriodicGrid{n, 1, 1., 1. / n});
    const HalfSpaceContact plain(transform, sinusoid(transform.grid()), 1.);
    const HalfSpaceContact contact(transform, sinusoid(transform.grid()), 1., sticky);
    const ContactSolution  start    = plain.solve(0.2, {1000, 1e-11});
    const ContactSolution  solution = contact.solve(0.2, {10000, 1e-11}, start.gap);
    BOOST_TEST(solution.residual <= 1e-11);
    BOOST_TEST(equilibrium_violation(contact, solution) <= 1e-6);
    BOOST_TEST(solution.contact_fraction > start.contact_fraction);
  }
  {
    const double           lambda = 1e-3, E_star = 1e7;
    const PowerSpectrum    spectrum = power_law_spectrum(0.75, 2 * M_PI / lambda, 8, 1e-5);
    const PeriodicGrid     grid     = square_grid(128, lambda);
    const FourierTransform transform(grid);
    const GridField        h = gaussian_field(transform, spectrum, 11);
    const double sqrt_V = std::sqrt(lattice_moments(grid, pressure_spectrum(spectrum, E_star)).expected.m0);
    // w and rho with a cohesive zone of 6 grid spacings and a strength of sqrt(V)/2.
    const double strength = 0.5 * sqrt_V, zone = 6 * lambda / 128,
                 w = zone * M_PI * strength * strength / E_star;
    const HalfSpaceContact plain(transform, h, E_star);
    const HalfSpaceContact contact(transform, h, E_star, {w, w / strength});
    const ContactSolution  start    = plain.solve(sqrt_V, {1000, 1e-10});
    const ContactSolution  solution = contact.solve(sqrt_V, {10000, 1e-10}, start.gap);
    BOOST_TEST(equilibrium_violation(contact, solution) <= 1e-6);
    BOOST_TEST(solution.contact_fraction > start.contact_fraction);
  }
}

BOOST_AUTO_TEST_CASE(prescribed_mean_gap_and_mean_pressure_agree)
{
  // The load found at a prescribed mean gap, prescribed in turn, gives back
  // that mean gap (to 1e-7, measured 5e-11) and the same contact.
  const FourierTransform transform(PeriodicGrid{n, 1, 1., 1. / n});
  const HalfSpaceContact plain(transform, sinusoid(transform.grid()), 1.);
  const HalfSpaceContact contact(transform, sinusoid(transform.grid()), 1., sticky);
  const ContactSolution  start   = plain.solve(0.3, {1000, 1e-11});
  const ContactSolution  at_gap  = contact.solve_at_mean_gap(0.8 * start.mean_gap, {10000, 1e-11}, start.gap);
  const ContactSolution  at_load = contact.solve(at_gap.mean_pressure, {10000, 1e-11}, start.gap);
  BOOST_TEST(at_load.mean_gap == at_gap.mean_gap, tt::tolerance(1e-7));
  BOOST_TEST(at_load.contact_fraction == at_gap.contact_fraction);
  BOOST_TEST(at_gap.mean_gap == 0.8 * start.mean_gap, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(nested_start_and_a_bad_initial_gap)
{
  // 16 points per zone: the halved grids of 8 and 4 points per zone start
  // each solve from a given gap (coarse iterations counted), and a start
  // that does not fit the grid, or is negative or NaN, is refused by name
  // before it is restricted to them.
  const FourierTransform     transform(PeriodicGrid{n, 1, 1., 1. / n});
  const HalfSpaceContact     plain(transform, sinusoid(transform.grid()), 1.);
  const HalfSpaceContact     contact(transform, sinusoid(transform.grid()), 1., sticky);
  const ContactSolverControl control{10000, 1e-10};
  const ContactSolution      start = plain.solve(0.3, control);
  BOOST_TEST(contact.solve_at_mean_gap(start.mean_gap, control, start.gap).coarse_iterations > 0);
  BOOST_TEST(contact.solve(0.3, control, start.gap).coarse_iterations > 0);
  for (const int fault : {0, 1, 2})
    {
      GridField gap = start.gap;
      if (fault == 0)
        gap.resize(17);
      else
        gap[5] = fault == 1 ? std::numeric_limits<double>::quiet_NaN() : -1;
      const auto refused = [](const std::invalid_argument &e) { return says(e, "the initial gap"); };
      BOOST_CHECK_EXCEPTION(contact.solve_at_mean_gap(start.mean_gap, control, gap), std::invalid_argument,
                            refused);
      BOOST_CHECK_EXCEPTION(contact.solve(0.3, control, gap), std::invalid_argument, refused);
    }
}

BOOST_AUTO_TEST_CASE(hysteresis_and_jumps_along_paths)
{
  // Loading: the gap shrinks, then snaps shut past the largest load of the
  // curve (Johnson: p_bar/p* = 0.5537 at alpha = 0.2; less at this range). Unloading from full
  // contact: adhesion holds it while the tension p* - p_bar stays below the
  // strength w/rho = 1.26 p*, a different state at the same load; at
  // p_bar = -0.3 p* the surfaces separate (Johnson's pull-off: -0.056 p*).
  const FourierTransform     transform(PeriodicGrid{n, 1, 1., 1. / n});
  const HalfSpaceContact     plain(transform, sinusoid(transform.grid()), 1.);
  const HalfSpaceContact     contact(transform, sinusoid(transform.grid()), 1., sticky);
  const ContactSolverControl control{20000, 1e-10};
  ContactPath                loading(contact, "loading", control, plain.solve(0.3, control).gap);
  const double               gap_at_0_3 = loading.to_mean_pressure(0.3).mean_gap;
  loading.to_mean_pressure(0.5);
  loading.to_mean_pressure(0.6);
  const std::vector<PathStep> &up = loading.steps();
  BOOST_TEST(up.size() == 3u);
  BOOST_TEST(up[0].path == "loading");
  BOOST_TEST(up[2].step == 2u);
  BOOST_TEST(!up[1].jumped);
  BOOST_TEST(up[1].topology.gaps == 1u);
  BOOST_TEST(up[2].jumped);
  BOOST_TEST(up[2].topology.gaps == 0u);
  BOOST_TEST(up[2].contact_fraction == 1.0);

  ContactPath unloading(contact, "unloading", control, loading.current().gap);
  BOOST_TEST(unloading.to_mean_pressure(0.3).contact_fraction == 1.0);
  BOOST_TEST(gap_at_0_3 > 0);
  BOOST_TEST(unloading.to_mean_pressure(-0.2).contact_fraction == 1.0);
  BOOST_TEST(!unloading.steps().back().jumped);
  BOOST_CHECK_EXCEPTION(unloading.to_mean_pressure(-0.3), std::runtime_error,
                        [](const std::runtime_error &e) { return says(e, "the surfaces separate"); });
}

BOOST_AUTO_TEST_CASE(full_contact_is_never_nan)
{
  // A load that closes every gap: full contact, no iteration, finite numbers.
  const FourierTransform transform(PeriodicGrid{n, 1, 1., 1. / n});
  for (const Adhesion &adhesion : {Adhesion{}, sticky})
    {
      const HalfSpaceContact contact(transform, sinusoid(transform.grid()), 1., adhesion);
      const ContactSolution  solution = contact.solve(1e6, {10, 1e-10});
      BOOST_TEST(solution.contact_fraction == 1.0);
      BOOST_TEST(solution.iterations == 0u);
      BOOST_TEST(solution.mean_gap == 0.0);
      BOOST_TEST(solution.residual == 0.0);
      BOOST_TEST(std::isfinite(solution.energy));
      BOOST_TEST(contact_topology(transform.grid(), solution.gap).gaps == 0u);
    }
}

BOOST_AUTO_TEST_CASE(topology_and_equivalent_radius)
{
  // Two round gaps of radius 10 and 6 cells on a 64 x 64 grid, one across the
  // periodic boundary: one contact region, two gaps. The level set of the
  // paraboloid r^2 at 10^2 has radius 10 less at most 0.025 cells: bilinear
  // interpolation overestimates r^2 by at most half a cell squared, and
  // 0.5/(2 r) = 0.025 (measured: 0.016).
  const PeriodicGrid grid = square_grid(64, 64.);
  GridField          gaps(grid.n_points(), 0.), paraboloid(grid.n_points());
  for (unsigned int i = 0; i < 64; ++i)
    for (unsigned int j = 0; j < 64; ++j)
      {
        const double r1        = std::hypot(double(i) - 32, double(j) - 32);
        const double r2        = std::hypot(std::min<double>(i, 64 - i), double(j) - 20);
        gaps[i * 64 + j]       = r1 < 10 || r2 < 6 ? 1 : 0;
        paraboloid[i * 64 + j] = r1 * r1;
      }
  const ContactTopology topology = contact_topology(grid, gaps);
  BOOST_TEST(topology.contacts == 1u);
  BOOST_TEST(topology.gaps == 2u);
  const double radius = level_radius(grid, paraboloid, 100., 32, 32);
  BOOST_TEST(radius <= 10.);
  BOOST_TEST(radius >= 10. - 0.025);
  BOOST_CHECK_THROW(level_radius(grid, paraboloid, 1e6, 32, 32), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(extrapolation_is_exact_for_its_expansion)
{
  // A(h) = 1 + 2 h + 3 h^1.5 + 4 h^2 at h = 1, 1/2, 1/4, 1/8: the three
  // exponents give 1 to rounding; the error estimate is the change from two
  // exponents. In two parameters, A(l, h) = A(l) + 5 h^2.
  const std::vector<double> h = {1, 0.5, 0.25, 0.125};
  std::vector<double>       values;
  for (const double x : h)
    values.push_back(1 + 2 * x + 3 * std::pow(x, 1.5) + 4 * x * x);
  const Extrapolated limit = extrapolate(h, values, {1, 1.5, 2});
  BOOST_TEST(limit.value == 1., tt::tolerance(1e-12));
  const Extrapolated rough = extrapolate(h, values, {1, 1.5});
  BOOST_TEST(limit.error == std::abs(1 - rough.value), tt::tolerance(1e-9));
  BOOST_TEST(extrapolate(h, values, {1, 1.5, 2}, {1e-3, 1e-3, 1e-3, 1e-3}).error > limit.error);

  std::vector<std::vector<double>> table;
  for (const double l : h)
    table.push_back({1 + 2 * l + 3 * std::pow(l, 1.5) + 4 * l * l + 5 * 0.25,
                     1 + 2 * l + 3 * std::pow(l, 1.5) + 4 * l * l + 5 * 0.0625});
  BOOST_TEST(extrapolate_in_both(h, {0.5, 0.25}, table, {1, 1.5, 2}, {2}).value == 1., tt::tolerance(1e-12));
  BOOST_TEST(observed_order(values[0] - 1, values[1] - 1, 0, 2) > 0);
  BOOST_TEST(observed_order(1, 0.25, 0.0625, 2) == 2., tt::tolerance(1e-12));
  BOOST_CHECK_THROW(extrapolate({1, 0.5}, {1, 2}, {1, 2}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused_in_one_line)
{
  const FourierTransform transform(PeriodicGrid{n, 1, 1., 1. / n});
  const GridField        h   = sinusoid(transform.grid());
  const double           inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  for (const double w : {-1., nan, inf})
    BOOST_CHECK_EXCEPTION(HalfSpaceContact(transform, h, 1., {w, 0.01}), std::invalid_argument,
                          [](const std::invalid_argument &e) { return says(e, "work of adhesion w = "); });
  for (const double range : {0., -1., nan, inf})
    BOOST_CHECK_EXCEPTION(HalfSpaceContact(transform, h, 1., {0.02, range}), std::invalid_argument,
                          [](const std::invalid_argument &e) { return says(e, "adhesive range rho = "); });
  // A cohesive zone of 1 grid spacing: refused, saying how many it spans and needs.
  const double zone = 1. / n, w = 0.02;
  BOOST_CHECK_EXCEPTION(HalfSpaceContact(transform, h, 1., {w, std::sqrt(M_PI * w * zone)}),
                        std::invalid_argument, [](const std::invalid_argument &e) {
                          return says(e, "spans 1 grid spacings; at least 4 are needed") &&
                                 std::string(e.what()).find('\n') == std::string::npos;
                        });
  const HalfSpaceContact contact(transform, h, 1., sticky);
  BOOST_CHECK_THROW(load_sweep(contact, {0.1, 0.2}, {100, 1e-10}), std::invalid_argument);
  BOOST_CHECK_EXCEPTION(
      contact.solve(0.2, {3, 1e-12}, HalfSpaceContact(transform, h, 1.).solve(0.2, {1000, 1e-10}).gap),
      std::runtime_error,
      [](const std::runtime_error &e) { return says(e, "no convergence in 3 iterations (residual "); });
  BOOST_CHECK_THROW(contact.solve(inf, {100, 1e-10}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
