#include "fe/elastic_diagonal.h"

#include <array>
#include <stdexcept>
#include <vector>

namespace penny
{
  using namespace dealii;

  template <typename Number>
  void integrate_elastic_cell(ElasticEvaluation<Number> &phi, const IsotropicElasticity &elasticity)
  {
    const Number mu = elasticity.mu, lambda = elasticity.lambda;
    phi.evaluate(EvaluationFlags::gradients);
    for (const unsigned int q : phi.quadrature_point_indices())
      {
        const auto e = phi.get_symmetric_gradient(q);
        phi.submit_symmetric_gradient(
            2 * mu * e + lambda * trace(e) * unit_symmetric_tensor<3, VectorizedArray<Number>>(), q);
      }
    phi.integrate(EvaluationFlags::gradients);
  }

  namespace
  {
    // One step of sum factorisation: out = in contracted with the 1D matrix
    // f[m nq + q] over the index of stride `stride`, for `blocks` outer
    // blocks (of nq such indices in `in`, of n in `out`); added to `out` if
    // `add`.
    template <typename Number>
    void contract(const VectorizedArray<Number> *in, const std::vector<Number> &f,
                  VectorizedArray<Number> *out, const unsigned int n, const unsigned int nq,
                  const unsigned int stride, const unsigned int blocks, const bool add)
    {
      for (unsigned int o = 0; o < blocks; ++o)
        for (unsigned int m = 0; m < n; ++m)
          for (unsigned int s = 0; s < stride; ++s)
            {
              VectorizedArray<Number> sum = 0;
              for (unsigned int q = 0; q < nq; ++q)
                sum += in[s + stride * (q + nq * o)] * f[m * nq + q];
              VectorizedArray<Number> &target = out[s + stride * (m + n * o)];
              target                          = add ? target + sum : sum;
            }
    }
  } // namespace

  template <typename Number>
  void add_elastic_diagonal(const MatrixFree<3, Number> &matrix_free, const IsotropicElasticity &elasticity,
                            LinearAlgebra::distributed::Vector<Number> &diagonal)
  {
    using Lanes = VectorizedArray<Number>;
    // The constraint pool holds the weights of each kind of tie (a fixed
    // DoF's kind has none); deal.II resolves hanging nodes of FE_Q without it.
    bool tied = matrix_free.get_dof_handler().get_triangulation().has_hanging_nodes();
    for (unsigned int i = 0; i < matrix_free.n_constraint_pool_entries(); ++i)
      tied = tied || matrix_free.constraint_pool_begin(i) != matrix_free.constraint_pool_end(i);
    if (tied)
      throw std::logic_error("add_elastic_diagonal: DoFs tied to others (hanging nodes); the diagonal "
                             "is not the sum of the cells'");
    ElasticEvaluation<Number> phi(matrix_free);
    const auto               &shape = matrix_free.get_shape_info().data[0];
    const unsigned int        n = shape.fe_degree + 1, nq = shape.n_q_points_1d, n_points = nq * nq * nq;
    const unsigned int        per_component = n * n * n;

    // The 1D factors [kind][i nq + q], kind = how many of the two gradient
    // directions a, b are this direction: f^2, f f', f'^2.
    std::array<std::vector<Number>, 3> factor;
    for (auto &f : factor)
      f.resize(n * nq);
    for (unsigned int iq = 0; iq < n * nq; ++iq)
      {
        const Number f = shape.shape_values[iq][0], df = shape.shape_gradients[iq][0];
        factor[0][iq] = f * f;
        factor[1][iq] = f * df;
        factor[2][iq] = df * df;
      }

    const Number                     mu = elasticity.mu, lambda = elasticity.lambda;
    std::vector<Tensor<2, 3, Lanes>> M(n_points);
    std::vector<Lanes>               JxW(n_points), B(n_points), along_z(nq * nq * n), along_y(nq * n * n);
    for (unsigned int cell = 0; cell < matrix_free.n_cell_batches(); ++cell)
      {
        phi.reinit(cell);
        for (unsigned int q = 0; q < n_points; ++q)
          {
            M[q]   = phi.inverse_jacobian(q);
            JxW[q] = phi.JxW(q);
          }
        Lanes *const values = phi.begin_dof_values();
        for (unsigned int c = 0; c < 3; ++c)
          {
            Lanes *const d = values + c * per_component;
            for (unsigned int i = 0; i < per_component; ++i)
              d[i] = 0;
            // The symmetric B: the entries a <= b, those off the diagonal twice.
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = a; b < 3; ++b)
                {
                  for (unsigned int q = 0; q < n_points; ++q)
                    {
                      Lanes column_product = 0;
                      for (unsigned int k = 0; k < 3; ++k)
                        column_product += M[q][k][a] * M[q][k][b];
                      B[q] = Number(a == b ? 1 : 2) * JxW[q] *
                             (mu * column_product + (lambda + mu) * M[q][c][a] * M[q][c][b]);
                    }
                  const std::vector<Number> &fx = factor[(a == 0) + (b == 0)],
                                            &fy = factor[(a == 1) + (b == 1)],
                                            &fz = factor[(a == 2) + (b == 2)];
                  // Points q = qx + nq (qy + nq qz); DoFs i + n (j + n k):
                  // qz -> k, qy -> j, qx -> i.
                  contract(B.data(), fz, along_z.data(), n, nq, nq * nq, 1, false);
                  contract(along_z.data(), fy, along_y.data(), n, nq, nq, n, false);
                  contract(along_y.data(), fx, d, n, nq, 1, n * n, true);
                }
          }
        phi.distribute_local_to_global(diagonal);
      }
    diagonal.compress(VectorOperation::add);
  }

  template void integrate_elastic_cell(ElasticEvaluation<double> &, const IsotropicElasticity &);
  template void integrate_elastic_cell(ElasticEvaluation<float> &, const IsotropicElasticity &);
  template void add_elastic_diagonal(const MatrixFree<3, double> &, const IsotropicElasticity &,
                                     LinearAlgebra::distributed::Vector<double> &);
  template void add_elastic_diagonal(const MatrixFree<3, float> &, const IsotropicElasticity &,
                                     LinearAlgebra::distributed::Vector<float> &);
} // namespace penny
