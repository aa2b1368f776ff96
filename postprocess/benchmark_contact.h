// What the two parts of benchmark_contact share: clocks, the machine's load,
// the time of one convolution, and the adhesive part's entry
// (benchmark_contact_adhesive.cc).
#pragma once

#include "fourier/fourier_transform.h"

#include <chrono>
#include <mpi.h>
#include <string>
#include <vector>

namespace penny::benchmark
{
  using Clock = std::chrono::steady_clock;

  inline double seconds_since(const Clock::time_point start)
  {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }

  // The load average of /proc/loadavg (1, 5 and 15 minutes).
  std::string load_average();

  // The wall time (s) of one convolution of the work array (an r2c and a c2r
  // FFT, the "FFT pair"), repeated for a second at least (rank 0's clock
  // decides when to stop, for all ranks).
  template <typename Real> double convolution_time(const BasicFourierTransform<Real> &transform);

  // The adhesive table: `cases` among "johnson", "sphere", "random" (all if
  // empty); prints on rank 0.
  void adhesive_benchmark(const std::vector<std::string> &cases, Planning planning);
} // namespace penny::benchmark
