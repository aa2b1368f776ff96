// Summits of fields on a periodic grid: detection and refinement on a field
// with known summits, the Kac-Rice expectations against Nayak's closed forms,
// quadrature and Monte Carlo, the ensemble arithmetic, and the summits of
// sampled Gaussian fields against their expectation.
#include "contact/half_space.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"
#include "statistics/summit_statistics.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>

BOOST_AUTO_TEST_SUITE(test_summit_statistics)

namespace tt = boost::test_tools;
using namespace penny;

BOOST_AUTO_TEST_CASE(summits_of_a_cosine_lattice)
{
  // f = cos(a (x - x0)) + c cos(b (y - y0)), a = 4 pi, b = 6 pi, c = 1/2 on the
  // unit square: 2 x 3 summits of height 1 + c at (x0 + m/2, y0 + n/3), principal
  // curvatures a^2 and c b^2. The offsets put them between grid points (up to
  // half a cell r = dx/2 away); the Taylor model's errors are then at most
  // (b r)^2/2 = 2.7e-3 (curvature), (b r)^4/24 = 1.2e-6 (height) and
  // r (b r)^2/6 = 5e-4 dx (position), relative.
  const unsigned int     n  = 128;
  const double           dx = 1. / n, x0 = 0.3 * dx, y0 = 0.45 * dx, a = 4 * M_PI, b = 6 * M_PI, c = 0.5;
  const FourierTransform transform(square_grid(n, 1));
  GridField              f(n * n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      f[i * n + j] = std::cos(a * (i * dx - x0)) + c * std::cos(b * (j * dx - y0));

  std::vector<Summit> summits = find_summits(transform, f);
  BOOST_TEST_REQUIRE(summits.size() == 6u);
  std::sort(summits.begin(), summits.end(), [&](const Summit &s, const Summit &t) {
    return std::make_pair(std::round(s.x / dx), s.y) < std::make_pair(std::round(t.x / dx), t.y);
  });
  for (unsigned int k = 0; k < 6; ++k)
    {
      const Summit &s = summits[k];
      BOOST_TEST(std::abs(s.x - (x0 + (k / 3) * 0.5)) < 1e-3 * dx);
      BOOST_TEST(std::abs(s.y - (y0 + (k % 3) / 3.)) < 1e-3 * dx);
      BOOST_TEST(s.height == 1 + c, tt::tolerance(2e-6));
      BOOST_TEST(s.curvature_min == a * a, tt::tolerance(3e-3));
      BOOST_TEST(s.curvature_max == c * b * b, tt::tolerance(3e-3));
    }
}

BOOST_AUTO_TEST_CASE(isotropic_expectation_is_nayak)
{
  // m22 = m4/3: Nayak's density m4/(6 pi sqrt(3) m2) and mean curvature
  // (8/3) sqrt(m4/pi), which pressure_summits() (consistent) turns into eta and R_p.
  const SpectralMoments heights = spectral_moments(power_law_spectrum(0.6, 2e3, 50, 1e-6));
  const double          E_star  = 2e6;
  const SpectralMoments p =
      spectral_moments(pressure_spectrum(power_law_spectrum(0.6, 2e3, 50, 1e-6), E_star));
  const FieldMoments    moments  = isotropic_moments(p.m0, p.m2, p.m4);
  const ExpectedSummits expected = expected_summits(moments);
  BOOST_TEST(expected.density == p.m4 / (6 * M_PI * std::sqrt(3.) * p.m2), tt::tolerance(1e-12));
  BOOST_TEST(expected.mean_curvature == 8. / 3 * std::sqrt(p.m4 / M_PI), tt::tolerance(1e-12));
  const PressureSummits consistent = pressure_summits(heights, E_star, Convention::consistent);
  BOOST_TEST(consistent.variance == moments.m0, tt::tolerance(1e-12));
  BOOST_TEST(consistent.density == expected.density, tt::tolerance(1e-12));
  BOOST_TEST(1 / consistent.summit_radius == expected.mean_curvature, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(height_resolved_expectation_integrates_to_the_totals)
{
  // Isotropic and square-symmetric (m22 != m4/3) moments: int n(z) dz is the
  // density and int n(z) kappa(z) dz / density the mean curvature.
  using boost::math::quadrature::gauss_kronrod;
  for (const double twist : {1. / 3, 0.3, 0.36})
    {
      const FieldMoments    m{2.0, 1.5, 4.0, 4.0 * twist};
      const ExpectedSummits expected = expected_summits(m);
      const double          limit    = 12 * std::sqrt(m.m0);
      const double          density  = gauss_kronrod<double, 61>::integrate(
          [&](double z) { return summit_height_density(m, z); }, -limit, limit, 10, 1e-13);
      const double curvature = gauss_kronrod<double, 61>::integrate(
          [&](double z) { return summit_height_density(m, z) * summit_mean_curvature_at(m, z); }, -limit,
          limit, 10, 1e-13);
      BOOST_TEST(density == expected.density, tt::tolerance(1e-9));
      BOOST_TEST(curvature / density == expected.mean_curvature, tt::tolerance(1e-9));
    }
}

BOOST_AUTO_TEST_CASE(square_symmetric_expectation_against_monte_carlo)
{
  // E[det(-H) 1{-H > 0}]/(2 pi m2) and the mean of -tr(H)/2 over summits by
  // sampling the Hessian (f_xx, f_yy, f_xy) from its covariance
  // [[m4, m22, 0], [m22, m4, 0], [0, 0, m22]] (m22 = 0.27 m4, not m4/3):
  // within 4 standard errors.
  const FieldMoments               m{1.0, 1.0, 3.0, 0.8};
  std::mt19937_64                  generator(2024);
  std::normal_distribution<double> normal;
  const unsigned int               n = 400000;
  const double                     a = std::sqrt((m.m4 + m.m22) / 2), b = std::sqrt((m.m4 - m.m22) / 2);
  double                           weight = 0, weight_square = 0, curvature = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      // f_xx = -s + d1, f_yy = -s - d1 with s, d1 independent; f_xy = d2.
      const double s = a * normal(generator), d1 = b * normal(generator),
                   d2  = std::sqrt(m.m22) * normal(generator);
      const double det = s * s - d1 * d1 - d2 * d2, w = s > 0 && det > 0 ? det : 0;
      weight += w / n;
      weight_square += w * w / n;
      curvature += w * s / n;
    }
  const ExpectedSummits expected = expected_summits(m);
  const double          error    = std::sqrt((weight_square - weight * weight) / n) / (2 * M_PI * m.m2);
  BOOST_TEST(std::abs(weight / (2 * M_PI * m.m2) - expected.density) < 4 * error);
  BOOST_TEST(curvature / weight == expected.mean_curvature, tt::tolerance(5e-3));
  // The anisotropy matters: the isotropic formula with the same m4 differs.
  BOOST_TEST(std::abs(expected_summits(isotropic_moments(m.m0, m.m2, m.m4)).density - expected.density) >
             10 * error);
}

BOOST_AUTO_TEST_CASE(expected_gap_area_against_monte_carlo)
{
  // int 3 pi (z - p_bar) n(z) E[1/kappa | z] dz by sampling (z, s, d1, d2)
  // (cov(z, s) = m2) with the Kac-Rice weight det(-H) 1{-H > 0}/(2 pi m2):
  // within 4 standard errors at three mean pressures, square-symmetric moments.
  const FieldMoments               m{1.0, 1.0, 3.0, 0.8};
  std::mt19937_64                  generator(7);
  std::normal_distribution<double> normal;
  const unsigned int               n        = 400000;
  const double                     loads[3] = {0., 1., 2.5};
  double                           sum[3] = {0, 0, 0}, squares[3] = {0, 0, 0};
  const double a = std::sqrt(m.m2 * m.m2 / m.m0), b = std::sqrt((m.m4 + m.m22) / 2 - m.m2 * m.m2 / m.m0);
  for (unsigned int i = 0; i < n; ++i)
    {
      const double g = normal(generator), z = std::sqrt(m.m0) * g, s = a * g + b * normal(generator);
      const double d1  = std::sqrt((m.m4 - m.m22) / 2) * normal(generator),
                   d2  = std::sqrt(m.m22) * normal(generator);
      const double det = s * s - d1 * d1 - d2 * d2;
      for (int k = 0; k < 3; ++k)
        {
          const double w =
              s > 0 && det > 0 && z > loads[k] ? det * 3 * M_PI * (z - loads[k]) / s / (2 * M_PI * m.m2) : 0;
          sum[k] += w / n;
          squares[k] += w * w / n;
        }
    }
  for (int k = 0; k < 3; ++k)
    BOOST_TEST(std::abs(expected_gap_area(m, loads[k]) - sum[k]) <
               4 * std::sqrt((squares[k] - sum[k] * sum[k]) / n));
}

BOOST_AUTO_TEST_CASE(isolated_gaps_over_sampled_summits)
{
  // Two summits of tension z = 3 and 0.9 Pa, mean curvature 2 Pa/m^2 (R_p =
  // 1/2 m^2/Pa), on an area of 10 m^2, at p_bar = 0.5 Pa. Without adhesion each
  // holds a gap of area 3 pi R_p P; with K_Ic = 0.3 Pa m^1/2 (p0 = 0.527 Pa)
  // the second (P = 0.4 Pa) closes and the first keeps the stable radius of
  // P(c) = c^2/(3 R_p) + sqrt(pi) K_Ic/(2 sqrt(c)) = 2.5 Pa, 1.8594 m, by bisection above c_min = 0.398 m.
  const std::vector<Summit> summits = {{0, 0, 3, 1, 3}, {0, 0, 0.9, 2, 2}};
  BOOST_TEST(sampled_gap_area(summits, 10, 0.5, 0) == 3 * M_PI * 0.5 * (2.5 + 0.4) / 10,
             tt::tolerance(1e-14));
  double low = 0.5, high = 3;
  for (int k = 0; k < 100; ++k)
    {
      const double c                                                                = (low + high) / 2;
      (c * c / 1.5 + std::sqrt(M_PI) * 0.3 / (2 * std::sqrt(c)) < 2.5 ? low : high) = c;
    }
  BOOST_TEST(low == 1.8594, tt::tolerance(1e-4));
  BOOST_TEST(sampled_gap_area(summits, 10, 0.5, 0.3) == M_PI * low * low / 10, tt::tolerance(1e-12));
  BOOST_TEST(sampled_gap_area(summits, 10, 3, 0.3) == 0.);
}

BOOST_AUTO_TEST_CASE(ensemble_arithmetic)
{
  const HeightBins          bins{0, 2, 2};
  const std::vector<Summit> first  = {{0, 0, 0.5, 1, 3}, {0, 0, 1.5, 2, 2}};
  const std::vector<Summit> second = {{0, 0, 0.5, 4, 4}, {0, 0, 3.0, 6, 6}};
  const SummitSample        a = summarise_summits(first, 2.0, bins), b = summarise_summits(second, 2.0, bins);
  BOOST_TEST(a.n_summits == 2);
  BOOST_TEST(b.bin_counts[0] == 1); // height 3 lies outside the bins
  const SummitSample unpacked = SummitSample::unpack(b.pack(), bins.n);
  BOOST_TEST(unpacked.curvature_sum == b.curvature_sum);
  BOOST_TEST(unpacked.bin_curvature_squares == b.bin_curvature_squares, tt::per_element());
  BOOST_CHECK_THROW(SummitSample::unpack(b.pack(), 3), std::invalid_argument);

  const SummitEnsemble e = summit_ensemble({a, b}, bins);
  BOOST_TEST(e.density.value == 1.0);
  BOOST_TEST(e.density.standard_error == 0.0);
  BOOST_TEST(e.mean_curvature.value == (2 + 2 + 4 + 6) / 4., tt::tolerance(1e-15));
  // Bin [0, 1): curvatures 2 and 4, two summits on two areas of 2 and width 1.
  BOOST_TEST(e.bins[0].mean_curvature.value == 3.0);
  BOOST_TEST(e.bins[0].mean_curvature.standard_error == std::sqrt(2.) / std::sqrt(2.), tt::tolerance(1e-15));
  BOOST_TEST(e.bins[0].density_per_height.value == 0.5);
}

BOOST_AUTO_TEST_CASE(summits_of_gaussian_fields_match_their_expectation)
{
  // H = 0.75, zeta = 4 on L = 4 lambda0 (shortest wavelength 32 cells at
  // 512^2), 64 realisations of the full-contact pressure. The expectation is
  // the Kac-Rice one for the grid's lattice spectrum (m22 from the lattice
  // sums). Allowed: 4 standard errors plus 1 % for the grid (measured against
  // the exact maxima of 20 band-limited realisations, found by Newton's method
  // on direct Fourier sums: the count is exact at 32 points per shortest
  // wavelength and 1 % low at 16).
  const double              lambda0 = 1e-3, E_star = 1e7;
  const PowerSpectrum       heights = power_law_spectrum(0.75, 2 * M_PI / lambda0, 4, 1e-5);
  const PeriodicGrid        grid    = square_grid(512, 4 * lambda0);
  const FourierTransform    transform(grid);
  const FieldMoments        lattice = lattice_moments(grid, pressure_spectrum(heights, E_star)).expected;
  const HeightBins          bins{-3 * std::sqrt(lattice.m0), 5 * std::sqrt(lattice.m0), 8};
  std::vector<SummitSample> samples;
  for (unsigned int r = 0; r < 64; ++r)
    {
      const GridField p = full_contact_pressure(
          transform, gaussian_field(transform, heights, realisation_seed(9, r)), E_star);
      samples.push_back(summarise_summits(find_summits(transform, p), grid.area(), bins));
    }
  const SummitEnsemble  e        = summit_ensemble(samples, bins);
  const ExpectedSummits expected = expected_summits(lattice);
  BOOST_TEST(std::abs(e.density.value - expected.density) <
             4 * e.density.standard_error + 0.01 * expected.density);
  BOOST_TEST(std::abs(e.mean_curvature.value - expected.mean_curvature) <
             4 * e.mean_curvature.standard_error + 0.01 * expected.mean_curvature);
  // The paper's summit density is 3.4 times Nayak's: far outside the error.
  const PressureSummits paper = pressure_summits(spectral_moments(heights), E_star, Convention::paper);
  BOOST_TEST(paper.density > e.density.value + 100 * e.density.standard_error);
}

BOOST_AUTO_TEST_SUITE_END()
