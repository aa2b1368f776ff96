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
// distance from the front.
#pragma once

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
} // namespace penny
