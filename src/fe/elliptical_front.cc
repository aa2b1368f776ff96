#include "fe/elliptical_front.h"

#include "numerics/root_finding.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penny
{
  using namespace dealii;

  EllipticalFront::EllipticalFront(const double semi_axis_a, const double semi_axis_b)
      : a(semi_axis_a), b(semi_axis_b)
  {
  }

  Point<3> EllipticalFront::point(const double phi) const
  {
    return {a * std::cos(phi), b * std::sin(phi), 0};
  }

  Tensor<1, 3> EllipticalFront::unit_tangent(const double phi) const
  {
    const Tensor<1, 3> t({-a * std::sin(phi), b * std::cos(phi), 0});
    return t / t.norm();
  }

  Tensor<1, 3> EllipticalFront::unit_normal(const double phi) const
  {
    const Tensor<1, 3> n({b * std::cos(phi), a * std::sin(phi), 0});
    return n / n.norm();
  }

  double EllipticalFront::arc_length_rate(const double phi) const
  {
    return std::hypot(a * std::sin(phi), b * std::cos(phi));
  }

  double EllipticalFront::curvature(const double phi) const
  {
    return a * b / std::pow(arc_length_rate(phi), 3);
  }

  double EllipticalFront::tangent_distance(const double phi) const
  {
    return a * b / arc_length_rate(phi);
  }

  double EllipticalFront::tangent_distance_rate(const double phi) const
  {
    return -(a * a - b * b) * std::sin(phi) * std::cos(phi) * curvature(phi);
  }

  double EllipticalFront::front_coordinate(const double phi) const
  {
    return (phi + std::atan2(a * std::sin(phi), b * std::cos(phi))) / 2;
  }

  double EllipticalFront::front_coordinate_rate(const double phi) const
  {
    return (1 + a * b / std::pow(arc_length_rate(phi), 2)) / 2;
  }

  // On [0, pi/2], psi - phi = (alpha - phi)/2 lies in [0, pi/4]: the root is
  // bracketed by [psi - pi/4, psi]. Beyond, by the symmetries.
  double EllipticalFront::parametric_angle(const double psi) const
  {
    if (!(psi >= -M_PI / 2 && psi <= M_PI))
      throw std::invalid_argument("EllipticalFront::parametric_angle: psi must lie in [-pi/2, pi]");
    if (psi < 0)
      return -parametric_angle(-psi);
    if (psi > M_PI / 2)
      return M_PI - parametric_angle(M_PI - psi);
    if (psi == 0 || psi == M_PI / 2 || a == b)
      return psi;
    const auto   residual = [&](const double phi) { return front_coordinate(phi) - psi; };
    const double lo       = std::max(0., psi - M_PI / 4);
    return bracketed_root(residual, lo, psi, residual(lo), residual(psi), closed_form_root_bits);
  }

  // The nearest point of the ellipse to (x, y), by Eberly's robust bisection
  // ("Distance from a point to an ellipse", 2013): with z_i = y_i/e_i it is
  // x_i = e_i^2 y_i/(s + e_i^2) for the root s of
  // sum (e_i y_i/(s + e_i^2))^2 = 1, bracketed and bisected to machine
  // precision. The nearest point to x in 3D has the same (x, y).
  EllipticalFront::Coordinates EllipticalFront::local_coordinates(const Point<3> &x) const
  {
    const double y0 = std::abs(x[0]), y1 = std::abs(x[1]);
    double       x0, x1;
    if (y1 > 0 && y0 > 0)
      {
        const double z0 = y0 / a, z1 = y1 / b, g = z0 * z0 + z1 * z1 - 1;
        if (g == 0)
          x0 = y0, x1 = y1;
        else
          {
            // s in units of b^2: root of F(s) = (r0 z0/(s + r0))^2 + (z1/(s + 1))^2 - 1,
            // convex and decreasing on s > -1, bracketed by [s0, s1]. Newton's
            // method from the lower end climbs to the root monotonically (the
            // tangent of a convex function lies below it), and stops when
            // rounding ends the climb; bisection where rounding breaks that.
            const double r0 = (a / b) * (a / b), n0 = r0 * z0;
            double       s0 = z1 - 1, s1 = g < 0 ? 0 : std::hypot(n0, z1) - 1, s = s0;
            for (unsigned int iteration = 0; iteration < 200; ++iteration)
              {
                const double f0 = n0 / (s + r0), f1 = z1 / (s + 1), F = f0 * f0 + f1 * f1 - 1;
                if (F <= 0)
                  {
                    s1 = s;
                    s  = (s0 + s1) / 2;
                    if (s == s0 || s == s1)
                      break;
                    continue;
                  }
                s0                = s;
                const double next = s + F / (2 * (f0 * f0 / (s + r0) + f1 * f1 / (s + 1)));
                if (!(next > s))
                  break;
                s = std::min(next, s1);
              }
            x0 = r0 * y0 / (s + r0);
            x1 = y1 / (s + 1);
          }
      }
    else if (y1 > 0)
      x0 = 0, x1 = b;
    else if (a * y0 < a * a - b * b)
      {
        // On the major axis inside the evolute: two nearest points, take y >= 0.
        const double ratio = a * y0 / (a * a - b * b);
        x0 = a * ratio, x1 = b * std::sqrt(1 - ratio * ratio);
      }
    else
      x0 = a, x1 = 0;

    const double in_plane = std::hypot(y0 - x0, y1 - x1);
    const bool   outside  = (y0 / a) * (y0 / a) + (y1 / b) * (y1 / b) > 1;
    const double advance  = outside ? in_plane : -in_plane;
    return {std::atan2(std::copysign(x1, x[1]) / b, std::copysign(x0, x[0]) / a), std::hypot(advance, x[2]),
            std::atan2(x[2], advance)};
  }

  bool EllipticalFront::contains(const Point<3> &x) const
  {
    return std::abs(x[2]) < 1e-12 * a &&
           std::abs((x[0] / a) * (x[0] / a) + (x[1] / b) * (x[1] / b) - 1) < 1e-10;
  }

  std::vector<double> front_vertex_angles(const Triangulation<3> &triangulation, const EllipticalFront &front)
  {
    const double        a = front.semi_axis_a(), b = front.semi_axis_b();
    std::vector<double> local;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const Point<3> &x = cell->vertex(v);
            if (front.contains(x))
              local.push_back(std::atan2(x[1] / b, x[0] / a));
          }
    std::vector<double> angles;
    for (const auto &part : Utilities::MPI::all_gather(triangulation.get_communicator(), local))
      angles.insert(angles.end(), part.begin(), part.end());
    std::sort(angles.begin(), angles.end());
    // A vertex is shared by several cells (and ranks): keep one of each.
    angles.erase(std::unique(angles.begin(), angles.end(),
                             [](const double x, const double y) { return y - x < 1e-12; }),
                 angles.end());
    return angles;
  }
} // namespace penny
