// A grid split over the ranks of MPI_COMM_WORLD against the same grid on
// each rank alone: the transforms, the random fields, the moves between
// grids of nested iteration, single against double precision, and the contact solves with and without
// adhesion, at prescribed mean pressure and mean gap; what needs the whole
// field refuses a split grid. Each split both ways, in shared memory and by
// FFTW's MPI plans. Run on 1 rank (the split transform is then the serial
// one) and on 2.
#include "contact/contact_geometry.h"
#include "contact/contact_path.h"
#include "contact/half_space_contact.h"
#include "fourier/grid_resampling.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"
#include "statistics/summit_statistics.h"

#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

namespace penny
{
  std::ostream &operator<<(std::ostream &out, const SplitTransform how)
  {
    return out << (how == SplitTransform::shared_memory ? "shared memory" : "FFTW MPI");
  }
} // namespace penny

BOOST_AUTO_TEST_SUITE(test_split_grid)

using namespace penny;

namespace
{
  const auto both_ways =
      boost::unit_test::data::make({SplitTransform::shared_memory, SplitTransform::fftw_mpi});

  const MPI_Comm world = MPI_COMM_WORLD;

  // This rank's rows of a field on the whole grid.
  GridField local_rows(const FourierTransform &split, const GridField &field)
  {
    const auto begin = field.begin() + std::size_t(split.first_row()) * split.grid().ny;
    return GridField(begin, begin + split.n_local_points());
  }

  // max |a - b| over the grid (a, b local rows), the same on every rank.
  double largest_difference(const GridField &a, const GridField &b)
  {
    double difference = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      difference = std::max(difference, std::abs(a[i] - b[i]));
    MPI_Allreduce(MPI_IN_PLACE, &difference, 1, MPI_DOUBLE, MPI_MAX, world);
    return difference;
  }

  double largest_over_ranks(const double value)
  {
    double largest = value;
    MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, world);
    return largest;
  }

  double largest_value(const GridField &field)
  {
    return *std::max_element(field.begin(), field.end(),
                             [](double a, double b) { return std::abs(a) < std::abs(b); });
  }

  const double        lambda = 1e-3, E_star = 1e7;
  const PowerSpectrum spectrum = power_law_spectrum(0.75, 2 * M_PI / lambda, 16, 1e-5);

  double sqrt_V(const PeriodicGrid &grid)
  {
    return std::sqrt(lattice_moments(grid, pressure_spectrum(spectrum, E_star)).expected.m0);
  }

  // The solver's results on the split grid against those on each rank alone,
  // to `tolerance` (at least the solver's): the gaps and pressures within it of
  // the rms height and the mean pressure, the scalars within `tolerance`
  // relative, the same points in contact to two and the iterations to one.
  void check_equal(const HalfSpaceContact &split, const ContactSolution &s, const ContactSolution &serial,
                   const double height_rms, const double tolerance)
  {
    const double            fields = tolerance, scalars = tolerance;
    const FourierTransform &transform = split.transform();
    BOOST_TEST(largest_difference(s.gap, local_rows(transform, serial.gap)) <= fields * height_rms);
    BOOST_TEST(largest_difference(s.pressure, local_rows(transform, serial.pressure)) <=
               fields * std::abs(serial.mean_pressure));
    BOOST_TEST(std::abs(s.mean_gap - serial.mean_gap) <= scalars * serial.mean_gap);
    BOOST_TEST(std::abs(s.mean_pressure - serial.mean_pressure) <= scalars * std::abs(serial.mean_pressure));
    BOOST_TEST(std::abs(s.energy - serial.energy) <= scalars * std::abs(serial.energy));
    BOOST_TEST(std::abs(s.contact_fraction - serial.contact_fraction) <= 2.0 / transform.grid().n_points());
    BOOST_TEST(std::abs(int(s.iterations) - int(serial.iterations)) <= 1);
  }
} // namespace

