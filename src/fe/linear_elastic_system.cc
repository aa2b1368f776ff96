#include "fe/linear_elastic_system.h"

#include "fe/boundary_faces.h"
#include "fe/matrix_free_elasticity.h"
#include "fe/serial_cholesky.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // Q_p^dim for p = 1 ... degree (FE index p - 1) if graded, else Q_degree^dim alone.
    template <int dim> hp::FECollection<dim> elements(const unsigned int degree, const bool graded)
    {
      hp::FECollection<dim> collection;
      for (unsigned int p = graded ? 1 : degree; p <= degree; ++p)
        collection.push_back(FESystem<dim>(FE_Q<dim>(p), dim));
      return collection;
    }
  } // namespace

  template <typename Kinematics>
  LinearElasticSystem<Kinematics>::LinearElasticSystem(
      const Triangulation<dim> &triangulation, const unsigned int degree, const unsigned int mapping_degree,
      const MaterialParameters &material, const LinearSolverParameters &linear_solver,
      std::vector<ZeroDisplacement> zero_displacements, TimerOutput &timer, CellDegree cell_degree)
      : cell_degree(std::move(cell_degree)),
        fe(elements<Kinematics::dim>(degree, static_cast<bool>(this->cell_degree))),
        mapping(MappingQ<dim>(mapping_degree)), elasticity{material.lame_lambda(), material.lame_mu()},
        linear_solver(linear_solver), zero_displacements(std::move(zero_displacements)), timer(timer),
        dof_handler(triangulation)
  {
    if (matrix_free() && (!std::is_same_v<Kinematics, Solid> || this->cell_degree))
      throw std::invalid_argument("the matrix-free solver serves 3D models with one degree on every cell");
    setup();
  }

  template <typename Kinematics>
  auto LinearElasticSystem<Kinematics>::gauss(const unsigned int extra) const -> hp::QCollection<dim>
  {
    hp::QCollection<dim> quadratures;
    for (unsigned int i = 0; i < fe.size(); ++i)
      quadratures.push_back(QGauss<dim>(fe[i].degree + extra));
    return quadratures;
  }

  template <typename Kinematics>
  auto LinearElasticSystem<Kinematics>::face_gauss(const unsigned int extra) const -> hp::QCollection<dim - 1>
  {
    hp::QCollection<dim - 1> quadratures;
    for (unsigned int i = 0; i < fe.size(); ++i)
      quadratures.push_back(QGauss<dim - 1>(fe[i].degree + extra));
    return quadratures;
  }

  template <typename Kinematics> LinearElasticSystem<Kinematics>::~LinearElasticSystem() = default;

  template <typename Kinematics> void LinearElasticSystem<Kinematics>::setup()
  {
    distribute_and_constrain();
    if (!matrix_free())
      assemble_matrix();
    factorise();
  }

  // The zero displacements and the hanging nodes of a locally refined mesh.
  template <typename Kinematics> void LinearElasticSystem<Kinematics>::distribute_and_constrain()
  {
    TimerOutput::Scope scope(timer, "setup");
    // Solvers built on a previous matrix go before it does.
    cholesky.reset();
    mumps.reset();
    amg.clear();
    operator_without_matrix.reset();
    if (cell_degree)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_active_fe_index(cell_degree(cell) - 1);
    dof_handler.distribute_dofs(fe);
    owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

    constrain(dof_handler, constraints);
    if (matrix_free())
      return;

    DynamicSparsityPattern pattern(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, pattern, constraints, false);
    SparsityTools::distribute_sparsity_pattern(pattern, owned, get_communicator(), relevant);
    stiffness.reinit(owned, owned, pattern, get_communicator());
  }

  template <typename Kinematics>
  void LinearElasticSystem<Kinematics>::constrain(const DoFHandler<dim>     &dofs,
                                                  AffineConstraints<double> &constraints) const
  {
    IndexSet dofs_relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, dofs_relevant);
    constraints.clear();
    constraints.reinit(dofs_relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    for (const auto &[boundary, components] : zero_displacements)
      VectorTools::interpolate_boundary_values(dofs, boundary, Functions::ZeroFunction<dim>(dim), constraints,
                                               components);
    constraints.close();
  }

  // a(u, v) = int sigma(u):e(v) dmu, dmu the volume element of the kinematics.
  // On each cell the strains and the stresses of the shape functions at the
  // quadrature points are the columns of two matrices E and S (the entries of
  // the symmetric tensors the kinematics can make nonzero, per point; the
  // strains weighted by dmu, and by 2 off the diagonal), and the cell matrix
  // is the one product E^T S (BLAS gemm).
  template <typename Kinematics> void LinearElasticSystem<Kinematics>::assemble_matrix()
  {
    TimerOutput::Scope                   scope(timer, "assembly");
    hp::FEValues<dim>                    hp_values(mapping, fe, gauss(2),
                                                   update_values | update_gradients | update_quadrature_points |
                                                       update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    constexpr auto                       entries   = Kinematics::strain_entries;
    constexpr unsigned int               n_entries = entries.size();
    FullMatrix<double>                   cell_matrix, strains, stresses;
    std::vector<types::global_dof_index> local_dofs;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          hp_values.reinit(cell);
          const FEValues<dim> &fe_values     = hp_values.get_present_fe_values();
          const unsigned int   dofs_per_cell = fe_values.dofs_per_cell;
          if (cell_matrix.m() != dofs_per_cell || strains.m() != n_entries * fe_values.n_quadrature_points)
            {
              cell_matrix.reinit(dofs_per_cell, dofs_per_cell);
              strains.reinit(n_entries * fe_values.n_quadrature_points, dofs_per_cell);
              stresses.reinit(n_entries * fe_values.n_quadrature_points, dofs_per_cell);
              local_dofs.resize(dofs_per_cell);
            }
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Point<dim> &x   = fe_values.quadrature_point(q);
              const double      dmu = Kinematics::measure(x) * fe_values.JxW(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const Strain e     = strain(Kinematics::gradient(fe_values[displacement].gradient(i, q),
                                                                   fe_values[displacement].value(i, q), x));
                  const Strain sigma = elasticity.stress(e);
                  for (unsigned int k = 0; k < n_entries; ++k)
                    {
                      const double weight            = entries[k] < 3 ? dmu : 2 * dmu;
                      strains(n_entries * q + k, i)  = weight * e.access_raw_entry(entries[k]);
                      stresses(n_entries * q + k, i) = sigma.access_raw_entry(entries[k]);
                    }
                }
            }
          strains.Tmmult(cell_matrix, stresses);
          // Exactly symmetric, as the Cholesky factorisation reads one triangle.
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
              cell_matrix(i, j) = cell_matrix(j, i) = 0.5 * (cell_matrix(i, j) + cell_matrix(j, i));
          cell->get_dof_indices(local_dofs);
          constraints.distribute_local_to_global(cell_matrix, local_dofs, stiffness);
        }
    stiffness.compress(VectorOperation::add);
  }

  template <typename Kinematics>
  TrilinosWrappers::MPI::Vector LinearElasticSystem<Kinematics>::load_vector(const types::boundary_id face,
                                                                             const Traction &traction) const
  {
    return face_load(face, [&](const Point<dim> &x, const Tensor<1, dim> &) {
      Tensor<1, dim> t;
      t[dim - 1] = traction(x);
      return t;
    });
  }

  template <typename Kinematics>
  TrilinosWrappers::MPI::Vector
  LinearElasticSystem<Kinematics>::stress_load_vector(const types::boundary_id face,
                                                      const Stress            &stress) const
  {
    return face_load(face,
                     [&](const Point<dim> &x, const Tensor<1, dim> &normal) { return stress(x) * normal; });
  }

  template <typename Kinematics>
  TrilinosWrappers::MPI::Vector LinearElasticSystem<Kinematics>::face_load(const types::boundary_id face,
                                                                           const FaceForce &force) const
  {
    TimerOutput::Scope                   scope(timer, "assembly");
    TrilinosWrappers::MPI::Vector        rhs(owned, get_communicator());
    hp::FEFaceValues<dim>                fe_face(mapping, fe, face_gauss(2),
                                                 update_values | update_quadrature_points | update_normal_vectors |
                                                     update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> local_dofs;
    for_each_boundary_face(dof_handler, face, fe_face,
                           [&](const auto &cell, const FEFaceValues<dim> &values) {
                             cell_rhs.reinit(values.dofs_per_cell);
                             local_dofs.resize(values.dofs_per_cell);
                             for (const unsigned int q : values.quadrature_point_indices())
                               {
                                 const Point<dim>    &x = values.quadrature_point(q);
                                 const Tensor<1, dim> f = force(x, values.normal_vector(q)) *
                                                          Kinematics::measure(x) * values.JxW(q);
                                 for (unsigned int i = 0; i < values.dofs_per_cell; ++i)
                                   cell_rhs(i) += f * values[displacement].value(i, q);
                               }
                             cell->get_dof_indices(local_dofs);
                             constraints.distribute_local_to_global(cell_rhs, local_dofs, rhs);
                           });
    rhs.compress(VectorOperation::add);
    if (!std::isfinite(rhs.l2_norm()))
      throw std::runtime_error("assembly: the load vector holds NaN or Inf");
    return rhs;
  }

  template class LinearElasticSystem<Axisymmetric>;
  template class LinearElasticSystem<PlaneStrain>;
  template class LinearElasticSystem<Solid>;
} // namespace penny
