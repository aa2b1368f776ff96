#include "fe/penny_gap_model.h"

#include "fe/boundary_faces.h"
#include "fe/boundary_ids.h"
#include "fe/gap_opening.h"
#include "fe/tip_graded_mesh.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/error_estimator.h>

#include <algorithm>
#include <cmath>

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
      if (geometry.far_boundary == FarBoundary::clamped)
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
        triangulation(parameters.communicator, Triangulation<2>::limit_level_difference_at_vertices),
        system(meshed(triangulation, parameters, timer), parameters.degree, 1, parameters.material,
               parameters.linear_solver, zero_displacements(parameters.geometry), timer,
               degree_graded_towards_tip(parameters.geometry.gap_radius, parameters.degree,
                                         parameters.levels_per_degree))
  {
    load_far_field();
  }

  void PennyGapModel::load_far_field()
  {
    if (parameters.geometry.far_boundary == FarBoundary::far_field)
      far_field.emplace(system, boundary_id::far, parameters.material.poissons_ratio,
                        [this](const DisplacementVector &u) { return gap_volume(u); });
  }

  DisplacementVector PennyGapModel::solve(const FaceLoad &load)
  {
    if (far_field)
      return far_field->solve(system.load_vector(boundary_id::gap_face, face_traction(load)));
    return system.solve(boundary_id::gap_face, face_traction(load));
  }

  const SolveReport &PennyGapModel::last_solve() const
  {
    return far_field ? far_field->last_solve() : system.last_solve();
  }

  void PennyGapModel::refine_by_kelly(const DisplacementVector &u, const double fraction)
  {
    {
      TimerOutput::Scope scope(timer, "mesh");
      // Each rank estimates its own cells; the sum gives every rank all of them.
      Vector<float> indicators(triangulation.n_active_cells());
      KellyErrorEstimator<2>::estimate(system.get_dof_handler(), system.face_gauss(1), {}, u, indicators,
                                       ComponentMask(), nullptr, numbers::invalid_unsigned_int,
                                       triangulation.locally_owned_subdomain());
      Utilities::MPI::sum(indicators, triangulation.get_communicator(), indicators);
      GridRefinement::refine_and_coarsen_fixed_number(triangulation, indicators, fraction, 0.);
      triangulation.execute_coarsening_and_refinement();
    }
    system.setup();
    load_far_field();
  }

  double PennyGapModel::opening_at_centre(const DisplacementVector &u) const
  {
    return normal_displacement_at_origin(system, u);
  }

  double PennyGapModel::gap_volume(const DisplacementVector &u) const
  {
    return normal_displacement_integral(system, boundary_id::gap_face, u,
                                        [](const Point<2> &x) { return 2 * 2 * numbers::PI * x[0]; });
  }
} // namespace penny
