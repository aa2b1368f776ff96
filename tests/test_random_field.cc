// Gaussian random fields on a periodic grid: FFT round trips, spectral
// derivatives, the PSD evaluation, reproducibility from the seed, Hermitian
// symmetry, the same surface on a finer grid, sampled mean squares against
// their lattice expectation within a stated number of standard errors, and
// realisations gathered over MPI ranks in index order.
#include "contact/half_space.h"
#include "input/input_error.h"
#include "numerics/solver_failure.h"
#include "parallel/collective.h"
#include "parallel/spread_over_ranks.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"

#include <boost/test/unit_test.hpp>

#include <cmath>

BOOST_AUTO_TEST_SUITE(test_random_field)

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  // H = 0.75, lambda0 = 1 mm, zeta = 8, h0 = 10 um on a box of 4 lambda0:
  // the shortest wavelength has 8 points on a 256^2 grid.
  const double        lambda0 = 1e-3, box = 4 * lambda0;
  const PowerSpectrum spectrum = power_law_spectrum(0.75, 2 * M_PI / lambda0, 8, 1e-5);

  double max_abs_difference(const GridField &a, const GridField &b)
  {
    double difference = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      difference = std::max(difference, std::abs(a[i] - b[i]));
    return difference;
  }

  double rms(const GridField &field)
  {
    double sum = 0;
    for (const double v : field)
      sum += v * v;
    return std::sqrt(sum / field.size());
  }
} // namespace

