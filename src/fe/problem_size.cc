#include "fe/problem_size.h"

#include "input/input_error.h"
#include "parallel/spread_over_ranks.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

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

  AvailableMemory available_memory(const unsigned int sharing)
  {
    double        machine = std::numeric_limits<double>::infinity();
    std::string   key;
    double        value;
    std::string   unit;
    std::ifstream meminfo("/proc/meminfo");
    while (meminfo >> key >> value >> unit)
      if (key == "MemAvailable:")
        machine = value * 1024;
    // cgroup v2: the limit and what the group uses now.
    std::ifstream limit_file("/sys/fs/cgroup/memory.max"), usage_file("/sys/fs/cgroup/memory.current");
    double        limit, usage;
    std::string   machine_limit = "the machine's available memory";
    if (limit_file >> limit && usage_file >> usage && limit - usage < machine)
      {
        machine       = std::max(0., limit - usage);
        machine_limit = "the free part of the cgroup's memory limit";
      }
    if (sharing > 1)
      machine_limit += ", shared by " + std::to_string(sharing) + " ranks";
    // The address space left: the limit (each process its own) less what
    // the process maps already.
    double own = std::numeric_limits<double>::infinity();
    rlimit address_space;
    if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY)
      own = std::max(0., double(address_space.rlim_cur) - mapped_memory());
    if (own < machine / sharing)
      return {own, "the free part of each process's address-space limit (ulimit -v)"};
    return {machine / sharing, machine_limit};
  }

  double mapped_memory()
  {
    std::ifstream statm("/proc/self/statm");
    double        pages = 0;
    statm >> pages;
    return pages * sysconf(_SC_PAGESIZE);
  }

  void check_problem_size(const ProblemSize &size, const std::string &entries, const MPI_Comm communicator)
  {
    // Every rank of the run on this machine builds its model at the same time.
    const unsigned int sharing = ranks_on_this_machine();
    // Libraries allocate later what no estimate counts (OpenBLAS's buffers:
    // 128 MB on its first product).
    constexpr double library_reserve = 256. * 1024 * 1024;
    // Rank 0 decides for all; the limit named is each rank's own.
    const AvailableMemory available = available_memory(sharing);
    const double          budget    = dealii::Utilities::MPI::broadcast(
                    communicator, memory_share * std::max(0., available.bytes - library_reserve), 0);
    if (size.bytes <= budget)
      return;
    const auto gib = [](const double bytes) {
      std::ostringstream text;
      text.precision(3);
      text << bytes / (1024. * 1024 * 1024) << " GiB";
      return text.str();
    };
    std::ostringstream message;
    message.precision(2);
    message << entries << ": about " << size.cells << " cells, " << size.dofs << " degrees of freedom and "
            << gib(size.bytes) << (sharing > 1 ? " per rank; each rank" : "; this run") << " may use "
            << gib(budget) << " (" << memory_share * 100 << " % of " << available.limit << ", after "
            << gib(library_reserve) << " for the libraries)";
    throw InputError(message.str());
  }
} // namespace penny
