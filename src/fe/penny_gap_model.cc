#include "fe/penny_gap_model.h"

#include "fe/boundary_faces.h"
#include "fe/boundary_ids.h"
#include "fe/penny_gap_mesh.h"
#include "fe/problem_size.h"
#include "fe/tip_graded_mesh.h"
#include "input/input_error.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/error_estimator.h>

#include <algorithm>
#include <cmath>
#include <sstream>

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

    // Refuses a model of `cells` cells that would not fit in memory, naming
    // the entries that make it large.
    void check_model_size(const PennyGapModelParameters &model, const double cells,
                          const std::string &more_entries = "")
    {
      const auto        &mesh = model.mesh;
      std::ostringstream entries;
      entries.precision(3);
      if (mesh.generator == MeshParameters::Generator::builtin)
        entries << "Mesh/Tip refinement levels = " << mesh.tip_levels
                << ", Grading distance = " << mesh.grading_distance << ", ";
      else
        entries << "Mesh/Mesh file = " << in_quotes(mesh.mesh_file) << ", ";
      entries << "Global refinements = " << mesh.global_refinements
              << ", Finite element/Polynomial degree = " << model.degree << more_entries;
      if (mesh.generator == MeshParameters::Generator::builtin)
        entries << " (R = " << model.geometry.domain_radius / model.geometry.gap_radius
                << " c, H = " << model.geometry.domain_height / model.geometry.gap_radius << " c)";
      check_problem_size(problem_size(cells, model.degree, model.linear_solver.type,
                                      Utilities::MPI::n_mpi_processes(model.communicator)),
                         entries.str(), model.communicator);
    }

    // Meshed before the system that distributes its degrees of freedom on it.
    const Triangulation<2> &meshed(Triangulation<2> &triangulation, const PennyGapModelParameters &model,
                                   TimerOutput &timer)
    {
      TimerOutput::Scope scope(timer, "mesh");
      make_penny_gap_mesh(triangulation, model.geometry, model.mesh,
                          [&](const double cells) { check_model_size(model, cells); });
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
      KellyErrorEstimator<2>::estimate(system.get_dof_handler(), system.face_gauss(1), {}, u, indicators,
                                       ComponentMask(), nullptr, numbers::invalid_unsigned_int,
                                       triangulation.locally_owned_subdomain());
      Utilities::MPI::sum(indicators, triangulation.get_communicator(), indicators);
      // Each refined cell becomes four, and balancing the levels refines about as many again.
      check_model_size(parameters, triangulation.n_active_cells() * (1 + 6 * fraction),
                       ", Convergence/Refined fraction = " + Utilities::to_string(fraction) +
                           " (adaptive cycles)");
      GridRefinement::refine_and_coarsen_fixed_number(triangulation, indicators, fraction, 0.);
      triangulation.execute_coarsening_and_refinement();
    }
    system.setup();
  }

  double PennyGapModel::opening_at_centre(const DisplacementVector &u) const
  {
    return system.normal_displacement_at_origin(u);
  }

  double PennyGapModel::gap_volume(const DisplacementVector &u) const
  {
    hp::FEFaceValues<2>              fe_face(system.get_mapping(), system.get_fe(), system.face_gauss(2),
                                             update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<1, 2>>        values;
    const FEValuesExtractors::Vector displacement(0);
    double                           volume = 0;
    for_each_boundary_face(system.get_dof_handler(), boundary_id::gap_face, fe_face,
                           [&](const auto &, const FEFaceValues<2> &face) {
                             values.resize(face.n_quadrature_points);
                             face[displacement].get_function_values(u, values);
                             for (const unsigned int q : face.quadrature_point_indices())
                               volume += 2 * 2 * numbers::PI * face.quadrature_point(q)[0] * values[q][1] *
                                         face.JxW(q);
                           });
    return Utilities::MPI::sum(volume, triangulation.get_communicator());
  }
} // namespace penny
