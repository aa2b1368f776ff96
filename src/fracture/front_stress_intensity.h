// K_I(phi) along the front of an elliptical-gap model: one
// FrontSegmentExtension per front point and ring, all evaluated by the one
// domain integral (fracture/domain_integral.h), and the signed K_I from the
// polarised form with a reference solution of unit pressure.
#pragma once

#include "fe/elliptical_gap_model.h"
#include "fracture/domain_integral.h"
#include "fracture/front_segment_extension.h"

#include <vector>

namespace penny
{
  // The parametric angles 0 = phi_0 < ... < phi_(n-1) = pi/2 of n points
  // evenly spaced in the front coordinate psi of `front`, as the mesh's
  // columns are: each point is a front vertex when n - 1 divides the cells
  // along the front.
  std::vector<double> front_point_angles(unsigned int n, const EllipticalFront &front);

  // The weight along the front of each domain integral (FrontSegmentExtension).
  struct FrontWeight
  {
    double       half_width_cells;  // in front cells of the model's mesh
    unsigned int vanishing_moments; // its moments of orders 1 to this one vanish: 5 or 7
  };

  class FrontStressIntensity
  {
  public:
    // Extensions at `angles`, each with the front weight `weight`, on every
    // ring of `ring_radii` (in units of the smallest radius of curvature of
    // the front, b^2/a).
    FrontStressIntensity(const EllipticalGapModel &model, const std::vector<double> &angles,
                         const FrontWeight &weight, const std::vector<double> &ring_radii);

    // Signed K_I (Pa m^1/2) of each load (u under the traction t), per load,
    // ring and point: E' B(u, u_ref)/K_ref with u_ref the displacement under
    // the traction t_ref > 0 (e.g. unit pressure), K_ref = sqrt(E' B(u_ref, u_ref)).
    using Load = DomainIntegral<Solid>::Load;
    std::vector<std::vector<std::vector<double>>>
    signed_sifs(const std::vector<Load> &loads, const DisplacementVector &u_ref,
                const EllipticalGapModel::Traction &t_ref) const;

    const std::vector<double> &get_angles() const { return angles; }
    // The extension of point i on ring r.
    const FrontSegmentExtension &extension(unsigned int ring, unsigned int i) const
    {
      return extensions[ring][i];
    }
    double half_width() const { return half_width_angle; }

  private:
    const DomainIntegral<Solid>                     j_integral;
    const std::vector<double>                       angles;
    double                                          half_width_angle;
    std::vector<std::vector<FrontSegmentExtension>> extensions;
  };
} // namespace penny
