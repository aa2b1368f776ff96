#include "fe/elastic_operator.h"

#include "fe/elastic_diagonal.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/tools.h>

#include "fe/matrix_free_templates.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace penny
{
  using namespace dealii;

  struct ElasticOperator::Cells
  {
    MatrixFree<3, double> matrix_free;
    IsotropicElasticity   elasticity{};

    void integrate(ElasticEvaluation &phi) const { integrate_elastic_cell(phi, elasticity); }

    void apply(const MatrixFree<3, double> &, Vector &dst, const Vector &src,
               const std::pair<unsigned int, unsigned int> &range) const
    {
      ElasticEvaluation phi(matrix_free);
      for (unsigned int cell = range.first; cell < range.second; ++cell)
        {
          phi.reinit(cell);
          phi.read_dof_values(src);
          integrate(phi);
          phi.distribute_local_to_global(dst);
        }
    }
  };

  ElasticOperator::ElasticOperator() : cells(std::make_unique<Cells>()) {}

  ElasticOperator::~ElasticOperator() = default;

  void ElasticOperator::reinit(const Mapping<3> &mapping, const DoFHandler<3> &dof_handler,
                               const AffineConstraints<double> &constraints,
                               const IsotropicElasticity &elasticity, const unsigned int extra_points)
  {
    cells->elasticity = elasticity;
    MatrixFree<3, double>::AdditionalData data;
    data.tasks_parallel_scheme = MatrixFree<3, double>::AdditionalData::none; // MPI ranks, not threads
    data.mapping_update_flags  = update_gradients;
    cells->matrix_free.reinit(mapping, dof_handler, constraints,
                              QGauss<1>(dof_handler.get_fe().degree + extra_points), data);
  }

  void ElasticOperator::initialize_dof_vector(Vector &v) const
  {
    cells->matrix_free.initialize_dof_vector(v);
  }

  types::global_dof_index ElasticOperator::m() const
  {
    return cells->matrix_free.get_dof_handler().n_dofs();
  }

  double ElasticOperator::el(types::global_dof_index, types::global_dof_index) const
  {
    throw std::logic_error("a matrix-free operator has no entries to read");
  }

  void ElasticOperator::vmult(Vector &dst, const Vector &src) const
  {
    cells->matrix_free.cell_loop(&Cells::apply, cells.get(), dst, src, true);
    for (const unsigned int i : cells->matrix_free.get_constrained_dofs())
      dst.local_element(i) = src.local_element(i);
  }

  void ElasticOperator::compute_inverse_diagonal(Vector &inverse) const
  {
    const MatrixFree<3, double> &matrix_free = cells->matrix_free;
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
                                                                    [](double d) { return !(d > 0); })),
                            inverse.get_mpi_communicator());
    if (n_negative > 0)
      throw std::runtime_error(
          "solve: the degree-" + std::to_string(matrix_free.get_dof_handler().get_fe().degree) +
          " operator has " + std::to_string(n_negative) +
          " diagonal entries <= 0: mapped cells are inverted at quadrature points, the stiffness is not "
          "positive definite (a mesh too slender for this aspect ratio)");
    for (double &entry : inverse)
      entry = 1 / entry;
  }

  void ElasticOperator::assemble(TrilinosWrappers::SparseMatrix  &matrix,
                                 const AffineConstraints<double> &constraints) const
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
} // namespace penny
