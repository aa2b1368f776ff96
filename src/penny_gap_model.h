// The finite-element model of one penny gap: axisymmetric linear elasticity
// on the half model z >= 0 with the gap faces loaded (physics.md section 2).
// Cells, degrees of freedom and the Trilinos matrix are partitioned over the MPI
// ranks (the step-40 pattern); one rank is the serial case. The mesh itself is
// a parallel::shared::Triangulation, held whole on every rank: p4est, behind
// parallel::distributed, stops at 29 refinement levels below a coarse cell,
// and a quadtree from cells of 256 c down to tips of 1e-9 c needs 38. The stiffness
// matrix is assembled and factorised once; each load is one more right-hand
// side and one more solve.
#pragma once

#include "face_load.h"
#include "parameters.h"

#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

namespace penny
{
  // (u_r, u_z) with the ghost entries each rank needs to evaluate its cells.
  using DisplacementVector = dealii::TrilinosWrappers::MPI::Vector;

  struct SolveReport
  {
    double       relative_residual;  // |A u - b| / |b|
    unsigned int iterations;         // 0 for the direct solver
    double       condition_estimate; // of the preconditioned matrix, from CG; 0 for the direct solver
  };

  class PennyGapModel
  {
  public:
    // Builds the mesh, the constraints and the factorised stiffness matrix.
    PennyGapModel(const Parameters &parameters, dealii::TimerOutput &timer);

    // The displacement under the face traction `load`. Throws if the solve
    // misses the tolerance or produces NaN/Inf.
    DisplacementVector solve(const FaceLoad &load);

    const SolveReport                                 &last_solve() const { return report; }
    const dealii::DoFHandler<2>                       &dof_handler() const { return dofs; }
    const dealii::parallel::shared::Triangulation<2>  &triangulation() const { return mesh; }
    const dealii::FESystem<2>                         &finite_element() const { return fe; }
    const Parameters                                  &parameters() const { return prm; }

    // Refines the `fraction` of cells with the largest Kelly indicators of u
    // (the same cells on every rank), then rebuilds and factorises the system.
    void refine_by_kelly(const DisplacementVector &u, double fraction);

    // u_z at the centre of the gap face: the opening of one face at r = 0.
    double opening_at_centre(const DisplacementVector &u) const;
    // Volume between the two faces, 2 int_0^c 2 pi r u_z dr.
    double gap_volume(const DisplacementVector &u) const;

  private:
    void setup_system();
    void assemble_matrix();
    void factorise();
    // x = A^-1 b with the factorisation or the preconditioned CG.
    void apply_inverse(dealii::TrilinosWrappers::MPI::Vector       &x,
                       const dealii::TrilinosWrappers::MPI::Vector &b);

    const Parameters     prm;
    dealii::TimerOutput &timer;

    dealii::parallel::shared::Triangulation<2>      mesh;
    const dealii::FESystem<2>                       fe;
    dealii::DoFHandler<2>                           dofs;
    dealii::IndexSet                                owned, relevant;
    dealii::AffineConstraints<double>               constraints;
    dealii::TrilinosWrappers::SparseMatrix          stiffness;

    // Direct solvers: UMFPACK on one rank (on a copy of the matrix), MUMPS on several.
    dealii::SparsityPattern                               serial_sparsity;
    dealii::SparseMatrix<double>                          serial_stiffness;
    dealii::SparseDirectUMFPACK                           umfpack;
    dealii::SolverControl                                 mumps_control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> mumps;
    dealii::TrilinosWrappers::PreconditionAMG             amg;

    SolveReport report{};
  };
} // namespace penny
