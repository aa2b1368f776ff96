#include "parallel/memory_budget.h"

#include "input/input_error.h"
#include "parallel/spread_over_ranks.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

namespace penny
{
  AvailableMemory available_memory(const unsigned int sharing)
  {
    double        machine = std::numeric_limits<double>::infinity();
    std::string   key;
    double        value;
    std::string   unit;
    std::ifstream meminfo("/proc/meminfo");
    while (meminfo >> key >> value >> unit)
      if (key == "MemAvailable:")
        machine = value * 1024;
    // cgroup v2: the limit and what the group uses now.
    std::ifstream limit_file("/sys/fs/cgroup/memory.max"), usage_file("/sys/fs/cgroup/memory.current");
    double        limit, usage;
    std::string   machine_limit = "the machine's available memory";
    if (limit_file >> limit && usage_file >> usage && limit - usage < machine)
      {
        machine       = std::max(0., limit - usage);
        machine_limit = "the free part of the cgroup's memory limit";
      }
    if (sharing > 1)
      machine_limit += ", shared by " + std::to_string(sharing) + " ranks";
    // The address space left: the limit (each process its own) less what
    // the process maps already.
    double own = std::numeric_limits<double>::infinity();
    rlimit address_space;
    if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY)
      own = std::max(0., double(address_space.rlim_cur) - mapped_memory());
    if (own < machine / sharing)
      return {own, "the free part of each process's address-space limit (ulimit -v)"};
    return {machine / sharing, machine_limit};
  }

  double mapped_memory()
  {
    std::ifstream statm("/proc/self/statm");
    double        pages = 0;
    statm >> pages;
    return pages * sysconf(_SC_PAGESIZE);
  }

  void check_memory_need(const double bytes, const std::string &need, const MPI_Comm communicator)
  {
    // Every rank of the run on this machine builds at the same time.
    const unsigned int sharing = ranks_on_this_machine();
    // Libraries allocate later what no estimate counts (OpenBLAS's buffers:
    // 128 MB on its first product).
    constexpr double library_reserve = 256. * 1024 * 1024;
    // Rank 0 decides for all; the limit named is each rank's own.
    const AvailableMemory available = available_memory(sharing);
    const double          budget    = dealii::Utilities::MPI::broadcast(
                    communicator, memory_share * std::max(0., available.bytes - library_reserve), 0);
    if (bytes <= budget)
      return;
    const auto gib = [](const double amount) {
      std::ostringstream text;
      text.precision(3);
      text << amount / (1024. * 1024 * 1024) << " GiB";
      return text.str();
    };
    std::ostringstream message;
    message << need << " " << gib(bytes) << (sharing > 1 ? " per rank; each rank" : "; this run")
            << " may use " << gib(budget) << " (" << memory_share * 100 << " % of " << available.limit
            << ", after " << gib(library_reserve) << " for the libraries)";
    throw InputError(message.str());
  }

  void check_grid_memory(const unsigned int n_points, const double bytes_per_point,
                         const std::string &entries, const MPI_Comm communicator)
  {
    const double       points = double(n_points) * n_points;
    std::ostringstream need;
    need.precision(2);
    need << entries << ": " << points << " grid points need about";
    check_memory_need(bytes_per_point * points, need.str(), communicator);
  }
} // namespace penny
