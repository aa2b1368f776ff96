// The 3D elastic operator a(u, v) = int sigma(u):e(v) dV on the DoFHandler of
// one degree, applied cell by cell from the shape functions' tensor-product
// structure (deal.II's MatrixFree, sum factorisation), the identity on
// constrained entries: the operator of each level of the matrix-free
// multigrid (fe/matrix_free_elasticity.h). Its file is compiled at this
// machine's SIMD width, several cells at once (penny_native_simd() in
// CMakeLists.txt), so nothing of MatrixFree appears here.
#pragma once

#include "fe/elasticity.h"

#include <deal.II/base/subscriptor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <memory>

namespace penny
{
  // Number: double for the system's operator, float for the multigrid's
  // levels (half the bytes per cell and twice the cells per SIMD register).
  template <typename Number> class ElasticOperator : public dealii::Subscriptor
  {
  public:
    using value_type = Number;
    using Vector     = dealii::LinearAlgebra::distributed::Vector<Number>;

    ElasticOperator();
    ~ElasticOperator() override;

    // With degree + extra_points Gauss points per direction.
    void reinit(const dealii::Mapping<3> &mapping, const dealii::DoFHandler<3> &dof_handler,
                const dealii::AffineConstraints<Number> &constraints, const IsotropicElasticity &elasticity,
                unsigned int extra_points);

    void                            initialize_dof_vector(Vector &v) const;
    dealii::types::global_dof_index m() const;
    // Chebyshev's interface names the entries, for a diagonal not given to
    // it; ours always is (compute_inverse_diagonal).
    Number el(dealii::types::global_dof_index, dealii::types::global_dof_index) const;

    void vmult(Vector &dst, const Vector &src) const;
    void Tvmult(Vector &dst, const Vector &src) const { vmult(dst, src); }

    // 1/A_ii, 1 on the constrained entries: Chebyshev's preconditioner.
    // Throws if a mapped cell is inverted at a quadrature point.
    void compute_inverse_diagonal(Vector &inverse) const;

    // The assembled matrix, for the coarsest degree's direct solve (from the
    // float operator, entries to single precision: a preconditioner's).
    void assemble(dealii::TrilinosWrappers::SparseMatrix  &matrix,
                  const dealii::AffineConstraints<Number> &constraints) const;

  private:
    struct Cells;
    std::unique_ptr<Cells> cells;
  };
} // namespace penny