BOOST_DATA_TEST_CASE(split_transforms_equal_serial_ones, both_ways, how)
{
  // Rectangles of unequal sides and points, two with rows or spectrum lines
  // fewer than two ranks: convolution with a complex multiplier (d/dx), the
  // spectrum coefficient by coefficient and the quadratic form agree to
  // rounding (1e-12 relative; measured on 2 ranks 5e-16, 3e-16).
  const auto stiffness = [](const Wavevector &q) { return q.norm(); };
  const auto load      = [](const FourierTransform &transform, const GridField &field) {
    transform.for_each_point(
        [&](const std::size_t i, const std::size_t w) { transform.work_array()[w] = field[i]; });
  };
  for (const PeriodicGrid grid :
       {PeriodicGrid{48, 40, 2 * lambda, 1.5 * lambda}, PeriodicGrid{3, 8, lambda, lambda},
        PeriodicGrid{1, 8, lambda, lambda}, PeriodicGrid{5, 1, lambda, lambda}})
    {
      const FourierTransform serial(grid), split(grid, Planning::estimate, world, how);
      BOOST_TEST(split.shares_memory() == (split.split() && how == SplitTransform::shared_memory));
      const GridField h          = gaussian_field(serial, spectrum, 3);
      const auto      multiplier = [](const Wavevector &q) { return derivative_factor(q, 1, 0); };
      GridField       serial_slope, split_slope;
      serial.apply(serial.tabulate(multiplier), h, serial_slope);
      split.apply(split.tabulate(multiplier), local_rows(split, h), split_slope);
      BOOST_TEST(largest_difference(split_slope, local_rows(split, serial_slope)) <=
                 1e-12 * std::abs(largest_value(serial_slope)));

      const FourierTransform::Spectrum a = serial.forward(h), b = split.forward(local_rows(split, h));
      double                           difference = 0, largest = 0;
      for (std::size_t c = 0; c < b.size(); ++c)
        {
          const Wavevector q = split.wavevector(c);
          const auto       s = a[((q.kx + grid.nx) % grid.nx) * (grid.ny / 2 + 1) + q.ky];
          difference         = std::max(difference, std::abs(b[c] - s));
          largest            = std::max(largest, std::abs(s));
        }
      BOOST_TEST(largest_over_ranks(difference) <= 1e-12 * largest_over_ranks(largest));
      const GridField back = split.inverse(b);
      BOOST_TEST(largest_difference(back, local_rows(split, h)) <= 1e-12 * std::abs(largest_value(h)));

      load(serial, h);
      load(split, local_rows(split, h));
      const double expected = serial.quadratic_form_of_work_array(serial.tabulate_real(stiffness));
      BOOST_TEST(split.quadratic_form_of_work_array(split.tabulate_real(stiffness)) == expected,
                 boost::test_tools::tolerance(1e-12));
    }

  // Parseval: with m = 1 the quadratic form is the mean square (ny even and odd).
  for (const unsigned int ny : {40u, 39u})
    {
      const FourierTransform one({48, ny, 2 * lambda, 1.5 * lambda});
      const GridField        f      = gaussian_field(one, spectrum, 4);
      double                 square = 0;
      for (const double value : f)
        square += value * value / f.size();
      load(one, f);
      BOOST_TEST(one.quadratic_form_of_work_array(one.tabulate_real([](const Wavevector &) { return 1.; })) ==
                     square,
                 boost::test_tools::tolerance(1e-12));
    }
}

BOOST_DATA_TEST_CASE(single_precision_transforms_equal_double_ones, both_ways, how)
{
  // The contact solver's preconditioner and curvature: a convolution with the
  // half-space's compliance and the quadratic form of its stiffness in single
  // precision, on the same split as in double, agree with double precision to
  // 1e-6 relative (float rounding, 6e-8, times a few for the passes; the
  // quadratic forms measured 1.5e-8 and 6.1e-8 apart).
  const auto compliance = [](const Wavevector &q) { return q.norm() > 0 ? 1 / q.norm() : 0.; };
  const auto stiffness  = [](const Wavevector &q) { return q.norm(); };
  for (const PeriodicGrid grid :
       {PeriodicGrid{48, 40, 2 * lambda, 1.5 * lambda}, PeriodicGrid{3, 8, lambda, lambda}})
    {
      const FourierTransform       exact(grid, Planning::estimate, world, how);
      const SingleFourierTransform single(grid, Planning::estimate, world, how);
      BOOST_TEST(single.first_row() == exact.first_row());
      BOOST_TEST(single.n_rows() == exact.n_rows());
      const GridField h    = local_rows(exact, gaussian_field(FourierTransform(grid), spectrum, 5));
      const auto      load = [&](const auto &transform) {
        transform.for_each_point(
            [&](const std::size_t i, const std::size_t w) { transform.work_array()[w] = h[i]; });
      };
      load(exact);
      load(single);
      exact.convolve_work_array(exact.tabulate_real(compliance));
      single.convolve_work_array(single.tabulate_real(compliance));
      GridField expected(h.size()), rounded(h.size());
      exact.for_each_point([&](const std::size_t i, const std::size_t w) {
        expected[i] = exact.work_array()[w];
        rounded[i]  = single.work_array()[w];
      });
      BOOST_TEST(largest_difference(rounded, expected) <=
                 1e-6 * std::abs(largest_over_ranks(largest_value(expected))));

      load(exact);
      load(single);
      BOOST_TEST(single.quadratic_form_of_work_array(single.tabulate_real(stiffness)) ==
                     exact.quadratic_form_of_work_array(exact.tabulate_real(stiffness)),
                 boost::test_tools::tolerance(1e-6));
    }
}

