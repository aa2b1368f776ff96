// How large a model will be, known before it is built: the degrees of
// freedom, matrix entries and memory that follow from its cells, and the
// memory this run can get. A model that would not fit is refused with one
// line naming the entries that make it large, instead of ending in
// std::bad_alloc after minutes of work.
#pragma once

#include "fe/linear_elastic_system.h"

#include <mpi.h>

#include <string>

namespace penny
{
  struct ProblemSize
  {
    double cells;
    double dofs;
    double matrix_entries;
    double bytes; // on the rank that needs most, with the factorisation of the direct solver
  };

  // The 2D (axisymmetric or periodic) model on n_ranks.
  ProblemSize problem_size(double cells, unsigned int degree, LinearSolverParameters::Type solver,
                           unsigned int n_ranks);

  // The 3D elliptical model, distributed over n_ranks.
  ProblemSize elliptical_problem_size(double cells, unsigned int degree, LinearSolverParameters::Type solver,
                                      unsigned int n_ranks);

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

  // Throws InputError, naming `entries`, if `size` (per rank) needs more than
  // memory_share of the memory available to each rank of the run on this
  // machine (they build their models at the same time), less a reserve for
  // the libraries. Collective on
  // `communicator`: its rank 0 decides.
  void check_problem_size(const ProblemSize &size, const std::string &entries, MPI_Comm communicator);
} // namespace penny
