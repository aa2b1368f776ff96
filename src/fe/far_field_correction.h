// The truncated solid made to answer the infinite one (doc/theory.md,
// section 10). A free far boundary makes the model more compliant than the
// infinite solid, by about (c/R)^3. Loaded instead with the traction of the
// gap's own far field (closed_forms/gap_far_field.h), the truncated solid is
// the infinite one up to the next term of that field, smaller by (c/R)^2.
// The field's strength is the gap's volume D, which the solution itself
// decides; by linearity, with u_p the solution under the face load alone and
// u_1 the one under the far field of a unit volume,
//   u = u_p + D u_1,   D = V(u) = V(u_p) + D V(u_1)  =>  D = V(u_p)/(1 - V(u_1)).
// One extra solve, once per mesh, gives u_1.
#pragma once

#include "fe/boundary_ids.h"
#include "fe/linear_elastic_system.h"

#include <functional>

namespace penny
{
  template <typename Kinematics> class FarFieldCorrection
  {
  public:
    // The volume between the faces of the whole gap (m^3).
    using GapVolume = std::function<double(const DisplacementVector &)>;

    // Solves for u_1 with the far field's traction on the boundary `far`.
    FarFieldCorrection(LinearElasticSystem<Kinematics> &system, dealii::types::boundary_id far,
                       double poissons_ratio, GapVolume gap_volume);

    // u_p -> u_p + D u_1.
    void apply(DisplacementVector &u) const;

  private:
    const GapVolume                       gap_volume;
    dealii::TrilinosWrappers::MPI::Vector unit_response; // u_1 on the owned degrees of freedom
    double                                unit_volume;   // V(u_1)
  };
} // namespace penny
