// 3D elasticity without an assembled matrix: the operator a(u, v) = int
// sigma(u):e(v) dV evaluated cell by cell from the shape functions'
// tensor-product structure (fe/elastic_operator.h), and
// conjugate gradients preconditioned by one V-cycle of polynomial multigrid:
// the same mesh with the degrees p, p/2, ..., 1 (each evaluated with one
// Gauss point per direction fewer than the system's operator, in single
// precision), Chebyshev smoothing with the operator's diagonal on each, and
// on degree 1 a sparse direct solve (MUMPS) of the assembled matrix, which
// is small (one node per vertex). The cost of an operator application grows like p^4 per cell
// instead of the assembled matrix's p^6, and the memory is that of a few
// vectors: what high degrees in 3D need.
#pragma once

#include "fe/elasticity.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>

namespace penny
{
  class MatrixFreeElasticity
  {
  public:
    // Sets the constraints of one degree's DoFHandler (zero displacements).
    using Constrain = std::function<void(const dealii::DoFHandler<3> &, dealii::AffineConstraints<double> &)>;

    // `dof_handler` holds one FESystem of degree p; its `constraints` (closed)
    // and `constrain` for the coarser degrees. Quadrature: p + 2 Gauss points
    // per direction, as the assembled matrix.
    MatrixFreeElasticity(const dealii::DoFHandler<3>             &dof_handler,
                         const dealii::AffineConstraints<double> &constraints,
                         const dealii::Mapping<3> &mapping, const Constrain &constrain,
                         const IsotropicElasticity &elasticity);
    ~MatrixFreeElasticity();

    // dst = A src on the unconstrained entries.
    void vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
               const dealii::TrilinosWrappers::MPI::Vector &src) const;

    // x = A^-1 b by CG from x to `control`'s tolerance; the estimate of the
    // preconditioned matrix's condition number goes to `condition`. Throws
    // SolverControl::NoConvergence.
    void solve(dealii::TrilinosWrappers::MPI::Vector &x, const dealii::TrilinosWrappers::MPI::Vector &b,
               dealii::SolverControl &control, const std::function<void(double)> &condition);

  private:
    struct Hierarchy;
    std::unique_ptr<Hierarchy> hierarchy;
  };
} // namespace penny
