#include "fracture/front_stress_intensity.h"

#include <cmath>
#include <stdexcept>

namespace penny
{
  std::vector<double> front_point_angles(const unsigned int n, const EllipticalFront &front)
  {
    if (n < 2)
      throw std::invalid_argument("front_point_angles: at least the two ends phi = 0 and pi/2");
    std::vector<double> angles(n);
    for (unsigned int i = 0; i < n; ++i)
      angles[i] = front.parametric_angle(i + 1 == n ? M_PI / 2 : i * M_PI / (2 * (n - 1)));
    return angles;
  }

  FrontStressIntensity::FrontStressIntensity(const EllipticalGapModel  &model,
                                             const std::vector<double> &angles, const FrontWeight &weight,
                                             const std::vector<double> &ring_radii)
      : j_integral(model.get_system(), model.material().plane_strain_modulus()), angles(angles)
  {
    const auto  &front            = model.front();
    const double front_cells      = model.front_vertex_angles().size() - 1;
    const double curvature_radius = 1 / front.curvature(0);
    half_width_angle              = weight.half_width_cells * M_PI / (2 * front_cells);
    const auto nearest            = std::make_shared<const NearestFrontPoint>(front);
    for (const double rho : ring_radii)
      {
        extensions.emplace_back();
        for (const double phi : angles)
          extensions.back().emplace_back(nearest, phi, half_width_angle, weight.vanishing_moments,
                                         rho * curvature_radius);
      }
  }

  // All points on all rings and all loads in one pass of the domain integral.
  std::vector<std::vector<std::vector<double>>>
  FrontStressIntensity::signed_sifs(const std::vector<Load> &loads, const DisplacementVector &u_ref,
                                    const EllipticalGapModel::Traction &t_ref) const
  {
    std::vector<const CrackExtension<3> *> all;
    for (const auto &ring : extensions)
      for (const auto &q : ring)
        all.push_back(&q);
    std::vector<std::vector<std::vector<double>>> K;
    for (const std::vector<double> &flat :
         j_integral.stress_intensities(loads, {&u_ref, &t_ref}, all).signed_sifs)
      {
        K.emplace_back();
        for (unsigned int r = 0, i = 0; r < extensions.size(); i += extensions[r].size(), ++r)
          K.back().emplace_back(flat.begin() + i, flat.begin() + i + extensions[r].size());
      }
    return K;
  }
} // namespace penny
