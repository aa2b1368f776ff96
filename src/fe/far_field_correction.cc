#include "fe/far_field_correction.h"

#include "closed_forms/gap_far_field.h"

#include <stdexcept>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // The stress of the gap's far field in the kinematics' components: the
    // axisymmetric (r, z) at the point (r, 0, z) of the solid.
    SymmetricTensor<2, 3> in_components(const SymmetricTensor<2, 3> &stress, Solid)
    {
      return stress;
    }

    SymmetricTensor<2, 2> in_components(const SymmetricTensor<2, 3> &stress, Axisymmetric)
    {
      SymmetricTensor<2, 2> s;
      s[0][0] = stress[0][0];
      s[0][1] = stress[0][2];
      s[1][1] = stress[2][2];
      return s;
    }

    Point<3> in_space(const Point<3> &x)
    {
      return x;
    }
    Point<3> in_space(const Point<2> &x)
    {
      return {x[0], 0, x[1]};
    }
  } // namespace

  template <typename Kinematics>
  FarFieldCorrection<Kinematics>::FarFieldCorrection(LinearElasticSystem<Kinematics> &system,
                                                     const types::boundary_id         far,
                                                     const double poissons_ratio, GapVolume gap_volume)
      : gap_volume(std::move(gap_volume))
  {
    const GapFarField unit_gap(1, poissons_ratio);
    const auto        stress = [&](const auto &x) {
      return system.get_elasticity().stress(strain(unit_gap.displacement_gradient(in_space(x))));
    };
    const DisplacementVector u = system.solve(system.stress_load_vector(
        far, [&](const auto &x) { return in_components(stress(x), Kinematics()); }));
    unit_volume                = this->gap_volume(u);
    // V(u_1) is of order -(c/R)^3; near 1 the superposition's D would blow up.
    if (!(std::abs(unit_volume) < 0.5))
      throw std::runtime_error("far field: the gap's volume under the far field of a unit volume is " +
                               std::to_string(unit_volume) +
                               ", not small: the far boundary is too close to the gap");
    unit_response.reinit(u.locally_owned_elements(), u.get_mpi_communicator());
    unit_response = u;
  }

  template <typename Kinematics> void FarFieldCorrection<Kinematics>::apply(DisplacementVector &u) const
  {
    const double                  volume = gap_volume(u) / (1 - unit_volume);
    TrilinosWrappers::MPI::Vector sum(unit_response);
    sum = u;
    sum.add(volume, unit_response);
    u = sum;
  }

  template class FarFieldCorrection<Axisymmetric>;
  template class FarFieldCorrection<Solid>;
} // namespace penny
