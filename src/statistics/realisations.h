// Independent realisations of a random field spread over the ranks of an MPI
// communicator. Each realisation is a function of its index alone (its seed
// is realisation_seed(seed, index)), and every rank receives the results in
// index order, so every reduction over them is the same on any number of ranks.
// (Realisations are whole grids on one rank; FFTW's MPI grid splitting is not
// used: a 1024^2 grid and its work arrays take a few tens of MB.)
#pragma once

#include <mpi.h>

#include <functional>
#include <vector>

namespace penny
{
  // Rank r computes the indices r, r + size, r + 2 size, ... < n_realisations;
  // each result is a row of doubles (any length). Returns all rows, indexed by
  // realisation, on every rank.
  std::vector<std::vector<double>>
  gather_realisations(MPI_Comm communicator, unsigned int n_realisations,
                      const std::function<std::vector<double>(unsigned int)> &realisation);
} // namespace penny
