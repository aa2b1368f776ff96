#include "parallel/collective.h"

#include "input/input_error.h"
#include "numerics/solver_failure.h"

#include <deal.II/base/mpi.h>

#include <stdexcept>
#include <string>

namespace penny
{
  void throw_on_every_rank(const MPI_Comm communicator, const std::exception_ptr failure)
  {
    int rank = 0, size = 1;
    MPI_Comm_rank(communicator, &rank);
    MPI_Comm_size(communicator, &size);
    int origin = failure ? rank : size;
    MPI_Allreduce(MPI_IN_PLACE, &origin, 1, MPI_INT, MPI_MIN, communicator);
    if (origin == size)
      return;

    // The failure's kind, message and settings, from the rank it came from.
    enum Kind : int
    {
      input,
      solver,
      other
    };
    int         kind = other;
    std::string message, settings;
    if (rank == origin)
      try
        {
          std::rethrow_exception(failure);
        }
      catch (const InputError &error)
        {
          kind    = input;
          message = error.what();
        }
      catch (const SolverFailure &error)
        {
          kind     = solver;
          message  = error.what();
          settings = error.settings;
        }
      catch (const std::exception &error)
        {
          message = error.what();
        }
      catch (...)
        {
        }
    if (message.empty())
      message = "unknown failure";
    kind     = dealii::Utilities::MPI::broadcast(communicator, kind, origin);
    message  = dealii::Utilities::MPI::broadcast(communicator, message, origin);
    settings = dealii::Utilities::MPI::broadcast(communicator, settings, origin);

    if (rank == origin)
      std::rethrow_exception(failure);
    if (kind == input)
      throw InputError(message);
    if (kind == solver)
      throw SolverFailure(message, settings);
    throw std::runtime_error(message);
  }
} // namespace penny
