#include "fe/elliptical_gap_model.h"

#include "fe/boundary_faces.h"
#include "fe/boundary_ids.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // u_x = 0 on x = 0, u_y = 0 on y = 0, u_z = 0 on the ligament.
    std::vector<ZeroDisplacement> zero_displacements()
    {
      const auto only = [](const unsigned int component) {
        std::vector<bool> mask(3, false);
        mask[component] = true;
        return ComponentMask(mask);
      };
      return {{boundary_id::symmetry, only(0)},
              {boundary_id::second_symmetry, only(1)},
              {boundary_id::ligament, only(2)}};
    }

    // Meshed and refined before the system distributes its degrees of freedom on it.
    const Triangulation<3> &meshed(Triangulation<3> &triangulation, const EllipticalGapModelParameters &model,
                                   TimerOutput &timer)
    {
      TimerOutput::Scope scope(timer, "mesh");
      make_elliptical_gap_mesh(triangulation, model.mesh);
      triangulation.refine_global(model.global_refinements);
      return triangulation;
    }
  } // namespace

  EllipticalGapModel::EllipticalGapModel(const EllipticalGapModelParameters &parameters, TimerOutput &timer)
      : parameters(parameters), timer(timer), triangulation(MPI_COMM_WORLD),
        system(meshed(triangulation, parameters, timer), parameters.degree, parameters.degree,
               parameters.material, parameters.linear_solver, zero_displacements(), timer),
        crack_front(parameters.mesh.semi_axis_a, parameters.mesh.semi_axis_b)
  {
  }

  DisplacementVector EllipticalGapModel::solve(const Traction &traction)
  {
    return system.solve(boundary_id::gap_face, traction);
  }

  std::vector<double> EllipticalGapModel::front_vertex_angles() const
  {
    return penny::front_vertex_angles(triangulation, parameters.mesh);
  }

  double EllipticalGapModel::opening_at_centre(const DisplacementVector &u) const
  {
    return system.normal_displacement_at_origin(u);
  }

  double EllipticalGapModel::gap_volume(const DisplacementVector &u) const
  {
    hp::FEFaceValues<3>              fe_face(system.get_mapping(), system.get_fe(), system.face_gauss(2),
                                             update_values | update_JxW_values);
    std::vector<Tensor<1, 3>>        values;
    const FEValuesExtractors::Vector displacement(0);
    double                           volume = 0;
    for_each_boundary_face(system.get_dof_handler(), boundary_id::gap_face, fe_face,
                           [&](const auto &, const FEFaceValues<3> &face) {
                             values.resize(face.n_quadrature_points);
                             face[displacement].get_function_values(u, values);
                             for (const unsigned int q : face.quadrature_point_indices())
                               volume += 8 * values[q][2] * face.JxW(q);
                           });
    return Utilities::MPI::sum(volume, triangulation.get_communicator());
  }
} // namespace penny
