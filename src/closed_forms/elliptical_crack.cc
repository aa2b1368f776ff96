#include "closed_forms/elliptical_crack.h"

#include <deal.II/base/tensor.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
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

    // J_mn = int_0^inf du / ((a^2 + u)^(m + 1/2) (b^2 + u)^(n + 1/2) u^(1/2))
    //      = 2 b^(-2n) int_0^(pi/2) cos^(2(m + n)) t / (a^2 cos^2 t + b^2 sin^2 t)^(m + 1/2) dt
    // (u = b^2 tan^2 t), split where the integrand turns for slender ellipses.
    double dyson_integral(const unsigned int m, const unsigned int n, const double a, const double b)
    {
      const auto integrand = [&](const double t) {
        const double c = std::cos(t), s = std::sin(t);
        return std::pow(c, 2. * (m + n)) / std::pow(a * a * c * c + b * b * s * s, m + 0.5);
      };
      // A relative tolerance of 1e-13: below that, rounding keeps the Kronrod
      // error estimate from converging and the recursion runs to its depth
      // limit (1e8 evaluations, seconds, for the circle).
      using Rule         = boost::math::quadrature::gauss_kronrod<double, 31>;
      const double split = std::atan(a / b);
      return 2 * std::pow(b, -2. * n) *
             (Rule::integrate(integrand, 0., split, 15, 1e-13) +
              Rule::integrate(integrand, split, M_PI / 2, 15, 1e-13));
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

  // The traction of w = sqrt(1 - x^2/a^2 - y^2/b^2) q(x, y) inside the ellipse
  // for q = 1, x^2, y^2 (the columns), as coefficients of 1, x^2, y^2 (the
  // rows). With A = a^2 + u, B = b^2 + u, X = x^2/A + y^2/B, the layer
  // potentials are (doc/theory.md, section 8)
  //   q = 1:    (pi a b/2) int (1 - X) du/sqrt(A B u),
  //   q = x^2:  (pi b a^4/4) d/d(a^2) [a int (1 - X)^2 du/sqrt(A B u)],
  // and y^2 with the roles of (a, x) and (b, y) exchanged; the Laplacian
  // acts on X under the integral, and d/d(a^2) J_mn = -(m + 1/2) J_(m+1)n.
  GalinSolution::GalinSolution(const double semi_axis_a, const double semi_axis_b,
                               const QuadraticTraction &traction, const double plane_strain_modulus)
      : a(semi_axis_a), b(semi_axis_b), e_prime(plane_strain_modulus)
  {
    if (!(b > 0 && a >= b))
      throw std::invalid_argument("GalinSolution: the semi-axes must satisfy a >= b > 0");
    const auto   J   = [&](const unsigned int m, const unsigned int n) { return dyson_integral(m, n, a, b); };
    const double J10 = J(1, 0), J01 = J(0, 1), J20 = J(2, 0), J11 = J(1, 1), J02 = J(0, 2);
    const double J30 = J(3, 0), J21 = J(2, 1), J12 = J(1, 2), J03 = J(0, 3);
    // Laplacian of (1 - X)^2 integrated: S_0 + S_x x^2 + S_y y^2.
    const double S_0 = -4 * (J10 + J01), S_x = 12 * J20 + 4 * J11, S_y = 12 * J02 + 4 * J11;

    dealii::Tensor<2, 3> T;
    T[0][0]          = e_prime * a * b / 4 * (J10 + J01);
    const double f_x = -e_prime * b * std::pow(a, 4) / 16;
    T[0][1]          = f_x * (S_0 / (2 * a) + a * (6 * J20 + 2 * J11));
    T[1][1]          = f_x * (S_x / (2 * a) - a * (30 * J30 + 6 * J21));
    T[2][1]          = f_x * (S_y / (2 * a) - a * (6 * J12 + 6 * J21));
    const double f_y = -e_prime * a * std::pow(b, 4) / 16;
    T[0][2]          = f_y * (S_0 / (2 * b) + b * (6 * J02 + 2 * J11));
    T[1][2]          = f_y * (S_x / (2 * b) - b * (6 * J21 + 6 * J12));
    T[2][2]          = f_y * (S_y / (2 * b) - b * (30 * J03 + 6 * J12));

    const dealii::Tensor<1, 3> C =
        dealii::invert(T) * dealii::Tensor<1, 3>({traction.constant, traction.xx, traction.yy});
    coefficients = {{C[0], C[1], C[2]}};
  }

  // Near the front at distance d, 1 - x^2/a^2 - y^2/b^2 ~ 2 d (cos^2/a^2 + sin^2/b^2)^(1/2),
  // and w ~ (4 K_I/E') sqrt(d/(2 pi)).
  double GalinSolution::stress_intensity_factor(const double phi) const
  {
    const double c = std::cos(phi), s = std::sin(phi);
    const double front_polynomial =
        coefficients[0] + coefficients[1] * a * a * c * c + coefficients[2] * b * b * s * s;
    return e_prime * std::sqrt(M_PI) / 2 * front_polynomial *
           std::pow(c * c / (a * a) + s * s / (b * b), 0.25);
  }

  double GalinSolution::opening(const double x, const double y) const
  {
    const double inside = 1 - (x / a) * (x / a) - (y / b) * (y / b);
    return inside > 0
               ? std::sqrt(inside) * (coefficients[0] + coefficients[1] * x * x + coefficients[2] * y * y)
               : 0.;
  }

  // 2 int w dA with int sqrt(1 - x^2/a^2 - y^2/b^2) (1, x^2, y^2) dA over the
  // ellipse = (2 pi a b/3) (1, a^2/5, b^2/5).
  double GalinSolution::gap_volume() const
  {
    return 4 * M_PI * a * b / 3 * (coefficients[0] + (coefficients[1] * a * a + coefficients[2] * b * b) / 5);
  }
} // namespace penny