BOOST_DATA_TEST_CASE(split_gaussian_field_equals_the_serial_one, both_ways, how)
{
  // Each rank draws only its own coefficients; the field is the serial one
  // to 1e-12 of its largest value (measured on 2 ranks 3e-16), its moments
  // to 1e-12.
  const PeriodicGrid     grid{96, 64, 2 * lambda, 2 * lambda * 64 / 96};
  const FourierTransform serial(grid), split(grid, Planning::estimate, world, how);
  const GridField        h    = gaussian_field(serial, spectrum, realisation_seed(5, 2));
  const GridField        rows = gaussian_field(split, spectrum, realisation_seed(5, 2));
  BOOST_TEST(rows.size() == split.n_local_points());
  BOOST_TEST(largest_difference(rows, local_rows(split, h)) <= 1e-12 * std::abs(largest_value(h)));
  const FieldMoments a = sampled_moments(serial, h), b = sampled_moments(split, rows);
  BOOST_TEST(b.m0 == a.m0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(b.m2 == a.m2, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(b.m4 == a.m4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(b.m22 == a.m22, boost::test_tools::tolerance(1e-12));
}

BOOST_DATA_TEST_CASE(split_resampling_and_interpolation_equal_serial_ones, both_ways, how)
{
  // Nested iteration's moves between a grid and its halved one, on grids
  // whose halved rows fall unevenly on the ranks: the spectral resampling to
  // rounding (1e-12 of the largest value), the interpolation exactly (the
  // same arithmetic on the same values).
  for (const PeriodicGrid fine : {PeriodicGrid{68, 40, lambda, lambda}, PeriodicGrid{12, 1, lambda, lambda}})
    {
      const PeriodicGrid     coarse = *halved(fine, 1);
      const FourierTransform serial_fine(fine), serial_coarse(coarse);
      const FourierTransform split_fine(fine, Planning::estimate, world, how),
          split_coarse(coarse, Planning::estimate, world, how);
      const GridField h          = gaussian_field(serial_fine, spectrum, 9);
      const GridField down       = resampled(serial_fine, serial_coarse, h);
      const GridField split_down = resampled(split_fine, split_coarse, local_rows(split_fine, h));
      BOOST_TEST(largest_difference(split_down, local_rows(split_coarse, down)) <=
                 1e-12 * std::abs(largest_value(down)));
      const GridField up = interpolated(serial_coarse, down, serial_fine);
      BOOST_TEST(largest_difference(interpolated(split_coarse, local_rows(split_coarse, down), split_fine),
                                    local_rows(split_fine, up)) == 0);
      const GridField back = resampled(split_coarse, split_fine, split_down);
      BOOST_TEST(
          largest_difference(back, local_rows(split_fine, resampled(serial_coarse, serial_fine, down))) <=
          1e-12 * std::abs(largest_value(down)));
    }
}

BOOST_DATA_TEST_CASE(split_solves_without_adhesion_equal_serial_ones, both_ways, how)
{
  // 256^2 at 2 sqrt(V): a cold start (nested iteration on 128^2, the halved
  // grid split too) at prescribed mean pressure, and a solve at 1.2 times
  // the mean gap it found, solved to 1e-12 and equal to 1e-10: the traction's
  // updates are rounded in single precision, so the two take different
  // paths to the same solution (measured on 2 ranks: fields 1.5e-11 and
  // 6.2e-11, scalars 5.5e-13, the same iterations; solved to 1e-10 instead,
  // the fields differed by up to 5e-9).
  const PeriodicGrid     grid = square_grid(256, lambda);
  const FourierTransform serial_transform(grid), split_transform(grid, Planning::estimate, world, how);
  const GridField        h = gaussian_field(serial_transform, spectrum, 7);
  const HalfSpaceContact serial(serial_transform, h, E_star),
      split(split_transform, local_rows(split_transform, h), E_star);
  const ContactSolverControl control{1000, 1e-12};
  const double               h_rms = std::sqrt(sampled_moments(serial_transform, h).m0);

  const ContactSolution a = serial.solve(2 * sqrt_V(grid), control),
                        b = split.solve(2 * sqrt_V(grid), control);
  BOOST_TEST(b.coarse_iterations > 0);
  check_equal(split, b, a, h_rms, 1e-10);

  const ContactSolution c = serial.solve_at_mean_gap(1.2 * a.mean_gap, control),
                        d = split.solve_at_mean_gap(1.2 * a.mean_gap, control);
  check_equal(split, d, c, h_rms, 1e-10);
}

BOOST_DATA_TEST_CASE(split_solves_with_adhesion_equal_serial_ones, both_ways, how)
{
  // 128^2, a cohesive zone of 5 grid spacings and a strength sqrt(V)/2, from
  // the adhesionless state at 2 sqrt(V): at that mean pressure and at 1.2
  // times its mean gap. Equal to the tolerance 1e-10 (measured on 2 ranks:
  // fields 7e-16, the energy 3e-13, the same iterations).
  const PeriodicGrid     grid = square_grid(128, lambda);
  const FourierTransform serial_transform(grid), split_transform(grid, Planning::estimate, world, how);
  const GridField        h        = gaussian_field(serial_transform, spectrum, 11);
  const double           strength = sqrt_V(grid) / 2, zone = 5 * lambda / 128;
  const double           w = M_PI * strength * strength * zone / E_star;
  const Adhesion         adhesion{w, w / strength};
  const HalfSpaceContact serial(serial_transform, h, E_star, adhesion),
      split(split_transform, local_rows(split_transform, h), E_star, adhesion);
  const HalfSpaceContact     start(serial_transform, h, E_star);
  const ContactSolverControl control{1000, 1e-10};
  const double               h_rms = std::sqrt(sampled_moments(serial_transform, h).m0);
  const GridField            gap   = start.solve(2 * sqrt_V(grid), control).gap;

  const ContactSolution a = serial.solve(2 * sqrt_V(grid), control, gap),
                        b = split.solve(2 * sqrt_V(grid), control, local_rows(split_transform, gap));
  check_equal(split, b, a, h_rms, control.tolerance);
  const ContactSolution c = serial.solve_at_mean_gap(1.2 * a.mean_gap, control, gap),
                        d = split.solve_at_mean_gap(1.2 * a.mean_gap, control,
                                                    local_rows(split_transform, gap));
  check_equal(split, d, c, h_rms, control.tolerance);
  BOOST_TEST(c.iterations > 0u);
}

BOOST_DATA_TEST_CASE(errors_reach_every_rank, both_ways, how)
{
  // A failure decided on reduced quantities is thrown on every rank (else
  // this test would hang), and what needs the whole field refuses a split grid.
  const PeriodicGrid     grid = square_grid(64, lambda);
  const FourierTransform split_transform(grid, Planning::estimate, world, how);
  const GridField        h = gaussian_field(split_transform, spectrum, 13);
  const HalfSpaceContact split(split_transform, h, E_star);
  BOOST_CHECK_THROW(split.solve(sqrt_V(grid), {2, 1e-14}), ContactSolverFailure);
  BOOST_CHECK_THROW(split.solve(-1, {100, 1e-10}), std::invalid_argument);
  GridField with_nan = h;
  if (split_transform.holds_first_row())
    with_nan[0] = std::nan("");
  BOOST_CHECK_THROW(HalfSpaceContact(split_transform, with_nan, E_star), std::invalid_argument);
  if (split_transform.split())
    {
      BOOST_CHECK_THROW(ContactPath(split, "loading", {100, 1e-10}), std::invalid_argument);
      BOOST_CHECK_THROW(find_summits(split_transform, h), std::invalid_argument);
      BOOST_CHECK_THROW(contact_topology(grid, h), std::invalid_argument);
    }
}

BOOST_AUTO_TEST_SUITE_END()
