#include "fracture/front_segment_extension.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // k(t) = (1 - t^2)^4 p(t^2) on |t| < 1 and its derivative, with p such that
    // the moments of orders 1 to `moments` of k vanish (the odd ones by
    // symmetry). The moments int t^2j (1 - t^2)^4 dt are in the ratios 1, 1/11,
    // 3/143, 1/143, 7/2431, 63/46189, 3/4199 for j = 0 ... 6, so that
    //   moments 5: p(u) = 1 - 10 u + 17 u^2,
    //     1/11 - 10 (3/143) + 17/143 = 0, 3/143 - 10/143 + 17 (7/2431) = 0;
    //   moments 7: p(u) = 1 - 17 u + (323/5) u^2 (1 - u),
    //     1/11 - 17 (3/143) + (323/5)(1/143 - 7/2431) = 0,
    //     3/143 - 17/143 + (323/5)(7/2431 - 63/46189) = 0,
    //     1/143 - 17 (7/2431) + (323/5)(63/46189 - 3/4199) = 0.
    std::pair<double, double> moment_free_bump(const double t, const unsigned int moments)
    {
      if (std::abs(t) >= 1)
        return {0., 0.};
      constexpr double c = 323. / 5;
      const double     u = t * t, s = 1 - u, s3 = s * s * s;
      const double     p     = moments == 5 ? 1 - 10 * u + 17 * u * u : 1 - 17 * u + c * u * u * (1 - u);
      const double     dp_du = moments == 5 ? -10 + 34 * u : -17 + c * (2 * u - 3 * u * u);
      return {s3 * s * p, -8 * t * s3 * p + s3 * s * 2 * t * dp_du};
    }
  } // namespace

  const FrontFrame &NearestFrontPoint::operator()(const Point<3> &x) const
  {
    if (!(x == last_point))
      {
        last_point         = x;
        const auto   local = front.local_coordinates(x);
        const double phi   = local.phi;
        last_frame         = {local,
                              front.point(phi),
                              front.unit_normal(phi),
                              front.unit_tangent(phi),
                              front.arc_length_rate(phi),
                              front.curvature(phi),
                              front.front_coordinate(phi),
                              front.front_coordinate_rate(phi)};
      }
    return last_frame;
  }

  FrontSegmentExtension::FrontSegmentExtension(std::shared_ptr<const NearestFrontPoint> nearest,
                                               const double centre, const double half_width,
                                               const unsigned int vanishing_moments, const double ring_radius)
      : nearest(std::move(nearest)), centre(centre), half_width(half_width), moments(vanishing_moments),
        rho(ring_radius)
  {
    if (moments != 5 && moments != 7)
      throw std::invalid_argument("FrontSegmentExtension: the vanishing moments must be 5 or 7");
    if (!(centre >= 0 && centre <= M_PI / 2))
      throw std::invalid_argument("FrontSegmentExtension: the centre must lie in [0, pi/2]");
    if (!(half_width > 0 && half_width <= M_PI / 2))
      throw std::invalid_argument("FrontSegmentExtension: the half-width must lie in (0, pi/2]");
    const double b = front().semi_axis_b(), a = front().semi_axis_a();
    if (!(ring_radius > 0 && ring_radius < b * b / a))
      throw std::invalid_argument("FrontSegmentExtension: the ring radius must lie in (0, b^2/a)");
    centre_coordinate = front().front_coordinate(centre);
    support_begin     = front().parametric_angle(std::max(0., centre_coordinate - half_width));
    support_end       = front().parametric_angle(std::min(M_PI / 2, centre_coordinate + half_width));
    // The support of f in [0, pi/2], split at the centre where k turns.
    const auto integrand = [&](const double phi) { return front_weight(phi) * front().arc_length_rate(phi); };
    const double lo = support_begin, hi = support_end;
    using Rule = boost::math::quadrature::gauss_kronrod<double, 31>;
    measure    = (centre > lo ? Rule::integrate(integrand, lo, centre, 15, 1e-14) : 0.) +
              (hi > centre ? Rule::integrate(integrand, centre, hi, 15, 1e-14) : 0.);
  }

  // The bump in the front coordinate psi and its images about the symmetry
  // planes psi = phi = 0 and psi = phi = pi/2.
  std::pair<double, double> FrontSegmentExtension::weight_and_slope(const double psi, const double rate) const
  {
    double f = 0, df = 0;
    for (const auto &[image, sign] : {std::pair{psi, 1.}, std::pair{-psi, -1.}, std::pair{M_PI - psi, -1.}})
      {
        const auto [k, dk] = moment_free_bump((image - centre_coordinate) / half_width, moments);
        f += k;
        df += sign * dk / half_width * rate;
      }
    return {f, df};
  }

  double FrontSegmentExtension::front_weight(const double phi) const
  {
    return weight_and_slope(front().front_coordinate(phi), front().front_coordinate_rate(phi)).first;
  }

  Tensor<1, 3> FrontSegmentExtension::value(const Point<3> &x) const
  {
    const FrontFrame &frame = (*nearest)(x);
    const double      s     = 1 - (frame.local.distance / rho) * (frame.local.distance / rho);
    if (s <= 0)
      return {};
    const double f = weight_and_slope(frame.psi, frame.psi_rate).first;
    return f * s * s * s * s * frame.normal;
  }

  // grad q = n (x) (f' w grad phi + f w' grad d) + f w dn/dphi (x) grad phi, with
  // grad phi = t/(|dx/dphi| (1 + kappa h)) (h the signed in-plane distance,
  // positive outside the ellipse), grad d = (x - x_front)/d, dn/dphi = kappa |dx/dphi| t.
  Tensor<2, 3> FrontSegmentExtension::gradient(const Point<3> &x) const
  {
    const FrontFrame &frame = (*nearest)(x);
    const auto       &local = frame.local;
    const double      s     = 1 - (local.distance / rho) * (local.distance / rho);
    if (s <= 0)
      return {};
    const auto [f, df] = weight_and_slope(frame.psi, frame.psi_rate);
    if (f == 0 && df == 0)
      return {};
    const double       w = s * s * s * s;
    const Tensor<1, 3> grad_phi =
        frame.tangent / (frame.speed * (1 + frame.curvature * local.distance * std::cos(local.theta)));
    // w' grad d = -8 s^3 d/rho^2 (x - x_front)/d, without the division.
    const Tensor<1, 3> w_grad_d = -8 * s * s * s / (rho * rho) * (x - frame.point);
    return outer_product(frame.normal, df * w * grad_phi + f * w_grad_d) +
           f * w * frame.curvature * frame.speed * outer_product(frame.tangent, grad_phi);
  }

  // A cell may meet the support when its centre lies within rho plus its
  // diameter of the front arc where f is not zero.
  bool FrontSegmentExtension::may_touch(const Triangulation<3>::cell_iterator &cell) const
  {
    const Point<3> x     = cell->center();
    const double   reach = rho + cell->diameter();
    const auto     local = front().local_coordinates(x);
    if (local.distance > reach)
      return false;
    if (local.phi >= support_begin && local.phi <= support_end)
      return true;
    return std::min(x.distance(front().point(support_begin)), x.distance(front().point(support_end))) <=
           reach;
  }

  // The distance d from the front is 1-Lipschitz: over a box of half-diagonal
  // r around its centre it stays within r of d(centre).
  bool FrontSegmentExtension::edge_crosses(const BoundingBox<3> &box) const
  {
    const auto  &corners       = box.get_boundary_points();
    const double half_diagonal = corners.first.distance(corners.second) / 2;
    return std::abs(front().local_coordinates(box.center()).distance - rho) <= half_diagonal;
  }
} // namespace penny
