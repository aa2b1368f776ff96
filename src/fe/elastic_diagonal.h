// The diagonal of the 3D elastic operator a(u, v) = int sigma(u):e(v) dV,
// the Chebyshev smoother's preconditioner in the matrix-free multigrid, by
// sum factorisation.
//
// For the shape function phi e_c (component c) with physical gradient
// g = M grad phi, M = J^-T, the strain is sym(e_c (x) g) and
//   sigma : e = mu |g|^2 + (lambda + mu) g_c^2 = grad phi . B grad phi,
//   B = mu M^T M + (lambda + mu) m_c (x) m_c   (m_c the row c of M),
// a quadratic form in the reference gradient. On a tensor-product element
// the reference gradient of phi_ijk = f_i(x) f_j(y) f_k(z) has the entries
// f_i' f_j f_k, f_i f_j' f_k, f_i f_j f_k', so each entry B_ab adds
//   sum over the quadrature points q of JxW B_ab(q) u_i(q_x) v_j(q_y) w_k(q_z),
// u, v, w each one of f^2, f f', f'^2 as a and b pick its direction: three
// one-dimensional contractions per entry, about 50,000 operations a Q4 cell.
// deal.II's MatrixFreeTools::compute_diagonal applies the cell operator to
// every unit vector instead, one cell evaluation per DoF (375 at Q4): 42 s
// of a 97 s Q4 solve phase on one rank at 1.4 M DoFs.
#pragma once

#include "fe/elasticity.h"

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>

namespace penny
{
  // The cell evaluation of one FESystem of FE_Q (three components), its
  // degree and points known at run time (deal.II's kernels for degrees 1 to
  // 6 and a generic one above, instantiated at this machine's SIMD width in
  // fe/cell_kernel_instances_*.cc).
  // Number: double for the system's operator, float for the multigrid's.
  template <typename Number> using ElasticEvaluation = dealii::FEEvaluation<3, -1, 0, 3, Number>;

  // The cell's sigma(u) : e(v) from the values in `phi`, integrated back
  // into it: the matrix-free operator's cell kernel, whose diagonal
  // add_elastic_diagonal computes.
  template <typename Number>
  void integrate_elastic_cell(ElasticEvaluation<Number> &phi, const IsotropicElasticity &elasticity);

  // Adds the diagonal of a(u, v) over the cells of `matrix_free` (one
  // FESystem of FE_Q, three components) into `diagonal`, which
  // MatrixFree::initialize_dof_vector made; constrained entries are left as
  // they were. The constraints must fix DoFs (zero displacements) and tie
  // none to others (no hanging nodes): a tied DoF's diagonal is not the sum
  // of its cells' (std::logic_error).
  template <typename Number>
  void add_elastic_diagonal(const dealii::MatrixFree<3, Number>                &matrix_free,
                            const IsotropicElasticity                          &elasticity,
                            dealii::LinearAlgebra::distributed::Vector<Number> &diagonal);
} // namespace penny
