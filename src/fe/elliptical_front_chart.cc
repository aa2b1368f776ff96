#include "fe/elliptical_gap_mesh_internal.h"

#include <array>
#include <cmath>

namespace penny
{
  using namespace dealii;

  namespace internal
  {
    // The columns' turn towards the front's normal. The stretched plane's
    // radial line through the front point at parametric angle phi leans on
    // the front: its step per unit of R, (a cos, b sin), has the component h
    // across the front and (b^2 - a^2) sin cos/|(a sin, b cos)| along it,
    // 5 times larger at phi = pi/4 for b/a = 0.1 (cells sheared by 79
    // degrees). A point at (R, Z) of the meridian plane, at the distance
    // rho = |(R - 1, Z)| from the front, is turned by the angle
    //   S = g lambda tanh(rho/lambda) (R - 1)/rho,  g = (a^2 - b^2) sin cos/H^2,
    // H^2 = b^2 cos^2 + a^2 sin^2, which is g (R - 1) near the front (the
    // turn that cancels the lean: columns leave the front along its normal)
    // and g lambda (R - 1)/rho beyond the depth lambda, varying on the scale
    // rho of the cells there. lambda, in units of r, is a harmonic mean of L,
    // c q (c times the distance to the centre of curvature, where normals
    // cross, q = H^4/(a b)^2) and k H^2/(a^2 - b^2) (so that the largest
    // turn, g lambda <= (k/2) sin 2 phi, keeps psi = phi + S increasing).
    ColumnTurn::Value ColumnTurn::operator()(const double cp, const double sp, const double R,
                                             const double Z) const
    {
      const double d = a * a - b * b, ab2 = a * a * b * b;
      const double H2 = b * b * cp * cp + a * a * sp * sp, dH2 = 2 * d * sp * cp;
      const double g = d * sp * cp / H2, dg = d * ((cp * cp - sp * sp) * H2 - sp * cp * dH2) / (H2 * H2);
      const double q = H2 * H2 / ab2, dq = 2 * H2 * dH2 / ab2;
      const double lambda  = 1 / (d / (k * H2) + 1 / L + 1 / (c * q));
      const double dlambda = lambda * lambda * (d * dH2 / (k * H2 * H2) + dq / (c * q * q));
      // S = T(rho) (R - 1), T = g t(u), t(u) = tanh(u)/u, u = rho/lambda;
      // t and t'(u)/u by their series where u is small.
      const double delta = R - 1, rho2 = delta * delta + Z * Z, u = std::sqrt(rho2) / lambda;
      const double th = std::tanh(u);
      const double t  = u < 1e-3 ? 1 - u * u / 3 : th / u;
      const double t1 = u < 1e-3 ? -2. / 3 + 8 * u * u / 15 : ((1 - th * th) * u - th) / (u * u * u);
      const double T = g * t, dT_over_rho = g * t1 / (lambda * lambda); // dT/drho / rho
      const double dT_dphi = dg * t - g * t1 * rho2 * dlambda / (lambda * lambda * lambda);
      return {T * delta, T + dT_over_rho * delta * delta, dT_over_rho * delta * Z, dT_dphi * delta, g};
    }

    // R and beta from the stretched plane, then phi from beta = phi + S(phi,
    // R, z/h(phi)) by Newton's method kept inside a bracket (the left side
    // increases with phi: h' = -g h, d/dphi = 1 + S_phi + g Z S_Z > 0).
    Point<3> EllipticalFrontChart::pull_back(const Point<3> &x) const
    {
      const double X = x[0] / a, Y = x[1] / b, R = std::hypot(X, Y), beta = std::atan2(Y, X);
      const auto   height = [&](const double phi) { return x[2] / front.tangent_distance(phi); };
      double       lower = beta - M_PI / 2, upper = beta + M_PI / 2, phi = beta;
      for (unsigned int iteration = 0; iteration < 100; ++iteration)
        {
          const double Z        = height(phi);
          const auto   value    = turn(std::cos(phi), std::sin(phi), R, Z);
          const double residual = phi + value.turn - beta;
          if (std::abs(residual) < 1e-15)
            break;
          (residual > 0 ? upper : lower) = phi;
          const double newton = phi - residual / (1 + value.d_phi + value.lean * Z * value.d_height);
          phi                 = newton > lower && newton < upper ? newton : (lower + upper) / 2;
        }
      const double Z = height(phi);
      return {std::hypot(R, Z), std::atan2(Z, R), front.front_coordinate(phi)};
    }

    Point<3> EllipticalFrontChart::push_forward(const Point<3> &chart) const
    {
      const double R = chart[0] * std::cos(chart[1]), Z = chart[0] * std::sin(chart[1]);
      const double phi  = front.parametric_angle(chart[2]);
      const double beta = phi + turn(std::cos(phi), std::sin(phi), R, Z).turn;
      return {a * R * std::cos(beta), b * R * std::sin(beta), front.tangent_distance(phi) * Z};
    }

    DerivativeForm<1, 3, 3> EllipticalFrontChart::push_forward_gradient(const Point<3> &chart) const
    {
      const double r = chart[0], ct = std::cos(chart[1]), st = std::sin(chart[1]);
      const double R = r * ct, Z = r * st, phi = front.parametric_angle(chart[2]);
      const double dphi  = 1 / front.front_coordinate_rate(phi); // dphi/dpsi
      const auto   value = turn(std::cos(phi), std::sin(phi), R, Z);
      const double cb = std::cos(phi + value.turn), sb = std::sin(phi + value.turn);
      // d(R, Z, beta)/d(r, theta, psi)
      const std::array<double, 3> dR = {{ct, -r * st, 0}}, dZ = {{st, r * ct, 0}};
      DerivativeForm<1, 3, 3>     gradient;
      for (unsigned int j = 0; j < 3; ++j)
        {
          const double dbeta =
              value.d_radius * dR[j] + value.d_height * dZ[j] + (j == 2 ? (1 + value.d_phi) * dphi : 0);
          gradient[0][j] = a * (cb * dR[j] - R * sb * dbeta);
          gradient[1][j] = b * (sb * dR[j] + R * cb * dbeta);
          gradient[2][j] = front.tangent_distance(phi) * dZ[j];
        }
      gradient[2][2] = front.tangent_distance_rate(phi) * dphi * Z;
      return gradient;
    }
  } // namespace internal
} // namespace penny