BOOST_AUTO_TEST_CASE(spectral_density_interpolates_the_table)
{
  const double q0 = spectrum.wavenumbers[0], C0 = spectrum.densities[0];
  BOOST_TEST(spectral_density(spectrum, q0) == C0, tt::tolerance(1e-14));
  BOOST_TEST(spectral_density(spectrum, 3 * q0) == C0 * std::pow(3., -3.5), tt::tolerance(1e-13));
  BOOST_TEST(spectral_density(spectrum, 8 * q0 * (1 + 1e-14)) > 0); // a cut-off shell counts
  BOOST_TEST(spectral_density(spectrum, 0.99 * q0) == 0);
  BOOST_TEST(spectral_density(spectrum, 8.01 * q0) == 0);
  const PowerSpectrum pressure = pressure_spectrum(spectrum, 2e6);
  BOOST_TEST(spectral_density(pressure, 3 * q0) ==
                 1e12 * std::pow(3 * q0, 2) * spectral_density(spectrum, 3 * q0),
             tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(fourier_round_trip_and_derivatives_of_a_trigonometric_field)
{
  // f = sin(2 pi 3 x/lx) cos(2 pi 2 y/ly) on a rectangle: every derivative is exact.
  const PeriodicGrid     grid{64, 32, 2.0, 0.5};
  const FourierTransform transform(grid);
  const double           a = 2 * M_PI * 3 / grid.lx, b = 2 * M_PI * 2 / grid.ly;
  GridField              f(grid.n_points()), f_xy(grid.n_points()), f_yyy(grid.n_points());
  for (unsigned int i = 0; i < grid.nx; ++i)
    for (unsigned int j = 0; j < grid.ny; ++j)
      {
        const double x = i * grid.lx / grid.nx, y = j * grid.ly / grid.ny;
        f[i * grid.ny + j]     = std::sin(a * x) * std::cos(b * y);
        f_xy[i * grid.ny + j]  = -a * b * std::cos(a * x) * std::sin(b * y);
        f_yyy[i * grid.ny + j] = b * b * b * std::sin(a * x) * std::sin(b * y);
      }
  BOOST_TEST(max_abs_difference(transform.inverse(transform.forward(f)), f) < 1e-14);
  BOOST_TEST(max_abs_difference(spectral_derivative(transform, f, 1, 1), f_xy) < 1e-12 * a * b);
  BOOST_TEST(max_abs_difference(spectral_derivative(transform, f, 0, 3), f_yyy) < 1e-12 * b * b * b);
}

BOOST_AUTO_TEST_CASE(full_contact_pressure_of_a_sinusoid)
{
  // h = h0 cos(2 pi x/lambda) needs p_fc = p* cos(2 pi x/lambda), p* = pi E* h0/lambda.
  const PeriodicGrid     grid{128, 4, 1e-3, 1e-3 * 4 / 128};
  const FourierTransform transform(grid);
  const double           h0 = 1e-6, E_star = 1e7, p_star = M_PI * E_star * h0 / grid.lx;
  GridField              h(grid.n_points()), p(grid.n_points());
  for (unsigned int i = 0; i < grid.nx; ++i)
    for (unsigned int j = 0; j < grid.ny; ++j)
      {
        h[i * grid.ny + j] = h0 * std::cos(2 * M_PI * i / grid.nx);
        p[i * grid.ny + j] = p_star * std::cos(2 * M_PI * i / grid.nx);
      }
  BOOST_TEST(max_abs_difference(full_contact_pressure(transform, h, E_star), p) < 1e-12 * p_star);
}

BOOST_AUTO_TEST_CASE(reproducible_from_the_seed)
{
  const FourierTransform transform(square_grid(64, box));
  const GridField        a = gaussian_field(transform, spectrum, realisation_seed(42, 3));
  BOOST_TEST(max_abs_difference(a, gaussian_field(transform, spectrum, realisation_seed(42, 3))) == 0);
  BOOST_TEST(max_abs_difference(a, gaussian_field(transform, spectrum, realisation_seed(42, 4))) > rms(a));
  BOOST_TEST(max_abs_difference(a, gaussian_field(transform, spectrum, realisation_seed(43, 3))) > rms(a));
  BOOST_TEST(realisation_seed(42, 3) != realisation_seed(3, 42));
}

BOOST_AUTO_TEST_CASE(hermitian_spectrum_gives_a_real_field)
{
  // c2r assumes Hermitian symmetry; the round trip returns the drawn
  // coefficients only if they have it. Odd and even sizes, a rectangle.
  for (const PeriodicGrid grid : {square_grid(64, box), PeriodicGrid{63, 32, box, box / 2}})
    {
      const FourierTransform           transform(grid);
      const FourierTransform::Spectrum drawn   = gaussian_spectrum(transform, spectrum, 7);
      const FourierTransform::Spectrum back    = transform.forward(transform.inverse(drawn));
      double                           largest = 0, difference = 0;
      for (std::size_t c = 0; c < drawn.size(); ++c)
        {
          largest            = std::max(largest, std::abs(drawn[c]));
          difference         = std::max(difference, std::abs(back[c] - drawn[c]));
          const Wavevector q = transform.wavevector(c);
          if (q.ky == 0 && q.kx > 0) // its partner -kx sits at row nx - kx
            BOOST_TEST(std::abs(drawn[c] - std::conj(drawn[(grid.nx - q.kx) * (grid.ny / 2 + 1)])) == 0);
        }
      BOOST_TEST(largest > 0);
      BOOST_TEST(difference < 1e-13 * largest);
    }
}

BOOST_AUTO_TEST_CASE(same_surface_on_a_finer_grid)
{
  // Mode coefficients depend on the wavevector only: the 256^2 sampling of a
  // seed holds the 128^2 one at its even points (the spectrum ends at
  // |k| = 32, below both Nyquist wavenumbers).
  const FourierTransform coarse(square_grid(128, box)), fine(square_grid(256, box));
  const GridField        h_coarse = gaussian_field(coarse, spectrum, 11),
                  h_fine          = gaussian_field(fine, spectrum, 11);
  double difference               = 0;
  for (unsigned int i = 0; i < 128; ++i)
    for (unsigned int j = 0; j < 128; ++j)
      difference = std::max(difference, std::abs(h_coarse[i * 128 + j] - h_fine[2 * i * 256 + 2 * j]));
  BOOST_TEST(difference < 1e-13 * rms(h_coarse));
}

BOOST_AUTO_TEST_CASE(sampled_moments_within_four_standard_errors)
{
  // 64 realisations on 256^2: each mean square's average lies within 4
  // standard errors (predicted by the lattice sums) of its expectation, and
  // the lattice expectation is within 3 % of the continuum moment for
  // m2, m4 (L = 4 lambda0; m0 sits on the lowest shells, 8.5 % there).
  const PeriodicGrid     grid = square_grid(256, box);
  const FourierTransform transform(grid);
  const LatticeMoments   lattice = lattice_moments(grid, spectrum);
  const unsigned int     n       = 64;
  double                 sum[4]  = {0, 0, 0, 0};
  for (unsigned int r = 0; r < n; ++r)
    {
      const FieldMoments m =
          sampled_moments(transform, gaussian_field(transform, spectrum, realisation_seed(1, r)));
      const double v[4] = {m.m0, m.m2, m.m4, m.m22};
      for (int k = 0; k < 4; ++k)
        sum[k] += v[k] / n;
    }
  const double expected[4]  = {lattice.expected.m0, lattice.expected.m2, lattice.expected.m4,
                               lattice.expected.m22};
  const double deviation[4] = {lattice.standard_deviation.m0, lattice.standard_deviation.m2,
                               lattice.standard_deviation.m4, lattice.standard_deviation.m22};
  for (int k = 0; k < 4; ++k)
    BOOST_TEST(std::abs(sum[k] - expected[k]) < 4 * deviation[k] / std::sqrt(n));

  const SpectralMoments continuum = spectral_moments(spectrum);
  BOOST_TEST(lattice.expected.m0 == continuum.m0, tt::tolerance(0.1));
  BOOST_TEST(lattice.expected.m2 == continuum.m2, tt::tolerance(0.03));
  BOOST_TEST(lattice.expected.m4 == continuum.m4, tt::tolerance(0.03));
  BOOST_TEST(lattice.expected.m22 == continuum.m4 / 3, tt::tolerance(0.03));
}

BOOST_AUTO_TEST_CASE(realisations_gathered_in_index_order)
{
  const auto rows = spread_over_ranks(
      MPI_COMM_WORLD, 5, [](unsigned int index) { return std::vector<double>(index, double(index)); });
  BOOST_TEST_REQUIRE(rows.size() == 5u);
  for (unsigned int index = 0; index < 5; ++index)
    BOOST_TEST(rows[index] == std::vector<double>(index, double(index)), tt::per_element());
}

// A piece that throws on whichever rank draws it: every rank throws it, of
// the same kind, with the same message (and a solver failure its settings),
// instead of the others waiting for the gather.
BOOST_AUTO_TEST_CASE(a_failing_piece_throws_on_every_rank)
{
  const auto failing = [](unsigned int index) {
    if (index == 3)
      throw SolverFailure("piece 3 did not converge", "its settings");
    return std::vector<double>(1, index);
  };
  bool thrown = false;
  try
    {
      spread_over_ranks(MPI_COMM_WORLD, 6, failing);
    }
  catch (const SolverFailure &failure)
    {
      thrown = true;
      BOOST_TEST(std::string(failure.what()) == "piece 3 did not converge");
      BOOST_TEST(failure.settings == "its settings");
    }
  BOOST_TEST(thrown);
  // The ranks go on together afterwards.
  BOOST_TEST(spread_over_ranks(MPI_COMM_WORLD, 2, [](unsigned int i) {
               return std::vector<double>(1, i);
             }).size() == 2u);
}

BOOST_AUTO_TEST_CASE(a_failure_on_rank_zero_throws_on_every_rank)
{
  BOOST_CHECK_EXCEPTION(run_on_rank_zero(MPI_COMM_WORLD, [] { throw InputError("bad entry"); }), InputError,
                        [](const InputError &error) { return std::string(error.what()) == "bad entry"; });
  BOOST_CHECK_NO_THROW(run_on_rank_zero(MPI_COMM_WORLD, [] {}));
}

BOOST_AUTO_TEST_SUITE_END()
