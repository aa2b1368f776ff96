// The elastic operator's diagonal by sum factorisation (add_elastic_diagonal)
// against deal.II's MatrixFreeTools::compute_diagonal, which applies the
// operator's cell kernel to every unit vector: on the curved cells of a small
// elliptical-gap mesh with the 3D model's zero displacements, degrees 1 to
// 4, on 1 and 2 ranks; in float (the multigrid's levels) within 1e-5. And the
// refusal of hanging nodes.
#include "fe/boundary_ids.h"
#include "fe/elastic_diagonal.h"
#include "fe/elliptical_gap_mesh.h"
#include "test_support.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <boost/test/unit_test.hpp>

#include <stdexcept>

BOOST_AUTO_TEST_SUITE(test_elastic_diagonal)

using namespace penny;
using namespace dealii;

namespace
{
  using DiagonalVector = LinearAlgebra::distributed::Vector<double>;

  // MatrixFree of the FESystem of degree p on `triangulation`, constrained
  // by the zero displacements of the quarter model.
  struct Discretisation
  {
    Discretisation(const Triangulation<3> &triangulation, const unsigned int p)
        : mapping(p), dof_handler(triangulation)
    {
      dof_handler.distribute_dofs(FESystem<3>(FE_Q<3>(p), 3));
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      constraints.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
      for (const auto &[boundary, component] : {std::pair{boundary_id::symmetry, 0u},
                                                {boundary_id::second_symmetry, 1u},
                                                {boundary_id::ligament, 2u}})
        {
          ComponentMask fixed(3, false);
          fixed.set(component, true);
          VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary,
                                                   Functions::ZeroFunction<3>(3), constraints, fixed);
        }
      constraints.close();
      MatrixFree<3, double>::AdditionalData data;
      data.mapping_update_flags = update_gradients;
      matrix_free.reinit(mapping, dof_handler, constraints, QGauss<1>(p + 2), data);
      MatrixFree<3, float>::AdditionalData single_data;
      single_data.mapping_update_flags = update_gradients;
      single_constraints.copy_from(constraints);
      single_precision.reinit(mapping, dof_handler, single_constraints, QGauss<1>(p + 2), single_data);
    }

    MappingQ<3>               mapping;
    DoFHandler<3>             dof_handler;
    AffineConstraints<double> constraints;
    AffineConstraints<float>  single_constraints;
    MatrixFree<3, double>     matrix_free;
    MatrixFree<3, float>      single_precision; // as the multigrid's levels
  };

  constexpr IsotropicElasticity elasticity{1.2, 0.7};

} // namespace

// Every unconstrained entry within 1e-12 of the largest, at degrees 1 to 4
// (both sums of the same products in another order).
BOOST_AUTO_TEST_CASE(equals_the_diagonal_by_unit_vectors)
{
  parallel::distributed::Triangulation<3> triangulation(MPI_COMM_WORLD);
  make_elliptical_gap_mesh(triangulation, small_elliptical_mesh(0.25));
  for (const unsigned int p : {1u, 2u, 3u, 4u})
    BOOST_TEST_CONTEXT("degree " << p)
    {
      const Discretisation discretisation(triangulation, p);
      DiagonalVector       fast, reference;
      discretisation.matrix_free.initialize_dof_vector(fast);
      discretisation.matrix_free.initialize_dof_vector(reference);
      add_elastic_diagonal(discretisation.matrix_free, elasticity, fast);
      MatrixFreeTools::compute_diagonal<3, -1, 0, 3, double, VectorizedArray<double>>(
          discretisation.matrix_free, reference,
          [](ElasticEvaluation<double> &phi) { integrate_elastic_cell(phi, elasticity); });
      for (const unsigned int i : discretisation.matrix_free.get_constrained_dofs())
        fast.local_element(i) = reference.local_element(i) = 0;
      BOOST_TEST(reference.linfty_norm() > 0);
      // In float (the multigrid's levels): within 1e-5 of the double.
      LinearAlgebra::distributed::Vector<float> single;
      discretisation.single_precision.initialize_dof_vector(single);
      add_elastic_diagonal(discretisation.single_precision, elasticity, single);
      DiagonalVector single_difference(fast);
      for (unsigned int i = 0; i < single.locally_owned_size(); ++i)
        single_difference.local_element(i) -= single.local_element(i);
      for (const unsigned int i : discretisation.matrix_free.get_constrained_dofs())
        single_difference.local_element(i) = 0;
      BOOST_TEST(single_difference.linfty_norm() <= 1e-5 * fast.linfty_norm());
      reference -= fast;
      BOOST_TEST(reference.linfty_norm() <= 1e-12 * fast.linfty_norm());
    }
}

BOOST_AUTO_TEST_CASE(hanging_nodes_are_refused)
{
  parallel::distributed::Triangulation<3> triangulation(MPI_COMM_WORLD);
  GridGenerator::hyper_cube(triangulation);
  triangulation.refine_global(1);
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned() && cell->center()[0] < 0.5 && cell->center()[1] < 0.5 &&
        cell->center()[2] < 0.5)
      cell->set_refine_flag();
  triangulation.execute_coarsening_and_refinement();
  const Discretisation discretisation(triangulation, 2);
  DiagonalVector       diagonal;
  discretisation.matrix_free.initialize_dof_vector(diagonal);
  BOOST_CHECK_THROW(add_elastic_diagonal(discretisation.matrix_free, elasticity, diagonal), std::logic_error);
}

BOOST_AUTO_TEST_SUITE_END()
