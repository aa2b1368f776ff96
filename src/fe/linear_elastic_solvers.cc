#include "fe/linear_elastic_system.h"

#include "fe/matrix_free_elasticity.h"
#include "fe/rigid_body_modes.h"
#include "fe/serial_cholesky.h"
#include "input/input_error.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace penny
{
  using namespace dealii;

  std::string solver_name(const LinearSolverParameters &linear_solver, const MPI_Comm communicator)
  {
    if (linear_solver.type == LinearSolverParameters::Type::cg_amg)
      return "CG + AMG";
    if (linear_solver.type == LinearSolverParameters::Type::cg_multigrid)
      return "CG + matrix-free p-multigrid";
    return Utilities::MPI::n_mpi_processes(communicator) == 1 ? "CHOLMOD" : "MUMPS";
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

  // The members defined here, for each kinematics (the class itself is
  // instantiated in linear_elastic_system.cc: once in a program).
#define PENNY_INSTANTIATE_SOLVERS(Kinematics)                                                                \
  template void LinearElasticSystem<Kinematics>::factorise();                                                \
  template void LinearElasticSystem<Kinematics>::build_solver();                                             \
  template void LinearElasticSystem<Kinematics>::apply_inverse(                                              \
      TrilinosWrappers::MPI::Vector &, const TrilinosWrappers::MPI::Vector &, double);                       \
  template DisplacementVector LinearElasticSystem<Kinematics>::solve(types::boundary_id, const Traction &);  \
  template DisplacementVector LinearElasticSystem<Kinematics>::solve(const TrilinosWrappers::MPI::Vector &); \
  template DisplacementVector LinearElasticSystem<Kinematics>::solve(const TrilinosWrappers::MPI::Vector &,  \
                                                                     double, const DisplacementVector &);    \
  template void               LinearElasticSystem<Kinematics>::vmult(TrilinosWrappers::MPI::Vector &,        \
                                                                     const TrilinosWrappers::MPI::Vector &) const;
  PENNY_INSTANTIATE_SOLVERS(Axisymmetric)
  PENNY_INSTANTIATE_SOLVERS(PlaneStrain)
  PENNY_INSTANTIATE_SOLVERS(Solid)
#undef PENNY_INSTANTIATE_SOLVERS
} // namespace penny
