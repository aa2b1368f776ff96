// Errors that reach every MPI rank: work done on some ranks only (files and
// child processes on rank 0, pieces of work spread over the ranks) reports
// its failure to all ranks, which throw it together.
#pragma once

#include <mpi.h>

#include <exception>

namespace penny
{
  // `failure` is the exception a rank caught, null where none. Collective:
  // if any rank failed, every rank throws the failure of the lowest failing
  // rank, that rank as it was, the others with its message as the same kind
  // (InputError, SolverFailure with its settings, else std::runtime_error);
  // otherwise returns.
  void throw_on_every_rank(MPI_Comm communicator, std::exception_ptr failure);

  // Runs `action` on rank 0 of `communicator`; what it throws is thrown on
  // every rank. Collective.
  template <typename Action> void run_on_rank_zero(const MPI_Comm communicator, Action &&action)
  {
    std::exception_ptr failure;
    int                rank = 0;
    MPI_Comm_rank(communicator, &rank);
    if (rank == 0)
      try
        {
          action();
        }
      catch (...)
        {
          failure = std::current_exception();
        }
    throw_on_every_rank(communicator, failure);
  }
} // namespace penny
