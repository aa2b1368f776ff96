#include "fracture/front_stress_intensity.h"

#include <cmath>
#include <stdexcept>

namespace penny
{
  std::vector<double> front_point_angles(const unsigned int n)
  {
    if (n < 2)
      throw std::invalid_argument("front_point_angles: at least the two ends phi = 0 and pi/2");
    std::vector<double> angles(n);
    for (unsigned int i = 0; i < n; ++i)
      angles[i] = i + 1 == n ? M_PI / 2 : i * M_PI / (2 * (n - 1));
    return angles;
  }

  FrontStressIntensity::FrontStressIntensity(const EllipticalGapModel  &model,
                                             const std::vector<double> &angles, const double half_width_cells,
                                             const std::vector<double> &ring_radii)
      : j_integral(model.get_system(), model.material().plane_strain_modulus()), angles(angles)
  {
    const auto  &front            = model.front();
    const double front_cells      = model.front_vertex_angles().size() - 1;
    const double curvature_radius = 1 / front.curvature(0);
    half_width_angle              = half_width_cells * M_PI / (2 * front_cells);
    for (const double rho : ring_radii)
      {
        extensions.emplace_back();
        for (const double phi : angles)
          extensions.back().emplace_back(front, phi, half_width_angle, rho * curvature_radius);
      }
  }

  std::vector<std::vector<double>>
  FrontStressIntensity::signed_sifs(const DisplacementVector &u, const EllipticalGapModel::Traction &t,
                                    const DisplacementVector           &u_ref,
                                    const EllipticalGapModel::Traction &t_ref) const
  {
    std::vector<std::vector<double>> K(extensions.size());
    for (unsigned int r = 0; r < extensions.size(); ++r)
      for (const auto &q : extensions[r])
        K[r].push_back(j_integral.signed_stress_intensity_factor(u, t, u_ref, t_ref, q));
    return K;
  }

  std::vector<std::vector<double>> FrontStressIntensity::sifs(const DisplacementVector           &u,
                                                              const EllipticalGapModel::Traction &t) const
  {
    std::vector<std::vector<double>> K(extensions.size());
    for (unsigned int r = 0; r < extensions.size(); ++r)
      for (const auto &q : extensions[r])
        K[r].push_back(j_integral.stress_intensity_factor(u, t, q));
    return K;
  }
} // namespace penny
