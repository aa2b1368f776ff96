#include "fe/linear_elastic_system.h"

#include "fe/boundary_faces.h"
#include "fe/matrix_free_elasticity.h"
#include "fe/rigid_body_modes.h"
#include "fe/serial_cholesky.h"
#include "input/input_error.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>
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

  std::string solver_name(const LinearSolverParameters &linear_solver, const MPI_Comm communicator)
  {
    if (linear_solver.type == LinearSolverParameters::Type::cg_amg)
      return "CG + AMG";
    if (linear_solver.type == LinearSolverParameters::Type::cg_multigrid)
      return "CG + matrix-free p-multigrid";
    return Utilities::MPI::n_mpi_processes(communicator) == 1 ? "CHOLMOD" : "MUMPS";
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

  namespace
  {
    // A solver's failure in one line: deal.II's report spans many, and
    // Amesos prints MUMPS' error code (INFOG(1)) to std::cerr.
    std::string solver_failure(const std::string &solver, const std::string &deal_ii_report,
                               const std::string &amesos_report)
    {
      std::smatch code;
      if (std::regex_search(amesos_report, code, std::regex("INFOG\\(1\\) = (-?[0-9]+)")))
        {
          const int infog = std::stoi(code[1]);
          return solver + " failed with INFOG(1) = " + code[1].str() +
                 (infog == -10 ? ": the stiffness matrix is singular"
                  : infog == -7 || infog == -8 || infog == -9 || infog == -13 ? ": out of memory"
                                                                              : "");
        }
      return solver + " failed: " + deal_ii_report;
    }
  } // namespace

  // The solvers' own failures (a singular matrix, memory) as one line naming
  // the solver. A singular matrix means a mesh or boundary conditions that
  // leave the solid free to move.
  template <typename Kinematics> void LinearElasticSystem<Kinematics>::factorise()
  {
    TimerOutput::Scope scope(timer, "solve");
    const CapturedCerr amesos_report;
    try
      {
        build_solver();
      }
    catch (const ExceptionBase &exception)
      {
        throw std::runtime_error("solve: " +
                                 solver_failure(solver_name(), one_line(exception), amesos_report.text()));
      }
  }

  template <typename Kinematics> void LinearElasticSystem<Kinematics>::build_solver()
  {
    if constexpr (std::is_same_v<Kinematics, Solid>)
      if (matrix_free())
        {
          operator_without_matrix = std::make_unique<MatrixFreeElasticity>(
              dof_handler, constraints, mapping[0],
              [this](const DoFHandler<dim> &dofs, AffineConstraints<double> &c) { constrain(dofs, c); },
              elasticity);
          return;
        }
    if (linear_solver.type == LinearSolverParameters::Type::direct)
      {
        if (Utilities::MPI::n_mpi_processes(get_communicator()) == 1)
          {
            cholesky = std::make_unique<SerialCholesky>(stiffness.trilinos_matrix());
            if (cholesky->factors.info() != Eigen::Success)
              throw std::runtime_error(
                  "solve: CHOLMOD could not factorise the stiffness matrix: it is not positive definite (a "
                  "solid free to move)");
          }
        else
          {
            mumps = std::make_unique<TrilinosWrappers::SolverDirect>(
                mumps_control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
            mumps->initialize(stiffness);
          }
      }
    else
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = degree() > 1;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        if constexpr (std::is_same_v<Kinematics, Solid>)
          {
            // ML's smoothed aggregation builds its coarse spaces from the
            // near-null space of the operator: in 3D the six rigid-body
            // motions. (The constant modes of the components miss the three
            // rotations, and CG then needs several times the iterations.)
            Teuchos::ParameterList              parameters;
            std::unique_ptr<Epetra_MultiVector> unused;
            data.set_parameters(parameters, unused, stiffness);
            const Epetra_MultiVector modes =
                rigid_body_modes(dof_handler, mapping, stiffness.trilinos_matrix().DomainMap());
            parameters.set("null space: type", "pre-computed");
            parameters.set("null space: dimension", modes.NumVectors());
            parameters.set("null space: vectors", modes.Values());
            amg.initialize(stiffness, parameters);
          }
        else
          {
            // In 2D the constant modes of the components (in the
            // axisymmetric model only the shift along z is free of strain).
            DoFTools::extract_constant_modes(dof_handler, ComponentMask(), data.constant_modes);
            amg.initialize(stiffness, data);
          }
      }
  }

  template <typename Kinematics>
  void LinearElasticSystem<Kinematics>::apply_inverse(TrilinosWrappers::MPI::Vector       &x,
                                                      const TrilinosWrappers::MPI::Vector &b,
                                                      const double                         tolerance)
  {
    if (linear_solver.type != LinearSolverParameters::Type::direct)
      {
        // CG aims at half the tolerance: the residual recomputed in solve() differs by rounding.
        SolverControl control(linear_solver.max_iterations, 0.5 * tolerance * b.l2_norm(), false, false);
        const auto    condition = [this](const double kappa) { report.condition_estimate = kappa; };
        try
          {
            if (operator_without_matrix)
              operator_without_matrix->solve(x, b, control, condition);
            else
              {
                SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
                cg.connect_condition_number_slot(condition);
                cg.solve(stiffness, x, b, amg);
              }
          }
        catch (const SolverControl::NoConvergence &failure)
          {
            if (!std::isfinite(failure.last_residual))
              throw LinearSolverFailure("solve: " + solver_name() +
                                        " broke down: the residual is NaN or Inf");
            throw LinearSolverFailure("solve: " + solver_name() + " did not converge in " +
                                      std::to_string(failure.last_step) + " iterations, its limit");
          }
        report.iterations = control.last_step();
      }
    else
      {
        const CapturedCerr amesos_report;
        try
          {
            if (mumps)
              mumps->solve(x, b);
            else
              {
                Vector<double> serial(b);
                Eigen::Map<Eigen::VectorXd>(serial.data(), serial.size()) = cholesky->factors.solve(
                    Eigen::Map<const Eigen::VectorXd>(b.begin(), b.locally_owned_size()));
                x = serial;
              }
          }
        catch (const ExceptionBase &exception)
          {
            throw std::runtime_error(
                "solve: " + solver_failure(solver_name(), one_line(exception), amesos_report.text()));
          }
      }
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

  template <typename Kinematics>
  DisplacementVector LinearElasticSystem<Kinematics>::solve(const types::boundary_id face,
                                                            const Traction          &traction)
  {
    return solve(load_vector(face, traction));
  }

  template <typename Kinematics>
  DisplacementVector LinearElasticSystem<Kinematics>::solve(const TrilinosWrappers::MPI::Vector &rhs)
  {
    return solve(rhs, linear_solver.tolerance, {});
  }

  template <typename Kinematics>
  DisplacementVector LinearElasticSystem<Kinematics>::solve(const TrilinosWrappers::MPI::Vector &rhs,
                                                            const double                         tolerance,
                                                            const DisplacementVector            &start)
  {
    TimerOutput::Scope            scope(timer, "solve");
    TrilinosWrappers::MPI::Vector u(owned, get_communicator());
    if (start.size() != 0)
      {
        u = start;
        constraints.set_zero(u);
      }
    report.iterations         = 0;
    report.condition_estimate = 0;
    const double load_norm    = rhs.l2_norm();
    if (load_norm == 0)
      throw std::runtime_error("assembly: the load vector is zero: the load vanishes at every quadrature "
                               "point of the loaded faces");
    try
      {
        apply_inverse(u, rhs, tolerance);
      }
    catch (const ExceptionBase &exception)
      {
        throw LinearSolverFailure("solve: " + solver_name() + " failed: " + one_line(exception));
      }

    // The graded mesh makes the matrix ill-conditioned (cell widths span many
    // orders of magnitude); up to three steps of iterative refinement with the
    // same factors restore what MUMPS' pivoted LU loses to rounding, for as
    // long as each step at least halves the residual. The Cholesky factors of
    // the positive definite matrix are backward stable: their residual is at
    // the floor of rounding from the start (1.1e-12 on 64,106 DoFs of degree
    // 6, which a step does not lower).
    TrilinosWrappers::MPI::Vector residual(owned, get_communicator()), correction(residual);
    const auto                    relative_residual = [&]() {
      vmult(residual, u);
      residual.sadd(-1., 1., rhs);
      return residual.l2_norm() / load_norm;
    };
    report.relative_residual = relative_residual();
    for (unsigned int step = 0; step < 3 && report.relative_residual > 1e-3 * tolerance && mumps; ++step)
      {
        try
          {
            apply_inverse(correction, residual, tolerance);
          }
        catch (const ExceptionBase &exception)
          {
            throw LinearSolverFailure("solve: " + solver_name() + " failed: " + one_line(exception));
          }
        u += correction;
        const double previous    = report.relative_residual;
        report.relative_residual = relative_residual();
        if (report.relative_residual > 0.5 * previous)
          {
            // At the floor of rounding: the better of the last two.
            if (report.relative_residual > previous)
              {
                u -= correction;
                report.relative_residual = previous;
              }
            break;
          }
      }
    if (!std::isfinite(report.relative_residual) || !std::isfinite(u.l2_norm()))
      throw std::runtime_error("solve: the displacement holds NaN or Inf");
    if (report.relative_residual > tolerance)
      {
        std::ostringstream message;
        message << "solve: relative residual " << report.relative_residual << " exceeds the tolerance "
                << tolerance;
        throw LinearSolverFailure(message.str());
      }
    constraints.distribute(u);
    DisplacementVector ghosted(owned, relevant, get_communicator());
    ghosted = u;
    return ghosted;
  }

  template <typename Kinematics>
  void LinearElasticSystem<Kinematics>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                                              const TrilinosWrappers::MPI::Vector &src) const
  {
    if (operator_without_matrix)
      operator_without_matrix->vmult(dst, src);
    else
      stiffness.vmult(dst, src);
  }

  template class LinearElasticSystem<Axisymmetric>;
  template class LinearElasticSystem<PlaneStrain>;
  template class LinearElasticSystem<Solid>;
} // namespace penny
