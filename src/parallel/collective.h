// Errors that reach every MPI rank: work done on rank 0 alone (files, child
// processes) reports its failure to all ranks, which throw it together.
#pragma once

#include "input/input_error.h"

#include <deal.II/base/mpi.h>

#include <exception>
#include <stdexcept>
#include <string>

namespace penny
{
  // Runs `action` on rank 0 of `communicator`; the message of an exception it
  // throws reaches every rank, where it is thrown again (as InputError if it
  // was one). Collective.
  template <typename Action> void run_on_rank_zero(const MPI_Comm communicator, Action &&action)
  {
    std::string message;
    bool        input_error = false;
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      try
        {
          action();
        }
      catch (const InputError &error)
        {
          message     = error.what();
          input_error = true;
        }
      catch (const std::exception &error)
        {
          message = error.what();
          if (message.empty())
            message = "unknown failure";
        }
    message     = dealii::Utilities::MPI::broadcast(communicator, message, 0);
    input_error = dealii::Utilities::MPI::broadcast(communicator, input_error, 0);
    if (message.empty())
      return;
    if (input_error)
      throw InputError(message);
    throw std::runtime_error(message);
  }
} // namespace penny
