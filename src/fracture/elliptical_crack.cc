#include "fracture/elliptical_crack.h"

#include <boost/math/special_functions/ellint_2.hpp>

#include <cmath>
#include <stdexcept>

namespace penny
{
  namespace
  {
    double checked_elliptic_integral(const double a, const double b)
    {
      if (!(b > 0 && a >= b))
        throw std::invalid_argument("GreenSneddonSolution: the semi-axes must satisfy a >= b > 0");
      // Boost takes the modulus k, not the parameter m = k^2.
      return boost::math::ellint_2(std::sqrt(1 - (b / a) * (b / a)));
    }
  } // namespace

  GreenSneddonSolution::GreenSneddonSolution(const double semi_axis_a, const double semi_axis_b,
                                             const double pressure, const double plane_strain_modulus)
      : a(semi_axis_a), b(semi_axis_b), p(pressure), e_prime(plane_strain_modulus),
        elliptic_e(checked_elliptic_integral(a, b))
  {
  }

  double GreenSneddonSolution::stress_intensity_factor(const double phi) const
  {
    const double s = std::sin(phi), c = std::cos(phi), ratio = b / a;
    return p * std::sqrt(M_PI * b) / elliptic_e * std::pow(s * s + ratio * ratio * c * c, 0.25);
  }

  double GreenSneddonSolution::opening(const double x, const double y) const
  {
    const double inside = 1 - (x / a) * (x / a) - (y / b) * (y / b);
    return inside > 0 ? 2 * p * b / (e_prime * elliptic_e) * std::sqrt(inside) : 0.;
  }

  // 2 int w dA with int_ellipse sqrt(1 - x^2/a^2 - y^2/b^2) dA = 2 pi a b/3.
  double GreenSneddonSolution::gap_volume() const
  {
    return 8 * M_PI * p * a * b * b / (3 * e_prime * elliptic_e);
  }
} // namespace penny
