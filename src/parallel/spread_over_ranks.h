// Independent pieces of work spread over the ranks of an MPI communicator:
// the FE models of a batch of gap sizes, the searches of a sweep, the cases
// of a study, realisations of a random field (each a function of its index
// alone). Every rank receives the results in index order, so every reduction
// over them is the same on any number of ranks. On MPI_COMM_SELF it is a
// plain loop.
#pragma once

#include <mpi.h>

#include <functional>
#include <vector>

namespace penny
{
  // Each rank computes pieces until none is left, drawing the next index
  // from a counter on rank 0 whenever it is free (dynamic scheduling: pieces
  // of unequal cost balance themselves); piece(i) must depend on i alone.
  // Each result is a row of doubles (any length). Returns all rows, indexed
  // by piece, on every rank.
  std::vector<std::vector<double>>
  spread_over_ranks(MPI_Comm communicator, unsigned int n,
                    const std::function<std::vector<double>(unsigned int)> &piece);

  // The ranks of this run on this machine, which share its memory while they
  // build their pieces at once: as the launcher tells each rank (Open MPI's
  // OMPI_COMM_WORLD_LOCAL_SIZE, MPICH's MPI_LOCALNRANKS), 1 without one. No
  // communication, so a piece on one rank alone may ask.
  unsigned int ranks_on_this_machine();
} // namespace penny
