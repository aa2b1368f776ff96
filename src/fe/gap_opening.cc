#include "fe/gap_opening.h"

#include "fe/boundary_faces.h"

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

namespace penny
{
  using namespace dealii;

  template <typename Kinematics>
  double normal_displacement_at_origin(const LinearElasticSystem<Kinematics> &system,
                                       const DisplacementVector              &u)
  {
    constexpr int dim         = Kinematics::dim;
    const auto   &dof_handler = system.get_dof_handler();
    double        value       = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).norm() == 0 && dof_handler.locally_owned_dofs().is_element(
                                                 cell->vertex_dof_index(v, dim - 1, cell->active_fe_index())))
            value = u(cell->vertex_dof_index(v, dim - 1, cell->active_fe_index()));
    return Utilities::MPI::sum(value, system.get_communicator());
  }

  template <typename Kinematics>
  double normal_displacement_integral(const LinearElasticSystem<Kinematics> &system,
                                      const types::boundary_id face, const DisplacementVector &u,
                                      const std::function<double(const Point<Kinematics::dim> &)> &weight)
  {
    constexpr int                    dim = Kinematics::dim;
    hp::FEFaceValues<dim>            fe_face(system.get_mapping(), system.get_fe(), system.face_gauss(2),
                                             update_values | update_quadrature_points | update_JxW_values);
    std::vector<Tensor<1, dim>>      values;
    const FEValuesExtractors::Vector displacement(0);
    double                           integral = 0;
    for_each_boundary_face(
        system.get_dof_handler(), face, fe_face, [&](const auto &, const FEFaceValues<dim> &face_values) {
          values.resize(face_values.n_quadrature_points);
          face_values[displacement].get_function_values(u, values);
          for (const unsigned int q : face_values.quadrature_point_indices())
            integral += weight(face_values.quadrature_point(q)) * values[q][dim - 1] * face_values.JxW(q);
        });
    return Utilities::MPI::sum(integral, system.get_communicator());
  }

  template double normal_displacement_at_origin(const LinearElasticSystem<Axisymmetric> &,
                                                const DisplacementVector &);
  template double normal_displacement_at_origin(const LinearElasticSystem<Solid> &,
                                                const DisplacementVector &);
  template double normal_displacement_integral(const LinearElasticSystem<Axisymmetric> &, types::boundary_id,
                                               const DisplacementVector &,
                                               const std::function<double(const Point<2> &)> &);
  template double normal_displacement_integral(const LinearElasticSystem<Solid> &, types::boundary_id,
                                               const DisplacementVector &,
                                               const std::function<double(const Point<3> &)> &);
} // namespace penny
