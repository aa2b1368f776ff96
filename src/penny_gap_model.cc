#include "penny_gap_model.h"

#include "axisymmetric_elasticity.h"
#include "gap_mesh.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    const FEValuesExtractors::Vector displacement(0);
  }

  PennyGapModel::PennyGapModel(const Parameters &parameters, TimerOutput &timer)
    : prm(parameters)
    , timer(timer)
    , mesh(MPI_COMM_WORLD, Triangulation<2>::limit_level_difference_at_vertices)
    , fe(FE_Q<2>(parameters.finite_element.degree), 2)
  {
    {
      TimerOutput::Scope scope(timer, "mesh");
      make_gap_mesh(mesh, prm.geometry, prm.mesh);
    }
    setup_system();
    assemble_matrix();
    factorise();
  }

  void PennyGapModel::refine_by_kelly(const DisplacementVector &u, const double fraction)
  {
    {
      TimerOutput::Scope scope(timer, "mesh");
      // Each rank estimates its own cells; the sum gives every rank all of them.
      Vector<float> indicators(mesh.n_active_cells());
      KellyErrorEstimator<2>::estimate(dofs, QGauss<1>(fe.degree + 1), {}, u, indicators, ComponentMask(), nullptr,
                                       numbers::invalid_unsigned_int, mesh.locally_owned_subdomain());
      Utilities::MPI::sum(indicators, mesh.get_communicator(), indicators);
      GridRefinement::refine_and_coarsen_fixed_number(mesh, indicators, fraction, 0.);
      mesh.execute_coarsening_and_refinement();
    }
    setup_system();
    assemble_matrix();
    factorise();
  }

  // Hanging nodes of the locally refined mesh, u_r = 0 on the axis, u_z = 0 on
  // the ligament, and u = 0 on a clamped far boundary.
  void PennyGapModel::setup_system()
  {
    TimerOutput::Scope scope(timer, "setup");
    // Solvers built on a previous matrix go before it does.
    mumps.reset();
    amg.clear();
    dofs.reinit(mesh);
    dofs.distribute_dofs(fe);
    owned = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);

    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    const ComponentMask radial(std::vector<bool>{true, false});
    const ComponentMask axial(std::vector<bool>{false, true});
    VectorTools::interpolate_boundary_values(dofs, boundary_id::axis, Functions::ZeroFunction<2>(2), constraints, radial);
    VectorTools::interpolate_boundary_values(dofs, boundary_id::ligament, Functions::ZeroFunction<2>(2), constraints, axial);
    if (prm.geometry.clamped_far_boundary)
      VectorTools::interpolate_boundary_values(dofs, boundary_id::far, Functions::ZeroFunction<2>(2), constraints);
    constraints.close();

    DynamicSparsityPattern pattern(relevant);
    DoFTools::make_sparsity_pattern(dofs, pattern, constraints, false);
    SparsityTools::distribute_sparsity_pattern(pattern, owned, mesh.get_communicator(), relevant);
    stiffness.reinit(owned, owned, pattern, mesh.get_communicator());
    if (prm.linear_solver.type == LinearSolverParameters::Type::direct && Utilities::MPI::n_mpi_processes(mesh.get_communicator()) == 1)
      {
        serial_stiffness.clear(); // releases the old pattern
        serial_sparsity.copy_from(pattern);
      }
  }

  // a(u, v) = int sigma(u):e(v) r dr dz, all four components (the 2 pi dropped).
  void PennyGapModel::assemble_matrix()
  {
    TimerOutput::Scope scope(timer, "assembly");
    const QGauss<2> quadrature(fe.degree + 2);
    FEValues<2>     fe_values(fe, quadrature, update_values | update_gradients | update_quadrature_points | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<AxisymmetricTensor>      shape_strain(dofs_per_cell);
    const double lambda = prm.material.lame_lambda();
    const double mu     = prm.material.lame_mu();

    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell_matrix = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const double r = fe_values.quadrature_point(q)[0];
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                shape_strain[i] = strain(fe_values[displacement].gradient(i, q), fe_values[displacement].value(i, q)[0], r);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const AxisymmetricTensor sigma_i = stress(shape_strain[i], lambda, mu);
                  for (unsigned int j = 0; j <= i; ++j)
                    cell_matrix(i, j) += sigma_i.contract(shape_strain[j]) * r * fe_values.JxW(q);
                }
            }
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
              cell_matrix(i, j) = cell_matrix(j, i);
          cell->get_dof_indices(local_dofs);
          constraints.distribute_local_to_global(cell_matrix, local_dofs, stiffness);
        }
    stiffness.compress(VectorOperation::add);
  }

  void PennyGapModel::factorise()
  {
    TimerOutput::Scope scope(timer, "solve");
    if (prm.linear_solver.type == LinearSolverParameters::Type::direct)
      {
        if (Utilities::MPI::n_mpi_processes(mesh.get_communicator()) == 1)
          {
            // Row by row through Epetra: SparseMatrix::copy_from(TrilinosWrappers::SparseMatrix)
            // grows super-linearly: 9.6 s of a 15.6 s run at 9e6 entries, 6.9 s in all this way.
            serial_stiffness.reinit(serial_sparsity);
            const Epetra_CrsMatrix &epetra = stiffness.trilinos_matrix();
            for (int local_row = 0; local_row < epetra.NumMyRows(); ++local_row)
              {
                int     n_entries;
                double *values;
                int    *columns;
                epetra.ExtractMyRowView(local_row, n_entries, values, columns);
                const auto row = epetra.RowMap().GID64(local_row);
                for (int k = 0; k < n_entries; ++k)
                  serial_stiffness.set(row, epetra.ColMap().GID64(columns[k]), values[k]);
              }
            umfpack.factorize(serial_stiffness);
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
        data.higher_order_elements = fe.degree > 1;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        DoFTools::extract_constant_modes(dofs, ComponentMask(), data.constant_modes);
        amg.initialize(stiffness, data);
      }
  }

  void PennyGapModel::apply_inverse(TrilinosWrappers::MPI::Vector &x, const TrilinosWrappers::MPI::Vector &b)
  {
    if (prm.linear_solver.type == LinearSolverParameters::Type::cg_amg)
      {
        // CG aims at half the tolerance: the residual recomputed in solve() differs by rounding.
        SolverControl control(prm.linear_solver.max_iterations, 0.5 * prm.linear_solver.tolerance * b.l2_norm(), false, false);
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.connect_condition_number_slot([this](const double kappa) { report.condition_estimate = kappa; });
        try
          {
            cg.solve(stiffness, x, b, amg);
          }
        catch (const SolverControl::NoConvergence &failure)
          {
            throw std::runtime_error("solve: CG with AMG did not converge in " + std::to_string(failure.last_step) +
                                     " iterations (Linear solver/Maximum iterations)");
          }
        report.iterations = control.last_step();
      }
    else if (mumps)
      mumps->solve(x, b);
    else
      {
        Vector<double> serial(b);
        umfpack.solve(serial);
        x = serial;
      }
  }

  DisplacementVector PennyGapModel::solve(const FaceLoad &load)
  {
    TrilinosWrappers::MPI::Vector rhs(owned, mesh.get_communicator());
    {
      // int_{z=0, r<c} p(r) v_z r dr: the traction p e_z opens the gap.
      TimerOutput::Scope scope(timer, "assembly");
      const QGauss<1> face_quadrature(fe.degree + 2);
      FEFaceValues<2> fe_face(fe, face_quadrature, update_values | update_quadrature_points | update_JxW_values);
      Vector<double>  cell_rhs(fe.n_dofs_per_cell());
      std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == boundary_id::gap_face)
              {
                fe_face.reinit(cell, face);
                cell_rhs = 0;
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  {
                    const double r = fe_face.quadrature_point(q)[0];
                    const double p = load(r);
                    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                      cell_rhs(i) += p * fe_face[displacement].value(i, q)[1] * r * fe_face.JxW(q);
                  }
                cell->get_dof_indices(local_dofs);
                constraints.distribute_local_to_global(cell_rhs, local_dofs, rhs);
              }
      rhs.compress(VectorOperation::add);
    }
    if (!std::isfinite(rhs.l2_norm()))
      throw std::runtime_error("assembly: the load vector holds NaN or Inf (check Load/Expression)");

    TimerOutput::Scope            scope(timer, "solve");
    TrilinosWrappers::MPI::Vector u(owned, mesh.get_communicator());
    report.iterations         = 0;
    report.condition_estimate = 0;
    apply_inverse(u, rhs);

    // The graded mesh makes the matrix ill-conditioned (cell widths span many
    // orders of magnitude); a few steps of iterative refinement with the same
    // factors restore the residual an LU solve loses to rounding.
    TrilinosWrappers::MPI::Vector residual(owned, mesh.get_communicator()), correction(residual);
    const auto relative_residual = [&]() {
      stiffness.vmult(residual, u);
      residual.sadd(-1., 1., rhs);
      return residual.l2_norm() / rhs.l2_norm();
    };
    report.relative_residual = relative_residual();
    for (unsigned int step = 0; step < 3 && report.relative_residual > 1e-3 * prm.linear_solver.tolerance &&
                                prm.linear_solver.type == LinearSolverParameters::Type::direct;
         ++step)
      {
        apply_inverse(correction, residual);
        u += correction;
        report.relative_residual = relative_residual();
      }
    if (!std::isfinite(report.relative_residual) || !std::isfinite(u.l2_norm()))
      throw std::runtime_error("solve: the displacement holds NaN or Inf");
    if (report.relative_residual > prm.linear_solver.tolerance)
      {
        std::ostringstream message;
        message << "solve: relative residual " << report.relative_residual
                << " exceeds Linear solver/Tolerance = " << prm.linear_solver.tolerance;
        throw std::runtime_error(message.str());
      }
    constraints.distribute(u);
    DisplacementVector ghosted(owned, relevant, mesh.get_communicator());
    ghosted = u;
    return ghosted;
  }

  // (0, 0) is a vertex: its u_z is a degree of freedom, read on the rank that owns it.
  double PennyGapModel::opening_at_centre(const DisplacementVector &u) const
  {
    double opening = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).norm() == 0 && owned.is_element(cell->vertex_dof_index(v, 1)))
            opening = u(cell->vertex_dof_index(v, 1));
    return Utilities::MPI::sum(opening, mesh.get_communicator());
  }

  double PennyGapModel::gap_volume(const DisplacementVector &u) const
  {
    const QGauss<1>     face_quadrature(fe.degree + 2);
    FEFaceValues<2>     fe_face(fe, face_quadrature, update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<1, 2>> values(face_quadrature.size());
    double volume = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == boundary_id::gap_face)
            {
              fe_face.reinit(cell, face);
              fe_face[displacement].get_function_values(u, values);
              for (const unsigned int q : fe_face.quadrature_point_indices())
                volume += 2 * 2 * numbers::PI * fe_face.quadrature_point(q)[0] * values[q][1] * fe_face.JxW(q);
            }
    return Utilities::MPI::sum(volume, mesh.get_communicator());
  }
} // namespace penny
