// Speed of the boundary-element contact solver near full contact, against the
// grid: the random surface of the random-contact scene (H = 0.75, zeta = 32,
// lambda0 = 1 mm, h0/lambda0 = 0.01, one period lambda0, seed 1; E = 10 MPa,
// nu = 0.49), tolerance 1e-8.
//
// For each N, adhesionless at p_bar = 2 sqrt(V): the solve from full contact
// (iterations, wall time, the time per iteration against the time of one
// convolution, i.e. one r2c and one c2r FFT, and the residual of the old
// definition, the gap that the reported pressure makes, evaluated
// independently) and the cold start, which first solves on the halved grids
// (iterations on this grid + on the coarser ones in this grid's units, wall
// time); then the six loads p_bar/sqrt(V) = 3, 2.5, ..., 0.5 as the
// random-contact scene runs them (load_sweep: each a cold start; the least
// wall time of three sweeps up to N = 2048, of one beyond); and the adhesive solve at 2 sqrt(V) from
// the adhesionless one (w, rho with a cohesive zone of lambda0/64, 4 grid spacings at N = 256, and a strength
// w/rho = sqrt(V)/2).
//
// Under mpirun -np P the grid is split over the P ranks (in shared memory
// where they share a node, else FFTW's MPI interface: SplitTransform); one
// rank runs the serial transforms. Each solve's results follow as "# result"
// lines (A_nc and the mean gap, all digits) for comparison across rank
// counts (postprocess/benchmark_contact_ranks.sh).
//
// "adhesive" runs the adhesive solver's table instead, on one rank
// (benchmark_contact_adhesive.cc): iterations and wall time per solve against
// the cohesive zone and the grid, for Johnson's sinusoid, the JKR sphere and
// the random surface.
//
// Usage: [mpirun -np P] benchmark_contact [measure] [fftw-mpi] [N ...]
//        benchmark_contact [measure] adhesive [johnson] [sphere] [random]
// (N in [256, 65536], default 256 512 1024 2048 4096; "measure": FFTW_MEASURE plans instead
// of FFTW_ESTIMATE; "fftw-mpi": FFTW's MPI plans on one node too; the adhesive problems: all if none named)
#include "benchmark_contact.h"
#include "contact/half_space_contact.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <mpi.h>
#include <stdexcept>
#include <string>
#include <vector>

using namespace penny;

namespace penny::benchmark
{
  std::string load_average()
  {
    std::ifstream file("/proc/loadavg");
    std::string   one, five, fifteen;
    file >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen;
  }

  template <typename Real> double convolution_time(const BasicFourierTransform<Real> &transform)
  {
    const auto identity = transform.tabulate_real([](const Wavevector &) { return 1.; });
    transform.for_each_point([&](std::size_t, const std::size_t w) { transform.work_array()[w] = 1; });
    const auto   start   = Clock::now();
    unsigned int repeats = 0;
    for (int more = 1; more;)
      {
        transform.convolve_work_array(identity);
        more = ++repeats < 3 || seconds_since(start) < 1;
        MPI_Bcast(&more, 1, MPI_INT, 0, transform.communicator());
      }
    return seconds_since(start) / repeats;
  }

  template double convolution_time(const BasicFourierTransform<double> &);
  template double convolution_time(const BasicFourierTransform<float> &);
} // namespace penny::benchmark

using namespace penny::benchmark;

namespace
{
  // The largest peak resident memory of the ranks (MB), from /proc/self/status.
  double peak_memory_per_rank(const MPI_Comm communicator)
  {
    std::ifstream file("/proc/self/status");
    std::string   key;
    double        kilobytes = 0;
    while (file >> key)
      if (key == "VmHWM:")
        file >> kilobytes;
    MPI_Allreduce(MPI_IN_PLACE, &kilobytes, 1, MPI_DOUBLE, MPI_MAX, communicator);
    return kilobytes / 1024;
  }

