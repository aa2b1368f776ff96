// Closed forms for a penny-shaped crack of radius c in an infinite isotropic
// solid whose faces carry an axisymmetric traction p(r) (Sneddon 1946), with
// E' = E/(1 - nu^2), each one integral (doc/theory.md, section 1):
//   K_I  = 2/sqrt(pi c) int_0^c r p(r)/sqrt(c^2 - r^2) dr
//   w(0) = 4/(pi E') int_0^c p(s) arccos(s/c) ds
//   V    = 16/E' int_0^c r sqrt(c^2 - r^2) p(r) dr
// (w is the opening of one face; the gap volume counts both faces).
// Uniform and parabolic loads have exact formulas. Any other load is
// integrated over r = c sin(theta), which removes the inverse square root and
// the square-root edge at r = c, by globally adaptive Gauss-Kronrod quadrature
// with a bounded number of load evaluations; the value comes with the
// quadrature's own error estimate, reached or not.
#pragma once

#include "closed_forms/face_load.h"

namespace penny
{
  // A closed-form value and how well it is known.
  struct ClosedForm
  {
    double value;
    double error_estimate; // absolute; 0 for an exact formula
    bool   exact;          // an exact formula, not a quadrature

    // error_estimate/|value|; 0 for an exact formula.
    double relative_error_estimate() const;
  };

  class SneddonSolution
  {
  public:
    SneddonSolution(const FaceLoad &load, double gap_radius, double plane_strain_modulus);

    // Exact where a formula exists, quadrature otherwise.
    ClosedForm stress_intensity_factor() const;
    ClosedForm opening_at_centre() const;
    ClosedForm gap_volume() const;
    // The opening w(r) of one face at 0 <= r <= c; for a general load two
    // nested quadratures, each with at most `profile_evaluations` points.
    ClosedForm opening(double r) const;

    // Always by quadrature, whatever the load.
    ClosedForm stress_intensity_factor_by_quadrature() const;
    ClosedForm opening_at_centre_by_quadrature() const;
    ClosedForm gap_volume_by_quadrature() const;

    // The largest number of load evaluations one quadrature makes.
    static constexpr unsigned int max_evaluations     = 100000;
    static constexpr unsigned int profile_evaluations = 31 * 7;

  private:
    ClosedForm exact_or(double uniform, double n, ClosedForm (SneddonSolution::*quadrature)() const) const;

    const FaceLoad &load;
    const double    c;
    const double    e_prime;
  };
} // namespace penny
