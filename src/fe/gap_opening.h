// The opening of a gap read from a displacement of its model: u_z at the
// centre of the gap face, and the integral of u_z over the face, which with
// the model's weight is the volume between the faces.
#pragma once

#include "fe/linear_elastic_system.h"

#include <functional>

namespace penny
{
  // The last component of u (u_z) at the origin, which must be a vertex:
  // read on the rank that owns that degree of freedom, known on every rank.
  template <typename Kinematics>
  double normal_displacement_at_origin(const LinearElasticSystem<Kinematics> &system,
                                       const DisplacementVector              &u);

  // int_face w(x) u_z dA over the faces of boundary `face`, all ranks together.
  template <typename Kinematics>
  double
  normal_displacement_integral(const LinearElasticSystem<Kinematics> &system, dealii::types::boundary_id face,
                               const DisplacementVector                                            &u,
                               const std::function<double(const dealii::Point<Kinematics::dim> &)> &weight);
} // namespace penny
