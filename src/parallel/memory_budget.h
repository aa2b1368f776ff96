// The memory a run may take, known before it allocates: what this machine,
// its cgroup and the process's own limit leave, shared by the ranks that run
// here. A model or grid that would not fit is refused with one line naming
// the entries that make it large, instead of ending in std::bad_alloc after
// minutes of work.
#pragma once

#include <mpi.h>

#include <string>

namespace penny
{
  // The memory a process of this run can get: MemAvailable of /proc/meminfo
  // and the free part of the cgroup's limit, shared by `sharing` processes,
  // or the free part of its own RLIMIT_AS, whichever is least.
  struct AvailableMemory
  {
    double      bytes;
    std::string limit; // which of them binds, for messages
  };
  AvailableMemory available_memory(unsigned int sharing = 1);

  // The address space this process maps now (bytes).
  double mapped_memory();

  // The share of the available memory a model may take.
  constexpr double memory_share = 0.75;

  // Throws InputError "NEED X GiB per rank; each rank may use Y GiB (...)"
  // if `bytes` (per rank) is more than memory_share of the memory available
  // to each rank of the run on this machine (they build at the same time),
  // less a reserve for the libraries. `need` names the entries and what they
  // make: "Grid points per side = 16384: 2.7e+08 points need about".
  // Collective on `communicator`: its rank 0 decides.
  void check_memory_need(double bytes, const std::string &need, MPI_Comm communicator);

  // The same for an N x N grid of `bytes_per_point` a point per rank (each
  // scene's, measured), named by `entries`: "ENTRIES: N^2 grid points need about ...".
  void check_grid_memory(unsigned int n_points, double bytes_per_point, const std::string &entries,
                         MPI_Comm communicator);
} // namespace penny
