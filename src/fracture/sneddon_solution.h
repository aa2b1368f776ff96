// Closed forms for a penny-shaped crack of radius c in an infinite isotropic
// solid whose faces carry an axisymmetric traction p(r) (Sneddon 1946), with
// E' = E/(1 - nu^2):
//   K_I  = 2/sqrt(pi c) int_0^c r p(r)/sqrt(c^2 - r^2) dr
//   w(r) = 4/(pi E') int_r^c dt/sqrt(t^2 - r^2) int_0^t s p(s)/sqrt(t^2 - s^2) ds
// (w is the opening of one face; the gap volume counts both faces).
// Uniform and parabolic loads have exact formulas; any other load is
// integrated by adaptive Gauss-Kronrod quadrature after substitutions that
// remove the inverse square-root singularities.
#pragma once

#include "fe/face_load.h"

namespace penny
{
  class SneddonSolution
  {
  public:
    SneddonSolution(const FaceLoad &load, double gap_radius, double plane_strain_modulus);

    // Exact where a formula exists, quadrature otherwise.
    double stress_intensity_factor() const;
    double opening(double r) const;
    double gap_volume() const;

    // Always by quadrature, whatever the load.
    double stress_intensity_factor_by_quadrature() const;
    double opening_by_quadrature(double r) const;
    double gap_volume_by_quadrature() const;

  private:
    const FaceLoad &load;
    const double    c;
    const double    e_prime;
  };
} // namespace penny
