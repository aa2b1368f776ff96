// The adhesive solver's cost against the cohesive zone l_pz and the grid
// (benchmark_contact adhesive): for each problem and discretisation two
// solves, each the least wall time of up to three (fewer once one takes
// over 20 s):
//   start  adhesion switched on at the adhesionless state's mean gap or load,
//          from its gap (how every adhesive path of the scenes begins);
//   step   one continuation step from that equilibrium (how a path goes on).
// Problems, in their scenes' units:
//   johnson  Johnson's sinusoid (bem-johnson) on an n x 1 grid, alpha = 0.2 and
//            0.5, a/lambda = 0.25 (the adhesionless load sin^2(pi a/lambda)),
//            l_pz/lambda = 1e-3 ... 1.25e-4 at 16 and 32 points per zone;
//            step: the mean gap times 0.98;
//   sphere   the JKR sphere (jkr-sphere), period 6 a, l_pz/a = 0.1 ... 0.0125
//            at 4 points per zone, from Hertz's contact of radius 1.2;
//            step: the mean gap plus 0.01;
//   random   the random surface of the adhesionless table at p_bar = 2 sqrt(V),
//            strength w/rho = sqrt(V)/2, l_pz = lambda0/64 ... lambda0/256 at 4
//            and 8 points per zone (N = 256 ... 2048); step: p_bar = 1.8 sqrt(V).
// Beside each solve: the wall time of an iteration and of one convolution
// (an r2c and a c2r FFT) of the grid in double and in single precision, and
// the iteration's cost in double-precision pairs. One rank.
#include "benchmark_contact.h"
#include "contact/half_space_contact.h"
#include "contact/rigid_surface.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>

namespace penny::benchmark
{
  namespace
  {
    // Up to three runs of `solve`, the least wall time kept.
    std::pair<ContactSolution, double> timed(const std::function<ContactSolution()> &solve)
    {
      ContactSolution solution;
      double          least = std::numeric_limits<double>::infinity();
      for (unsigned int run = 0; run < 3; ++run)
        {
          const auto start  = Clock::now();
          solution          = solve();
          const double time = seconds_since(start);
          least             = std::min(least, time);
          if (time > 20)
            break;
        }
      return {solution, least};
    }

    struct Row
    {
      const char  *problem;
      double       parameter; // alpha, or 0
      double       zone;      // l_pz in the problem's length unit
      unsigned int n;         // points per side (n x 1 for Johnson)
    };

    class Table
    {
    public:
      explicit Table(const Planning planning) : planning(planning)
      {
        std::printf("# %-8s %5s %9s %7s | %-5s %6s %7s %8s %9s | %9s %9s %7s | %s\n", "problem", "alpha",
                    "l_pz", "N", "solve", "iter", "coarse", "time(s)", "s/iter", "s/pair", "s/pair32",
                    "pairs", "result");
      }

      // The two solves of one row, on the grid of `transform`.
      void print(const Row &row, const FourierTransform &transform,
                 const std::function<ContactSolution()>                        &start,
                 const std::function<ContactSolution(const ContactSolution &)> &step, const char *result_name,
                 const std::function<double(const ContactSolution &)> &result) const
      {
        const double                 pair = convolution_time(transform);
        const SingleFourierTransform single(transform.grid(), planning);
        const double                 single_pair = convolution_time(single);
        const auto [first, first_time]           = timed(start);
        const auto [second, second_time]         = timed([&] { return step(first); });
        for (const auto &[name, solution, time] :
             {std::tuple{"start", &first, first_time}, std::tuple{"step", &second, second_time}})
          {
            // An iteration's time: the solve's over its iterations on this grid and,
            // in this grid's units, on the halved grids of nested iteration.
            const double per_iteration =
                time / std::max(solution->iterations + solution->coarse_iterations, 1.);
            std::printf(
                "  %-8s %5.2f %9.3g %7u | %-5s %6u %7.1f %8.3f %9.2e | %9.2e %9.2e %7.1f | %s %.12g\n",
                row.problem, row.parameter, row.zone, row.n, name, solution->iterations,
                solution->coarse_iterations, time, per_iteration, pair, single_pair, per_iteration / pair,
                result_name, result(*solution));
            std::fflush(stdout);
          }
      }

    private:
      Planning planning;
    };