  // Polonsky and Keer's residual of a solution: the rms gap C p - h + const
  // on the contact points and overlap elsewhere, in units of the rms height.
  double gap_residual(const FourierTransform &transform, const GridField &h, const ContactSolution &solution,
                      const double E_star)
  {
    const auto compliance = transform.tabulate([=](const Wavevector &q) {
      return std::complex<double>(q.kx == 0 && q.ky == 0 ? 0. : 2 / (E_star * q.norm()));
    });
    GridField  implied;
    transform.apply(compliance, solution.pressure, implied);
    const double n     = transform.grid().n_points();
    double       shift = 0, contact = 0, h_mean = 0, h_square = 0;
    for (std::size_t i = 0; i < h.size(); ++i)
      {
        if (solution.gap[i] == 0)
          {
            shift += implied[i] - h[i];
            ++contact;
          }
        h_mean += h[i] / n;
        h_square += h[i] * h[i] / n;
      }
    const auto sums   = transform.sums(shift, contact, h_mean, h_square);
    double     square = 0;
    for (std::size_t i = 0; i < h.size(); ++i)
      {
        const double g = implied[i] - h[i] - sums[0] / sums[1];
        square += solution.gap[i] == 0 ? g * g : std::pow(std::min(g, 0.), 2);
      }
    return std::sqrt(transform.sum(square) / n) / std::sqrt(sums[3] - sums[2] * sums[2]);
  }
} // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  const MPI_Comm world = MPI_COMM_WORLD;
  int            rank, ranks;
  MPI_Comm_rank(world, &rank);
  MPI_Comm_size(world, &ranks);
  // Rank 0 prints.
  const auto print = [&](const char *format, auto... values) {
    if (rank == 0)
      {
        std::printf(format, values...);
        std::fflush(stdout);
      }
  };
  int status = 0;
  try
    {
      Planning                  planning = Planning::estimate;
      SplitTransform            how      = SplitTransform::shared_memory;
      std::vector<unsigned int> sizes;
      bool                      adhesive = false;
      std::vector<std::string>  problems; // of the adhesive table
      for (int k = 1; k < argc; ++k)
        if (std::strcmp(argv[k], "measure") == 0)
          planning = Planning::measure;
        else if (std::strcmp(argv[k], "fftw-mpi") == 0)
          how = SplitTransform::fftw_mpi;
        else if (std::strcmp(argv[k], "adhesive") == 0)
          adhesive = true;
        else if (adhesive)
          {
            if (std::strcmp(argv[k], "johnson") != 0 && std::strcmp(argv[k], "sphere") != 0 &&
                std::strcmp(argv[k], "random") != 0)
              throw std::invalid_argument(std::string("benchmark_contact adhesive: '") + argv[k] +
                                          "' is none of the problems 'johnson', 'sphere', 'random'");
            problems.push_back(argv[k]);
          }
        else
          {
            // The adhesive solve's cohesive zone, lambda0/64, needs 4 grid spacings.
            char         *end;
            const long    n        = std::strtol(argv[k], &end, 10);
            constexpr int smallest = 256;
            if (end == argv[k] || *end != '\0' || n < smallest || n > 65536)
              throw std::invalid_argument(std::string("benchmark_contact: '") + argv[k] +
                                          "' is neither 'measure', 'fftw-mpi' nor a grid size N in [" +
                                          std::to_string(smallest) + ", 65536]");
            sizes.push_back(n);
          }
      if (adhesive && !sizes.empty())
        throw std::invalid_argument(
            "benchmark_contact: grid sizes are for the adhesionless table, not 'adhesive'");
      if (adhesive && how == SplitTransform::fftw_mpi)
        throw std::invalid_argument(
            "benchmark_contact: 'fftw-mpi' splits the adhesionless table's grids, not 'adhesive' "
            "(one rank)");
      if (adhesive)
        adhesive_benchmark(problems, planning);
      if (sizes.empty() && !adhesive)
        sizes = {256, 512, 1024, 2048, 4096};

      const double               lambda0 = 1e-3, E_star = 1e7 / (1 - 0.49 * 0.49);
      const PowerSpectrum        spectrum = power_law_spectrum(0.75, 2 * M_PI / lambda0, 32, 0.01 * lambda0);
      const ContactSolverControl control{5000, 1e-8};
      for (const unsigned int n : sizes)
        {
          const PeriodicGrid     grid = square_grid(n, lambda0);
          const FourierTransform transform(grid, planning, world, how);
          if (n == sizes.front())
            {
              print("# FFTW planning: %s; ranks: %d (grid split: %s); load average at the start %s\n",
                    planning == Planning::measure ? "measure" : "estimate", ranks,
                    !transform.split()          ? "no"
                    : transform.shares_memory() ? "in shared memory"
                                                : "by FFTW's MPI plans",
                    load_average().c_str());
              print("# %5s | %5s %8s %9s %9s %7s %9s | %11s %8s | %5s %8s | %5s %8s %7s | %7s | %s\n", "N",
                    "iter", "time(s)", "s/iter", "s/conv", "iter/c", "old res", "cold iter", "time(s)",
                    "iter6", "time6(s)", "iterA", "timeA(s)", "A_nc", "MB/rank", "load average");
            }
          const GridField h = gaussian_field(transform, spectrum, realisation_seed(1, 0));
          const double    sqrt_V =
              std::sqrt(lattice_moments(grid, pressure_spectrum(spectrum, E_star)).expected.m0);
          const HalfSpaceContact contact(transform, h, E_star);

          // One convolution on its own, for the cost of an iteration in FFTs.
          const double convolution_time = penny::benchmark::convolution_time(transform);

          const auto            start = Clock::now();
          const ContactSolution single =
              contact.solve(2 * sqrt_V, control, GridField(transform.n_local_points(), 0.));
          const double          time       = seconds_since(start);
          const auto            cold_start = Clock::now();
          const ContactSolution cold       = contact.solve(2 * sqrt_V, control);
          const double          cold_time  = seconds_since(cold_start);

          std::vector<double> loads;
          for (const double ratio : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0})
            loads.push_back(ratio * sqrt_V);
          // The least time of three sweeps up to 2048^2: other programs on a
          // shared machine only ever slow a run down.
          std::vector<LoadStep> steps;
          double                sweep_time = std::numeric_limits<double>::infinity();
          for (unsigned int sweep = 0; sweep < (n <= 2048 ? 3u : 1u); ++sweep)
            {
              const auto sweep_start = Clock::now();
              steps                  = load_sweep(contact, loads, control);
              sweep_time             = std::min(sweep_time, seconds_since(sweep_start));
            }
          unsigned int sweep_iterations = 0;
          for (const LoadStep &step : steps)
            sweep_iterations += step.iterations;

          const double           zone = lambda0 / 64, strength = sqrt_V / 2;
          const double           w = M_PI * strength * strength * zone / E_star;
          const HalfSpaceContact sticky(transform, h, E_star, {w, w / strength});
          const auto             adhesive_start = Clock::now();
          const ContactSolution  adhesive       = sticky.solve(2 * sqrt_V, control, single.gap);
          const double           adhesive_time  = seconds_since(adhesive_start);

          const double old_residual = gap_residual(transform, h, single, E_star);
          const double memory       = peak_memory_per_rank(world);
          print(
              "  %5u | %5u %8.2f %9.4f %9.4f %7.2f %9.1e | %4u + %4.1f %8.2f | %5u %8.2f | %5u %8.2f %7.4f | "
              "%7.0f | %s\n",
              n, single.iterations, time, time / single.iterations, convolution_time,
              time / single.iterations / convolution_time, old_residual, cold.iterations,
              cold.coarse_iterations, cold_time, sweep_iterations, sweep_time, adhesive.iterations,
              adhesive_time, 1 - adhesive.contact_fraction, memory, load_average().c_str());
          const auto result = [&](const char *solve, const double noncontact, const double mean_gap) {
            print("# result %u %s A_nc %.17g mean_gap %.17g\n", n, solve, noncontact, mean_gap);
          };
          result("single", 1 - single.contact_fraction, single.mean_gap);
          result("cold", 1 - cold.contact_fraction, cold.mean_gap);
          for (const LoadStep &step : steps)
            result(("load_" + std::to_string(step.mean_pressure / sqrt_V).substr(0, 3)).c_str(),
                   step.noncontact_fraction, step.mean_gap);
          result("adhesive", 1 - adhesive.contact_fraction, adhesive.mean_gap);
        }
      if (!sizes.empty())
        print(
            "%s",
            "# iter, time: adhesionless at 2 sqrt(V) from full contact; s/conv: one r2c + c2r pair in double "
            "precision;\n# iter/c: the time of an iteration in those convolutions (an iteration does 2.5 in "
            "single precision); old res: the gap residual of Polonsky and Keer's definition;\n# cold iter: "
            "the cold start's iterations on N^2 + on the halved grids in units of N^2 iterations; iter6, "
            "time6: the six loads 3 ... 0.5 sqrt(V) (load_sweep; the least time of three sweeps up to "
            "N = 2048);\n# iterA, timeA, A_nc: adhesive at 2 sqrt(V) from the adhesionless state; MB/rank: "
            "the largest peak memory of a rank\n");
    }
  catch (const std::exception &error)
    {
      if (rank == 0)
        std::fprintf(stderr, "%s\n", error.what());
      status = 1;
    }
  MPI_Finalize();
  return status;
}
