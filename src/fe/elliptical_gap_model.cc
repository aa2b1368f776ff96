#include "fe/elliptical_gap_model.h"

#include "fe/boundary_faces.h"
#include "fe/boundary_ids.h"
#include "fe/gap_opening.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // u_x = 0 on x = 0, u_y = 0 on y = 0, u_z = 0 on the ligament, u = 0 on
    // clamped far faces.
    std::vector<ZeroDisplacement> zero_displacements(const FarBoundary far_boundary)
    {
      const auto only = [](const unsigned int component) {
        std::vector<bool> mask(3, false);
        mask[component] = true;
        return ComponentMask(mask);
      };
      std::vector<ZeroDisplacement> conditions = {{boundary_id::symmetry, only(0)},
                                                  {boundary_id::second_symmetry, only(1)},
                                                  {boundary_id::ligament, only(2)}};
      if (far_boundary == FarBoundary::clamped)
        conditions.push_back({boundary_id::far, ComponentMask()});
      return conditions;
    }

    bool near_tip(const TriaAccessor<3, 3, 3> &cell, const EllipticalGapModelParameters &model)
    {
      const Point<3> tip(model.mesh.semi_axis_a, 0, 0);
      return cell.center().distance(tip) < model.tip_refinement_radius * model.mesh.semi_axis_a;
    }

    // Meshed and refined before the system distributes its degrees of freedom on it.
    const Triangulation<3> &meshed(Triangulation<3> &triangulation, const EllipticalGapModelParameters &model,
                                   TimerOutput &timer)
    {
      TimerOutput::Scope scope(timer, "mesh");
      make_elliptical_gap_mesh(triangulation, model.mesh);
      triangulation.refine_global(model.global_refinements);
      const EllipticalFront front(model.mesh.semi_axis_a, model.mesh.semi_axis_b);
      for (unsigned int level = 0; level < model.tip_refinements; ++level)
        {
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() && near_tip(*cell, model))
              {
                bool touches_front = false;
                for (const unsigned int v : cell->vertex_indices())
                  touches_front |= front.contains(cell->vertex(v));
                if (!touches_front)
                  cell->set_refine_flag();
              }
          triangulation.execute_coarsening_and_refinement();
        }
      return triangulation;
    }
  } // namespace

  double elliptical_model_cells(const EllipticalGapModelParameters &parameters)
  {
    // Counted, not built, when no tip refinement needs the cells' places or
    // when building the coarse mesh would already take gigabytes.
    const double coarse_cells = elliptical_gap_mesh_cells(parameters.mesh);
    if (parameters.tip_refinements == 0 || coarse_cells > 1e6)
      return coarse_cells * std::pow(8., parameters.global_refinements + parameters.tip_refinements);
    Triangulation<3> coarse;
    make_elliptical_gap_mesh(coarse, parameters.mesh);
    // A coarse cell whose box meets the ball may have children in it.
    const Point<3> tip(parameters.mesh.semi_axis_a, 0, 0);
    double         cells = 0;
    for (const auto &cell : coarse.active_cell_iterators())
      {
        const BoundingBox<3> box = cell->bounding_box();
        Point<3>             nearest;
        for (unsigned int d = 0; d < 3; ++d)
          nearest[d] = std::clamp(tip[d], box.lower_bound(d), box.upper_bound(d));
        const bool meets_ball =
            nearest.distance(tip) < parameters.tip_refinement_radius * parameters.mesh.semi_axis_a;
        cells += std::pow(8., parameters.global_refinements + (meets_ball ? parameters.tip_refinements : 0));
      }
    return cells;
  }

  EllipticalGapModel::EllipticalGapModel(const EllipticalGapModelParameters &parameters, TimerOutput &timer)
      : parameters(parameters), timer(timer), triangulation(MPI_COMM_WORLD),
        system(meshed(triangulation, parameters, timer), parameters.degree, parameters.degree,
               parameters.material, parameters.linear_solver, zero_displacements(parameters.far_boundary),
               timer),
        crack_front(parameters.mesh.semi_axis_a, parameters.mesh.semi_axis_b)
  {
    if (parameters.far_boundary == FarBoundary::far_field)
      far_field.emplace(system, boundary_id::far, parameters.material.poissons_ratio,
                        [this](const DisplacementVector &u) { return gap_volume(u); });
  }

  DisplacementVector EllipticalGapModel::solve(const Traction &traction)
  {
    if (far_field)
      return far_field->solve(system.load_vector(boundary_id::gap_face, traction));
    return system.solve(boundary_id::gap_face, traction);
  }

  const SolveReport &EllipticalGapModel::last_solve() const
  {
    return far_field ? far_field->last_solve() : system.last_solve();
  }

  std::vector<double> EllipticalGapModel::front_vertex_angles() const
  {
    return penny::front_vertex_angles(triangulation, crack_front);
  }

  double EllipticalGapModel::opening_at_centre(const DisplacementVector &u) const
  {
    return normal_displacement_at_origin(system, u);
  }

  double EllipticalGapModel::gap_volume(const DisplacementVector &u) const
  {
    return normal_displacement_integral(system, boundary_id::gap_face, u,
                                        [](const Point<3> &) { return 8.; });
  }
} // namespace penny
