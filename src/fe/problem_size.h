// How large a model will be, known before it is built: the degrees of
// freedom, matrix entries and memory that follow from its cells, held
// against the memory this run can get (parallel/memory_budget.h).
#pragma once

#include "fe/linear_elastic_system.h"
#include "parallel/memory_budget.h"

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

  // Throws InputError, naming `entries`, if `size` (per rank) needs more than
  // memory_share of the memory available to each rank of the run on this
  // machine (they build their models at the same time), less a reserve for
  // the libraries. Collective on
  // `communicator`: its rank 0 decides.
  void check_problem_size(const ProblemSize &size, const std::string &entries, MPI_Comm communicator);
} // namespace penny
