#include "fracture/sneddon_solution.h"

#include <deal.II/base/numbers.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>

namespace penny
{
  namespace
  {
    constexpr double pi = dealii::numbers::PI;

    template <typename F> double integrate(const F &f, const double a, const double b)
    {
      return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, a, b, 15, 1e-14);
    }
  } // namespace

  SneddonSolution::SneddonSolution(const FaceLoad &load, const double gap_radius,
                                   const double plane_strain_modulus)
      : load(load), c(gap_radius), e_prime(plane_strain_modulus)
  {
  }

  double SneddonSolution::stress_intensity_factor() const
  {
    const double P = load.peak_tension();
    const double a = load.tension_radius();
    switch (load.type())
      {
      case FaceLoad::Type::uniform:
        return 2 * P * std::sqrt(c / pi);
      case FaceLoad::Type::parabolic:
        return 2 * P * std::sqrt(c / pi) * (1 - 2 * c * c / (3 * a * a));
      default:
        return stress_intensity_factor_by_quadrature();
      }
  }

  double SneddonSolution::opening(const double r) const
  {
    const double P    = load.peak_tension();
    const double a    = load.tension_radius();
    const double root = std::sqrt(std::max(c * c - r * r, 0.));
    switch (load.type())
      {
      case FaceLoad::Type::uniform:
        return 4 * P * root / (pi * e_prime);
      case FaceLoad::Type::parabolic:
        return 4 * P * root / (pi * e_prime) * (1 - 2 * (c * c + 2 * r * r) / (9 * a * a));
      default:
        return opening_by_quadrature(r);
      }
  }

  double SneddonSolution::gap_volume() const
  {
    const double P = load.peak_tension();
    const double a = load.tension_radius();
    switch (load.type())
      {
      case FaceLoad::Type::uniform:
        return 16 * P * c * c * c / (3 * e_prime);
      case FaceLoad::Type::parabolic:
        return 16 * P * c * c * c / (3 * e_prime) * (1 - 2 * c * c / (5 * a * a));
      default:
        return gap_volume_by_quadrature();
      }
  }

  // With r = c sin(theta): int_0^c r p/sqrt(c^2 - r^2) dr = c int_0^{pi/2} sin(theta) p(c sin(theta)).
  double SneddonSolution::stress_intensity_factor_by_quadrature() const
  {
    const double integral =
        integrate([&](const double theta) { return std::sin(theta) * load(c * std::sin(theta)); }, 0, pi / 2);
    return 2 / std::sqrt(pi * c) * c * integral;
  }

  // The inner integral over s is t G(t) with G(t) = int_0^{pi/2} sin(theta) p(t sin(theta));
  // the outer one, with u = sqrt(t^2 - r^2), becomes int_0^{sqrt(c^2 - r^2)} G(t(u)) du.
  double SneddonSolution::opening_by_quadrature(const double r) const
  {
    const auto inner = [&](const double t) {
      return integrate([&](const double theta) { return std::sin(theta) * load(t * std::sin(theta)); }, 0,
                       pi / 2);
    };
    const double outer = integrate([&](const double u) { return inner(std::sqrt(r * r + u * u)); }, 0,
                                   std::sqrt(std::max(c * c - r * r, 0.)));
    return 4 / (pi * e_prime) * outer;
  }

  // Both faces: 2 int_0^c 2 pi r w(r) dr; with r = c sin(phi) the root at r = c is resolved.
  double SneddonSolution::gap_volume_by_quadrature() const
  {
    const double integral = integrate(
        [&](const double phi) {
          const double r = c * std::sin(phi);
          return r * opening_by_quadrature(r) * c * std::cos(phi);
        },
        0, pi / 2);
    return 4 * pi * integral;
  }
} // namespace penny
