#include "closed_forms/sneddon_solution.h"

#include "input/input_error.h"

#include <deal.II/base/numbers.h>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace penny
{
  namespace
  {
    constexpr double pi = dealii::numbers::PI;

    // The quadrature stops when its error estimate falls below this share of int |f|.
    constexpr double relative_tolerance = 1e-14;

    // Globally adaptive Gauss-Kronrod quadrature of f over [a, b]: each piece
    // is integrated by the 31-point Kronrod rule, whose difference to its
    // embedded 15-point Gauss rule is the piece's error estimate (Boost's
    // tables; Boost's own integrate leaves that estimate unscaled by the
    // piece's width), and the piece with the largest estimate is halved until
    // the estimates sum to `relative_tolerance` of int |f|, the evaluations
    // reach `max_evaluations`, or the worst piece is as narrow as rounding
    // allows. Jumps, kinks and integrable singularities cost a few pieces each.
    template <typename F>
    ClosedForm integrate(const F &f, const double a, const double b, const unsigned int max_evaluations)
    {
      using Kronrod                      = boost::math::quadrature::gauss_kronrod<double, 31>;
      using Gauss                        = boost::math::quadrature::gauss<double, 15>;
      constexpr unsigned int rule_points = 31;
      struct Piece
      {
        double a, b, value, error, l1;
      };
      // Kronrod's abscissae are 0 and the positive nodes; every second one is Gauss'.
      const auto measure = [&](const double from, const double to) {
        const double middle = 0.5 * (from + to), half = 0.5 * (to - from);
        const double centre  = f(middle);
        double       kronrod = centre * Kronrod::weights()[0], gauss = centre * Gauss::weights()[0],
               l1 = std::abs(centre) * Kronrod::weights()[0];
        for (unsigned int i = 1; i < Kronrod::abscissa().size(); ++i)
          {
            const double right = f(middle + half * Kronrod::abscissa()[i]);
            const double left  = f(middle - half * Kronrod::abscissa()[i]);
            kronrod += (right + left) * Kronrod::weights()[i];
            l1 += (std::abs(right) + std::abs(left)) * Kronrod::weights()[i];
            if (i % 2 == 0)
              gauss += (right + left) * Gauss::weights()[i / 2];
          }
        // Rounding bounds the estimate from below.
        const double error =
            std::max(std::abs(kronrod - gauss), 2 * std::numeric_limits<double>::epsilon() * l1);
        return Piece{from, to, half * kronrod, half * error, half * l1};
      };
      const auto smaller_error = [](const Piece &p, const Piece &q) { return p.error < q.error; };

      std::vector<Piece> pieces      = {measure(a, b)};
      unsigned int       evaluations = rule_points;
      double             error = pieces[0].error, l1 = pieces[0].l1; // running sums over the pieces
      while (error > relative_tolerance * l1 && evaluations + 2 * rule_points <= max_evaluations)
        {
          std::pop_heap(pieces.begin(), pieces.end(), smaller_error);
          const Piece  worst  = pieces.back();
          const double middle = 0.5 * (worst.a + worst.b);
          if (!(worst.a < middle && middle < worst.b))
            break;
          const Piece left = measure(worst.a, middle), right = measure(middle, worst.b);
          evaluations += 2 * rule_points;
          error += left.error + right.error - worst.error;
          l1 += left.l1 + right.l1 - worst.l1;
          pieces.back() = left;
          std::push_heap(pieces.begin(), pieces.end(), smaller_error);
          pieces.push_back(right);
          std::push_heap(pieces.begin(), pieces.end(), smaller_error);
        }
      ClosedForm result{0, 0, false};
      for (const Piece &piece : pieces)
        {
          result.value += piece.value;
          result.error_estimate += piece.error;
        }
      return result;
    }

    // Each integral over r in [0, c] becomes, with r = c sin(theta),
    // factor int_0^{pi/2} weight(theta) p(c sin(theta)) dtheta.
    template <typename Weight>
    ClosedForm over_the_face(const FaceLoad &load, const double c, const double factor, const Weight &weight)
    {
      const auto integrand = [&](const double theta) {
        const double r = c * std::sin(theta);
        const double p = load(r);
        if (!std::isfinite(p))
          throw std::runtime_error("the face load gives p(" + shortest(r) + " m) = " + shortest(p) +
                                   "; the closed forms need a load that is finite up to the tip r = c");
        return weight(theta) * p;
      };
      ClosedForm integral = integrate(integrand, 0, pi / 2, SneddonSolution::max_evaluations);
      integral.value *= factor;
      integral.error_estimate *= std::abs(factor);
      return integral;
    }
  } // namespace

  double ClosedForm::relative_error_estimate() const
  {
    if (exact)
      return 0;
    return value == 0 ? std::numeric_limits<double>::infinity() : error_estimate / std::abs(value);
  }

  SneddonSolution::SneddonSolution(const FaceLoad &load, const double gap_radius,
                                   const double plane_strain_modulus)
      : load(load), c(gap_radius), e_prime(plane_strain_modulus)
  {
  }

  // The closed form of the uniform load, `uniform`; that of the parabola,
  // `uniform` times 1 - 2 c^2/(n a^2); any other load's by `quadrature`.
  ClosedForm SneddonSolution::exact_or(const double uniform, const double n,
                                       ClosedForm (SneddonSolution::*quadrature)() const) const
  {
    const double a = load.tension_radius();
    switch (load.type())
      {
      case FaceLoad::Type::uniform:
        return {uniform, 0, true};
      case FaceLoad::Type::parabolic:
        return {uniform * (1 - 2 * c * c / (n * a * a)), 0, true};
      default:
        return (this->*quadrature)();
      }
  }

  ClosedForm SneddonSolution::stress_intensity_factor() const
  {
    return exact_or(2 * load.peak_tension() * std::sqrt(c / pi), 3,
                    &SneddonSolution::stress_intensity_factor_by_quadrature);
  }

  ClosedForm SneddonSolution::opening_at_centre() const
  {
    return exact_or(4 * load.peak_tension() * c / (pi * e_prime), 9,
                    &SneddonSolution::opening_at_centre_by_quadrature);
  }

  ClosedForm SneddonSolution::gap_volume() const
  {
    return exact_or(16 * load.peak_tension() * c * c * c / (3 * e_prime), 5,
                    &SneddonSolution::gap_volume_by_quadrature);
  }

  // w(r) = 4/(pi E') int_r^c F(t) t dt/sqrt(t^2 - r^2) with
  // F(t) = int_0^{pi/2} sin(theta) p(t sin(theta)) dtheta; with t^2 = r^2 + u^2,
  // t dt/sqrt(t^2 - r^2) = du. The inner quadratures' largest relative error
  // estimate is added to the outer one's.
  ClosedForm SneddonSolution::opening(const double r) const
  {
    const double P    = load.peak_tension();
    const double a    = load.tension_radius();
    const double root = std::sqrt(std::max(c * c - r * r, 0.));
    switch (load.type())
      {
      case FaceLoad::Type::uniform:
        return {4 * P * root / (pi * e_prime), 0, true};
      case FaceLoad::Type::parabolic:
        return {4 * P * root / (pi * e_prime) * (1 - 2 * (c * c + 2 * r * r) / (9 * a * a)), 0, true};
      default:
        break;
      }
    double     inner_relative_error = 0;
    const auto inner                = [&](const double u) {
      const double     t = std::hypot(r, u);
      const ClosedForm F =
          integrate([&](const double theta) { return std::sin(theta) * load(t * std::sin(theta)); }, 0,
                    pi / 2, profile_evaluations);
      if (F.value != 0)
        inner_relative_error = std::max(inner_relative_error, F.error_estimate / std::abs(F.value));
      return F.value;
    };
    ClosedForm w = integrate(inner, 0, root, profile_evaluations);
    w.value *= 4 / (pi * e_prime);
    w.error_estimate = w.error_estimate * 4 / (pi * e_prime) + inner_relative_error * std::abs(w.value);
    return w;
  }

  // r dr/sqrt(c^2 - r^2) = c sin(theta) dtheta.
  ClosedForm SneddonSolution::stress_intensity_factor_by_quadrature() const
  {
    return over_the_face(load, c, 2 * c / std::sqrt(pi * c),
                         [](const double theta) { return std::sin(theta); });
  }

  // arccos(s/c) ds = (pi/2 - theta) c cos(theta) dtheta.
  ClosedForm SneddonSolution::opening_at_centre_by_quadrature() const
  {
    return over_the_face(load, c, 4 * c / (pi * e_prime),
                         [](const double theta) { return (pi / 2 - theta) * std::cos(theta); });
  }

  // r sqrt(c^2 - r^2) dr = c^3 sin(theta) cos(theta)^2 dtheta.
  ClosedForm SneddonSolution::gap_volume_by_quadrature() const
  {
    return over_the_face(load, c, 16 * c * c * c / e_prime, [](const double theta) {
      return std::sin(theta) * std::cos(theta) * std::cos(theta);
    });
  }
} // namespace penny
