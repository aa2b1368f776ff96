// Independent pieces of work spread over the ranks of an MPI communicator:
// the FE models of a batch of gap sizes, the searches of a sweep, the cases
// of a study, realisations of a random field (each a function of its index
// alone). Every rank receives the results in index order, so every reduction
// over them is the same on any number of ranks. On MPI_COMM_SELF it is a
// plain loop.
#pragma once

#include <mpi.h>

#include <cstring>
#include <functional>
#include <type_traits>
#include <vector>

namespace penny
{
  // Each rank computes pieces until none is left, drawing the next index
  // from a counter on rank 0 whenever it is free (dynamic scheduling: pieces
  // of unequal cost balance themselves); piece(i) must depend on i alone.
  // Each result is a row of doubles (any length). Returns all rows, indexed
  // by piece, on every rank. If a piece throws, the ranks stop drawing and
  // all throw it together (throw_on_every_rank).
  std::vector<std::vector<double>>
  spread_over_ranks(MPI_Comm communicator, unsigned int n,
                    const std::function<std::vector<double>(unsigned int)> &piece);

  // The same with each result a struct of doubles (two K_I, say), which
  // travels as its doubles.
  template <typename Row, typename Piece>
  std::vector<Row> spread_over_ranks(const MPI_Comm communicator, const unsigned int n, Piece &&piece)
  {
    static_assert(std::is_trivially_copyable_v<Row> && sizeof(Row) % sizeof(double) == 0,
                  "a row travels as its doubles");
    const auto       rows = spread_over_ranks(communicator, n, [&](const unsigned int i) {
      const Row           row = piece(i);
      std::vector<double> values(sizeof(Row) / sizeof(double));
      std::memcpy(values.data(), &row, sizeof(Row));
      return values;
    });
    std::vector<Row> result(n);
    for (unsigned int i = 0; i < n; ++i)
      std::memcpy(&result[i], rows[i].data(), sizeof(Row));
    return result;
  }

  // The ranks of this run on this machine, which share its memory while they
  // build their pieces at once: as the launcher tells each rank (Open MPI's
  // OMPI_COMM_WORLD_LOCAL_SIZE, MPICH's MPI_LOCALNRANKS), 1 without one. No
  // communication, so a piece on one rank alone may ask.
  unsigned int ranks_on_this_machine();
} // namespace penny
