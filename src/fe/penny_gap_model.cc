#include "fe/penny_gap_model.h"

#include "fe/boundary_faces.h"
#include "fe/boundary_ids.h"
#include "fe/penny_gap_mesh.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/error_estimator.h>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // u_r = 0 on the axis, u_z = 0 on the ligament, u = 0 on a clamped far boundary.
    std::vector<ZeroDisplacement> zero_displacements(const GeometryParameters &geometry)
    {
      std::vector<ZeroDisplacement> conditions = {
          {boundary_id::symmetry, ComponentMask(std::vector<bool>{true, false})},
          {boundary_id::ligament, ComponentMask(std::vector<bool>{false, true})}};
      if (geometry.clamped_far_boundary)
        conditions.push_back({boundary_id::far, ComponentMask()});
      return conditions;
    }

    // Meshed before the system that distributes its degrees of freedom on it.
    const Triangulation<2> &meshed(Triangulation<2> &triangulation, const PennyGapModelParameters &model,
                                   TimerOutput &timer)
    {
      TimerOutput::Scope scope(timer, "mesh");
      make_penny_gap_mesh(triangulation, model.geometry, model.mesh);
      return triangulation;
    }
  } // namespace

  PennyGapModelParameters PennyGapModelParameters::scaled_to(const double c) const
  {
    PennyGapModelParameters scaled = *this;
    const double            factor = c / geometry.gap_radius;
    scaled.geometry.gap_radius     = c;
    scaled.geometry.domain_radius  = factor * geometry.domain_radius;
    scaled.geometry.domain_height  = factor * geometry.domain_height;
    return scaled;
  }

  PennyGapModel::PennyGapModel(const PennyGapModelParameters &parameters, TimerOutput &timer)
      : parameters(parameters), timer(timer),
        triangulation(MPI_COMM_WORLD, Triangulation<2>::limit_level_difference_at_vertices),
        system(meshed(triangulation, parameters, timer), parameters.degree, 1, parameters.material,
               parameters.linear_solver, zero_displacements(parameters.geometry), timer)
  {
  }

  DisplacementVector PennyGapModel::solve(const FaceLoad &load)
  {
    return system.solve(boundary_id::gap_face, face_traction(load));
  }

  void PennyGapModel::refine_by_kelly(const DisplacementVector &u, const double fraction)
  {
    {
      TimerOutput::Scope scope(timer, "mesh");
      // Each rank estimates its own cells; the sum gives every rank all of them.
      Vector<float> indicators(triangulation.n_active_cells());
      KellyErrorEstimator<2>::estimate(system.get_dof_handler(), QGauss<1>(parameters.degree + 1), {}, u,
                                       indicators, ComponentMask(), nullptr, numbers::invalid_unsigned_int,
                                       triangulation.locally_owned_subdomain());
      Utilities::MPI::sum(indicators, triangulation.get_communicator(), indicators);
      GridRefinement::refine_and_coarsen_fixed_number(triangulation, indicators, fraction, 0.);
      triangulation.execute_coarsening_and_refinement();
    }
    system.setup();
  }

  // (0, 0) is a vertex: its u_z is a degree of freedom, read on the rank that owns it.
  double PennyGapModel::opening_at_centre(const DisplacementVector &u) const
  {
    const auto &dof_handler = system.get_dof_handler();
    double      opening     = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).norm() == 0 &&
              dof_handler.locally_owned_dofs().is_element(cell->vertex_dof_index(v, 1)))
            opening = u(cell->vertex_dof_index(v, 1));
    return Utilities::MPI::sum(opening, triangulation.get_communicator());
  }

  double PennyGapModel::gap_volume(const DisplacementVector &u) const
  {
    const QGauss<1>                  face_quadrature(parameters.degree + 2);
    FEFaceValues<2>                  fe_face(system.get_fe(), face_quadrature,
                                             update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<1, 2>>        values(face_quadrature.size());
    const FEValuesExtractors::Vector displacement(0);
    double                           volume = 0;
    for_each_boundary_face(system.get_dof_handler(), boundary_id::gap_face, fe_face,
                           [&](const auto &, const FEFaceValues<2> &face) {
                             face[displacement].get_function_values(u, values);
                             for (const unsigned int q : face.quadrature_point_indices())
                               volume += 2 * 2 * numbers::PI * face.quadrature_point(q)[0] * values[q][1] *
                                         face.JxW(q);
                           });
    return Utilities::MPI::sum(volume, triangulation.get_communicator());
  }
} // namespace penny
