#include "fe/far_field_load.h"

#include "closed_forms/gap_far_field.h"

#include <cmath>
#include <sstream>
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

    template <typename Kinematics>
    TrilinosWrappers::MPI::Vector unit_far_field_load(const LinearElasticSystem<Kinematics> &system,
                                                      const types::boundary_id               far,
                                                      const double                           poissons_ratio)
    {
      const GapFarField unit_gap(1, poissons_ratio);
      return system.stress_load_vector(far, [&](const auto &x) {
        return in_components(
            system.get_elasticity().stress(strain(unit_gap.displacement_gradient(in_space(x)))),
            Kinematics());
      });
    }
  } // namespace

  template <typename Kinematics>
  FarFieldLoad<Kinematics>::FarFieldLoad(LinearElasticSystem<Kinematics> &system,
                                         const types::boundary_id far, const double poissons_ratio,
                                         GapVolume gap_volume)
      : system(system), gap_volume(std::move(gap_volume)),
        unit_load(unit_far_field_load(system, far, poissons_ratio)), report{}
  {
  }

  template <typename Kinematics>
  DisplacementVector FarFieldLoad<Kinematics>::solve(const TrilinosWrappers::MPI::Vector &load)
  {
    const double tolerance = system.tolerance();
    const auto   record    = [this]() {
      report.iterations += system.last_solve().iterations;
      report.relative_residual  = system.last_solve().relative_residual;
      report.condition_estimate = system.last_solve().condition_estimate;
    };
    report = {};

    DisplacementVector u = system.solve(load, std::sqrt(tolerance), {});
    record();
    // The far field's strength D that u answers, and by how much (relative
    // to the whole load) its load missed V(u) b_1.
    double                        strength = 0, mismatch = 0;
    TrilinosWrappers::MPI::Vector whole(load);
    for (unsigned int step = 0;; ++step)
      {
        const double volume = gap_volume(u);
        whole               = load;
        whole.add(volume, unit_load);
        const double previous = mismatch;
        mismatch              = std::abs(volume - strength) * unit_load.l2_norm() / whole.l2_norm();
        // Done when the load u answers is the consistent one to the
        // tolerance, after at least one solve to the full tolerance.
        if (step > 0 && mismatch <= tolerance)
          return u;
        // From the second step on each step shrinks the mismatch by about
        // |V(u_1)|; if it does not halve, |V(u_1)| is not small.
        if (step > 1 && !(mismatch < 0.5 * previous))
          {
            std::ostringstream message;
            message << "far field: the gap's volume does not settle (the far field's load misses it by "
                    << mismatch << " of the whole, from " << previous
                    << " one step before): the far boundary is too close to the gap for Far boundary = "
                       "far field (enlarge the model, or choose free or clamped)";
            throw std::runtime_error(message.str());
          }
        strength = volume;
        u        = system.solve(whole, tolerance, u);
        record();
      }
  }

  template class FarFieldLoad<Axisymmetric>;
  template class FarFieldLoad<Solid>;
} // namespace penny
