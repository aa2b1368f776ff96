#include "fe/elastic_operator.h"

#include "fe/elastic_diagonal.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/tools.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace penny
{
  using namespace dealii;

  template <typename Number> struct ElasticOperator<Number>::Cells
  {
    MatrixFree<3, Number> matrix_free;
    IsotropicElasticity   elasticity{};

    void integrate(ElasticEvaluation<Number> &phi) const { integrate_elastic_cell(phi, elasticity); }

    void apply(const MatrixFree<3, Number> &, Vector &dst, const Vector &src,
               const std::pair<unsigned int, unsigned int> &range) const
    {
      ElasticEvaluation<Number> phi(matrix_free);
      for (unsigned int cell = range.first; cell < range.second; ++cell)
        {
          phi.reinit(cell);
          phi.read_dof_values(src);
          integrate(phi);
          phi.distribute_local_to_global(dst);
        }
    }
  };

  template <typename Number> ElasticOperator<Number>::ElasticOperator() : cells(std::make_unique<Cells>()) {}

  template <typename Number> ElasticOperator<Number>::~ElasticOperator() = default;

  template <typename Number>
  void ElasticOperator<Number>::reinit(const Mapping<3> &mapping, const DoFHandler<3> &dof_handler,
                                       const AffineConstraints<Number> &constraints,
                                       const IsotropicElasticity &elasticity, const unsigned int extra_points)
  {
    cells->elasticity = elasticity;
    typename MatrixFree<3, Number>::AdditionalData data;
    data.tasks_parallel_scheme = MatrixFree<3, Number>::AdditionalData::none; // MPI ranks, not threads
    data.mapping_update_flags  = update_gradients;
    cells->matrix_free.reinit(mapping, dof_handler, constraints,
                              QGauss<1>(dof_handler.get_fe().degree + extra_points), data);
  }

  template <typename Number> void ElasticOperator<Number>::initialize_dof_vector(Vector &v) const
  {
    cells->matrix_free.initialize_dof_vector(v);
  }

  template <typename Number> types::global_dof_index ElasticOperator<Number>::m() const
  {
    return cells->matrix_free.get_dof_handler().n_dofs();
  }

  template <typename Number>
  Number ElasticOperator<Number>::el(types::global_dof_index, types::global_dof_index) const
  {
    throw std::logic_error("a matrix-free operator has no entries to read");
  }

  template <typename Number> void ElasticOperator<Number>::vmult(Vector &dst, const Vector &src) const
  {
    cells->matrix_free.cell_loop(&Cells::apply, cells.get(), dst, src, true);
    for (const unsigned int i : cells->matrix_free.get_constrained_dofs())
      dst.local_element(i) = src.local_element(i);
  }

  template <typename Number> void ElasticOperator<Number>::compute_inverse_diagonal(Vector &inverse) const
  {
    const MatrixFree<3, Number> &matrix_free = cells->matrix_free;
    initialize_dof_vector(inverse);
    // Hanging nodes tie DoFs to others, whose diagonal is not the sum of
    // the cells': deal.II's unit-vector loop resolves them, more slowly.
    if (matrix_free.get_dof_handler().get_triangulation().has_hanging_nodes())
      MatrixFreeTools::compute_diagonal(matrix_free, inverse, &Cells::integrate, cells.get());
    else
      add_elastic_diagonal(matrix_free, cells->elasticity, inverse);
    for (const unsigned int i : matrix_free.get_constrained_dofs())
      inverse.local_element(i) = 1;
    // A mapped cell turned inside out at a quadrature point (det J < 0)
    // makes the operator indefinite; CG cannot solve it.
    const unsigned int n_negative =
        Utilities::MPI::sum(static_cast<unsigned int>(std::count_if(inverse.begin(), inverse.end(),
                                                                    [](Number d) { return !(d > 0); })),
                            inverse.get_mpi_communicator());
    if (n_negative > 0)
      throw std::runtime_error(
          "solve: the degree-" + std::to_string(matrix_free.get_dof_handler().get_fe().degree) +
          " operator has " + std::to_string(n_negative) +
          " diagonal entries <= 0: mapped cells are inverted at quadrature points, the stiffness is not "
          "positive definite (a mesh too slender for this aspect ratio)");
    for (Number &entry : inverse)
      entry = 1 / entry;
  }

  template <typename Number>
  void ElasticOperator<Number>::assemble(TrilinosWrappers::SparseMatrix  &matrix,
                                         const AffineConstraints<Number> &constraints) const
  {
    const DoFHandler<3> &dof_handler  = cells->matrix_free.get_dof_handler();
    const MPI_Comm       communicator = dof_handler.get_communicator();
    IndexSet             relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    DynamicSparsityPattern pattern(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, pattern, constraints, false);
    SparsityTools::distribute_sparsity_pattern(pattern, dof_handler.locally_owned_dofs(), communicator,
                                               relevant);
    matrix.reinit(dof_handler.locally_owned_dofs(), dof_handler.locally_owned_dofs(), pattern, communicator);
    MatrixFreeTools::compute_matrix(cells->matrix_free, constraints, matrix, &Cells::integrate, cells.get());
  }

  template class ElasticOperator<double>;
  template class ElasticOperator<float>;
} // namespace penny
