// The truncated solid made to answer the infinite one (doc/theory.md,
// section 10). A free far boundary makes the model more compliant than the
// infinite solid, by about (c/R)^3. Loaded instead with the traction of the
// gap's own far field (closed_forms/gap_far_field.h), the truncated solid is
// the infinite one up to the next term of that field, smaller by (c/R)^2.
// The field's strength is the gap's volume D, which the solution itself
// decides: u solves A u = b + D b_1, b the face load and b_1 the far field's
// traction for a unit volume, with D = V(u). The fixed point D <- V(u)
// contracts by V(u_1) = V(A^-1 b_1), of order (c/R)^3: the first solve (D = 0,
// a free boundary) needs only the square root of the tolerance, and each
// later one starts from the last, so CG spends about one solve's iterations.
#pragma once

#include "fe/boundary_ids.h"
#include "fe/linear_elastic_system.h"

#include <functional>

namespace penny
{
  template <typename Kinematics> class FarFieldLoad
  {
  public:
    // The volume between the faces of the whole gap (m^3).
    using GapVolume = std::function<double(const DisplacementVector &)>;

    // The far field's traction on the boundary `far` of the system's mesh.
    FarFieldLoad(LinearElasticSystem<Kinematics> &system, dealii::types::boundary_id far,
                 double poissons_ratio, GapVolume gap_volume);

    // u = A^-1 (load + V(u) b_1). Throws if V does not settle (the far
    // boundary too close to the gap) or a solve fails.
    DisplacementVector solve(const dealii::TrilinosWrappers::MPI::Vector &load);

    // The solves of the last solve() together: their iterations summed, the
    // last one's residual and condition estimate.
    const SolveReport &last_solve() const { return report; }

  private:
    LinearElasticSystem<Kinematics>            &system;
    const GapVolume                             gap_volume;
    const dealii::TrilinosWrappers::MPI::Vector unit_load; // b_1
    SolveReport                                 report;
  };
} // namespace penny
