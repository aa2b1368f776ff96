// Closed forms for a flat elliptical crack x^2/a^2 + y^2/b^2 < 1 (a >= b) on
// z = 0 in an infinite isotropic solid, both faces under a uniform pressure p
// (Green & Sneddon 1950, Irwin 1962). With k^2 = 1 - b^2/a^2, E(k) the
// complete elliptic integral of the second kind and E' = E/(1 - nu^2):
//   w(x, y) = 2 p b/(E' E(k)) sqrt(1 - x^2/a^2 - y^2/b^2)          (one face)
//   K_I(phi) = p sqrt(pi b)/E(k) (sin^2 phi + (b/a)^2 cos^2 phi)^(1/4)
//   V = 8 pi p a b^2/(3 E' E(k))                                    (both faces)
// at the front point (a cos phi, b sin phi): phi is the parametric angle, not
// the polar angle of that point. The circle b = a gives Sneddon's
// 2 p sqrt(a/pi), 4 p sqrt(a^2 - r^2)/(pi E') and 16 p a^3/(3 E').
// K_I follows from w: near the front w ~ (4 K_I/E') sqrt(d/(2 pi)), d the
// distance from the front. The scenes take GalinSolution below, which for the
// uniform pressure reduces to this one; this one is the tests' check of it.
#pragma once

#include <array>

namespace penny
{
  class GreenSneddonSolution
  {
  public:
    GreenSneddonSolution(double semi_axis_a, double semi_axis_b, double pressure,
                         double plane_strain_modulus);

    double stress_intensity_factor(double parametric_angle) const;
    // Opening of one face at (x, y) inside the ellipse, 0 outside.
    double opening(double x, double y) const;
    double gap_volume() const;
    // E(k), k^2 = 1 - b^2/a^2.
    double elliptic_integral() const { return elliptic_e; }

  private:
    const double a;
    const double b;
    const double p;
    const double e_prime;
    const double elliptic_e;
  };

  // A face traction even in x and y and at most quadratic,
  // t = t_0 + t_xx x^2 + t_yy y^2 (Pa; t_xx, t_yy in Pa/m^2): the uniform
  // pressure, the summit tension P (1 - x^2/Ax^2 - y^2/Ay^2), and the unit
  // loads 1, x^2, y^2 of which every such traction is a combination.
  struct QuadraticTraction
  {
    double constant = 0;
    double xx       = 0;
    double yy       = 0;

    double operator()(const double x, const double y) const { return constant + xx * x * x + yy * y * y; }
  };

  // The same elliptical crack under any QuadraticTraction (doc/theory.md,
  // section 8). By Galin's theorem the opening of one face is
  //   w = sqrt(1 - x^2/a^2 - y^2/b^2) (C_0 + C_1 x^2 + C_2 y^2),
  // and the face traction of such a w inside the ellipse,
  // t = -(E'/(4 pi)) Laplacian int w(s)/|x - s| ds, is quadratic again: the
  // potentials of these layers are Dyson's (Ferrers') potentials of an
  // ellipsoid flattened onto z = 0, which reduce to the integrals
  //   J_mn = int_0^inf du / ((a^2 + u)^(m + 1/2) (b^2 + u)^(n + 1/2) u^(1/2)),
  // evaluated by adaptive Gauss-Kronrod quadrature. A 3 x 3 linear system
  // gives C from t, and from w near the front
  //   K_I(phi) = (E' sqrt(pi)/2) (C_0 + C_1 a^2 cos^2 phi + C_2 b^2 sin^2 phi)
  //              (cos^2 phi/a^2 + sin^2 phi/b^2)^(1/4).
  // The uniform pressure is Green and Sneddon's solution above; K_I(phi) is
  // the front polynomial C_0 + ... times a positive factor, so a traction can
  // make K_I vanish at phi = 0 and pi/2 only by making it vanish everywhere.
  class GalinSolution
  {
  public:
    GalinSolution(double semi_axis_a, double semi_axis_b, const QuadraticTraction &traction,
                  double plane_strain_modulus);

    double stress_intensity_factor(double parametric_angle) const;
    // Opening of one face at (x, y) inside the ellipse, 0 outside.
    double opening(double x, double y) const;
    // Volume between the faces (both faces' openings).
    double gap_volume() const;
    // C_0 (m), C_1, C_2 (1/m) of the opening polynomial.
    const std::array<double, 3> &opening_polynomial() const { return coefficients; }

  private:
    const double          a;
    const double          b;
    const double          e_prime;
    std::array<double, 3> coefficients;
  };
} // namespace penny
