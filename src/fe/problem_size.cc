#include "fe/problem_size.h"

#include "parallel/memory_budget.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace penny
{
  // Calibrated on this project's meshes (tests/test_problem_size.cc checks
  // the first two against built systems): Q_p elements with two components
  // have about 2 p (p + 1/2) degrees of freedom per cell on the graded
  // quadtree (hanging nodes add the p/2), and a row of the condensed matrix
  // holds about 2 (p + 1)(p + 3) entries. Memory, against the peak resident
  // size of penny-gap runs less the 160 MB of a run that builds nothing
  // (4e3 to 9e5 DoFs, degrees 1, 2 and 4): about 3 kB per cell on each rank
  // (the triangulation is held whole on every rank), and per matrix entry
  // 110 bytes with a direct solver (measured with UMFPACK's LU: the matrix,
  // its serial copy and the factors, whose fill grows slowly with the size;
  // CHOLMOD's Cholesky factors take less) or 50 bytes with CG and AMG. The
  // estimate lies 10-50 % above what was measured.
  ProblemSize problem_size(const double cells, const unsigned int degree,
                           const LinearSolverParameters::Type solver, const unsigned int n_ranks)
  {
    ProblemSize  size;
    const double p               = degree;
    size.cells                   = cells;
    size.dofs                    = 2 * p * (p + 0.5) * cells;
    size.matrix_entries          = size.dofs * 2 * (p + 1) * (p + 3);
    const double fill            = 1 + 0.05 * std::max(0., std::log2(size.dofs / 2e4));
    const double bytes_per_entry = solver == LinearSolverParameters::Type::direct ? 110 * fill : 50;
    // The triangulation is whole on each rank; the direct solver gathers the
    // matrix and its factors on one, AMG spreads them.
    const double ranks_sharing = solver == LinearSolverParameters::Type::direct ? 1. : n_ranks;
    size.bytes                 = 3e3 * cells + bytes_per_entry * size.matrix_entries / ranks_sharing;
    return size;
  }

  // Calibrated on the elliptical model (b/a = 0.5 to 0.1, degrees 1 to 5, 5472
  // to 43776 cells, peak resident size less the 170 MB of a run that builds
  // nothing; the estimate lies from 5 % below to 50 % above): Q_p with three
  // components has 3 p^2 (p + 0.18) degrees of freedom per cell, and a row of
  // the matrix couples 3 (p + 2)^3 entries (the mean over vertex, edge, face
  // and interior nodes). Per matrix entry 55 bytes with CG and AMG (its
  // hierarchy included); 70 bytes with a direct solver, plus the factors'
  // fill, 110 N^(4/3) bytes for N DoFs (nested dissection in 3D; CHOLMOD, 2e4
  // to 1.4e5 DoFs, degrees 1 and 2). Matrix-free p-multigrid holds no matrix
  // but its levels' mapping data, 400 + 2000/p bytes per DoF, and the direct
  // solver of its degree-1 level. The triangulation adds about 3 kB per cell,
  // spread over the ranks like the rest.
  ProblemSize elliptical_problem_size(const double cells, const unsigned int degree,
                                      const LinearSolverParameters::Type solver, const unsigned int n_ranks)
  {
    using Type                   = LinearSolverParameters::Type;
    const auto dofs_of_degree    = [cells](const double p) { return 3 * p * p * (p + 0.18) * cells; };
    const auto entries_of_degree = [&](const double p) { return dofs_of_degree(p) * 3 * std::pow(p + 2, 3); };
    const auto direct_bytes      = [&](const double p) {
      return 70 * entries_of_degree(p) + 110 * std::pow(dofs_of_degree(p), 4. / 3);
    };
    ProblemSize  size;
    const double p      = degree;
    size.cells          = cells;
    size.dofs           = dofs_of_degree(p);
    size.matrix_entries = solver == Type::cg_multigrid ? 0 : entries_of_degree(p);
    // Spread over the ranks, and gathered on one by the direct solvers.
    double spread = 3e3 * cells, gathered = 0;
    if (solver == Type::direct)
      gathered = direct_bytes(p);
    if (solver == Type::cg_amg)
      spread += 55 * size.matrix_entries;
    if (solver == Type::cg_multigrid)
      {
        spread += (400 + 2000 / p) * size.dofs;
        gathered = direct_bytes(1);
      }
    size.bytes = spread / n_ranks + gathered;
    return size;
  }

  void check_problem_size(const ProblemSize &size, const std::string &entries, const MPI_Comm communicator)
  {
    std::ostringstream need;
    need.precision(2);
    need << entries << ": about " << size.cells << " cells, " << size.dofs << " degrees of freedom and";
    check_memory_need(size.bytes, need.str(), communicator);
  }
} // namespace penny
