// The finite-element model of one penny gap: axisymmetric linear elasticity
// on the half model z >= 0 with the gap faces loaded (physics.md section 2).
// The stiffness matrix is assembled and factorised once; each load is one
// more right-hand side and one more solve.
#pragma once

#include "face_load.h"
#include "parameters.h"

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

namespace penny
{
  struct SolveReport
  {
    double       relative_residual; // |A u - b| / |b|
    unsigned int iterations;        // 0 for the direct solver
    double       condition_estimate; // of the preconditioned matrix, from CG; 0 for the direct solver
  };

  class PennyGapModel
  {
  public:
    // Builds the mesh, the constraints and the factorised stiffness matrix.
    PennyGapModel(const Parameters &parameters, dealii::TimerOutput &timer);

    // The displacement (u_r, u_z) under the face traction `load`. Throws if the
    // solve misses the tolerance or produces NaN/Inf.
    dealii::Vector<double> solve(const FaceLoad &load);

    const SolveReport                &last_solve() const { return report; }
    const dealii::DoFHandler<2>      &dof_handler() const { return dofs; }
    const dealii::Triangulation<2>   &triangulation() const { return mesh; }
    const dealii::FESystem<2>        &finite_element() const { return fe; }
    const Parameters                 &parameters() const { return prm; }

    // u_z at the centre of the gap face: the opening of one face at r = 0.
    double opening_at_centre(const dealii::Vector<double> &u) const;
    // Volume between the two faces, 2 int_0^c 2 pi r u_z dr.
    double gap_volume(const dealii::Vector<double> &u) const;

  private:
    void setup_system();
    void assemble_matrix();
    void factorise();

    const Parameters     prm;
    dealii::TimerOutput &timer;

    dealii::Triangulation<2>          mesh;
    const dealii::FESystem<2>         fe;
    dealii::DoFHandler<2>             dofs;
    dealii::AffineConstraints<double> constraints;
    dealii::SparsityPattern           sparsity;
    dealii::SparseMatrix<double>      stiffness;

    dealii::SparseDirectUMFPACK            direct_solver;
    dealii::TrilinosWrappers::SparseMatrix trilinos_stiffness;
    dealii::TrilinosWrappers::PreconditionAMG amg;

    SolveReport report{};
  };
} // namespace penny