    void johnson(const Table &table, const ContactSolverControl &control)
    {
      const double h0 = 1 / M_PI, a = 0.25; // p* = pi E* h0/lambda = 1
      for (const double alpha : {0.2, 0.5})
        for (const double zone : {1e-3, 5e-4, 2.5e-4, 1.25e-4})
          for (const unsigned int per_zone : {16u, 32u})
            {
              const unsigned int    n = std::lround(per_zone / zone);
              const RigidSurface    surface({n, 1, 1., 1. / n},
                                            [n, h0](unsigned int i, unsigned int) {
                                           return 2 * h0 * std::pow(std::sin(M_PI * i / n), 2);
                                         },
                                            {alpha * alpha / 2, alpha * std::sqrt(M_PI * zone / 2)});
              const ContactSolution adhesionless =
                  surface.adhesionless().solve(std::pow(std::sin(M_PI * a), 2), control);
              const FourierTransform transform(surface.grid());
              table.print(
                  {"johnson", alpha, zone, n}, transform,
                  [&] {
                    return surface.adhesive().solve_at_mean_gap(adhesionless.mean_gap, control,
                                                                adhesionless.gap);
                  },
                  [&](const ContactSolution &from) {
                    return surface.adhesive().solve_at_mean_gap(0.98 * from.mean_gap, control, from.gap);
                  },
                  "p_bar/p*", [](const ContactSolution &s) { return s.mean_pressure; });
            }
    }

    void sphere(const Table &table, const ContactSolverControl &control)
    {
      const double period = 6, work = 8 / (9 * M_PI), hertz_radius = 1.2;
      for (const double zone : {0.1, 0.05, 0.025, 0.0125})
        {
          const unsigned int    n = std::lround(4 * period / zone);
          const RigidSurface    surface(square_grid(n, period),
                                        [n, period](unsigned int i, unsigned int j) {
                                       const double x = (double(i) - n / 2) * period / n,
                                                    y = (double(j) - n / 2) * period / n;
                                       return -(x * x + y * y) / 2;
                                     },
                                        {work, std::sqrt(M_PI * work * zone)});
          const ContactSolution hertz =
              surface.adhesionless().solve(4 * std::pow(hertz_radius, 3) / 3 / (period * period), control);
          const FourierTransform transform(surface.grid());
          table.print(
              {"sphere", 0, zone, n}, transform,
              [&] { return surface.adhesive().solve_at_mean_gap(hertz.mean_gap, control, hertz.gap); },
              [&](const ContactSolution &from) {
                return surface.adhesive().solve_at_mean_gap(from.mean_gap + 0.01, control, from.gap);
              },
              "F", [&](const ContactSolution &s) { return s.mean_pressure * period * period; });
        }
    }

    void random(const Table &table, const ContactSolverControl &control, const Planning planning)
    {
      const double        lambda0 = 1e-3, E_star = 1e7 / (1 - 0.49 * 0.49);
      const PowerSpectrum spectrum = power_law_spectrum(0.75, 2 * M_PI / lambda0, 32, 0.01 * lambda0);
      for (const unsigned int per_zone : {4u, 8u})
        for (const double zones : {64., 128., 256.})
          {
            const unsigned int     n    = per_zone * zones;
            const PeriodicGrid     grid = square_grid(n, lambda0);
            const FourierTransform transform(grid, planning);
            const GridField        h = gaussian_field(transform, spectrum, realisation_seed(1, 0));
            const double           sqrt_V =
                std::sqrt(lattice_moments(grid, pressure_spectrum(spectrum, E_star)).expected.m0);
            const double           zone = lambda0 / zones, strength = sqrt_V / 2;
            const double           w = M_PI * strength * strength * zone / E_star;
            const HalfSpaceContact adhesionless(transform, h, E_star),
                sticky(transform, h, E_star, {w, w / strength});
            const ContactSolution from = adhesionless.solve(2 * sqrt_V, control);
            table.print(
                {"random", 0, zone / lambda0, n}, transform,
                [&] { return sticky.solve(2 * sqrt_V, control, from.gap); },
                [&](const ContactSolution &previous) {
                  return sticky.solve(1.8 * sqrt_V, control, previous.gap);
                },
                "A_nc", [](const ContactSolution &s) { return 1 - s.contact_fraction; });
          }
    }
  } // namespace

  void adhesive_benchmark(const std::vector<std::string> &cases, const Planning planning)
  {
    int ranks;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (ranks != 1)
      throw std::invalid_argument("benchmark_contact adhesive: runs on one rank (got " +
                                  std::to_string(ranks) + ")");
    const auto wanted = [&](const char *name) {
      return cases.empty() || std::find(cases.begin(), cases.end(), name) != cases.end();
    };
    std::printf("# adhesive solves; FFTW planning: %s; load average at the start %s\n",
                planning == Planning::measure ? "measure" : "estimate", load_average().c_str());
    const Table table(planning);
    // The scenes' tolerances: bem-johnson 1e-11, jkr-sphere 1e-9, the random surfaces 1e-8.
    if (wanted("johnson"))
      johnson(table, {200000, 1e-11});
    if (wanted("sphere"))
      sphere(table, {200000, 1e-9});
    if (wanted("random"))
      random(table, {200000, 1e-8}, planning);
    std::printf(
        "# l_pz: per lambda (johnson, random) or per a (sphere); N: points per side (johnson: N x 1);\n"
        "# time: least of up to three solves; s/pair, s/pair32: one r2c + c2r FFT of the grid in double "
        "and single precision;\n# pairs: an iteration's wall time in double-precision pairs; load "
        "average at the end %s\n",
        load_average().c_str());
  }
} // namespace penny::benchmark
