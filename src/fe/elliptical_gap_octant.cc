#include "fe/elliptical_gap_mesh_internal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace penny
{
  using namespace dealii;
  using internal::check;

  namespace
  {
    // The block around the front in the reference meridian half-plane:
    // 1 - w <= r <= 1 + w, 0 <= theta <= w.
    constexpr double tube_half_width = 0.4;
    // Radial thickness of a shell over its cells' angular width inside
    // r = 1 - w (beyond the tube: EllipticalGapMeshParameters).
    constexpr double inner_shell_aspect = 1.5;
    // The angular width that sets the shells' thickness and the rows above the
    // tube: that of the cells along the front, but never below that of 16 of
    // them, so that a finer front adds cells like m^2, not m^3.
    double radial_angle(const unsigned int m)
    {
      return std::max(M_PI / (4 * m), M_PI / 32);
    }
    constexpr double innermost_sphere = 0.35;

    // The box in the reference space: R x R a/b x H sqrt(a/b).
    Tensor<1, 3> reference_box(const EllipticalGapMeshParameters &p)
    {
      return Tensor<1, 3>({p.domain_width, p.domain_width * p.semi_axis_a / p.semi_axis_b,
                           p.domain_height * std::sqrt(p.semi_axis_a / p.semi_axis_b)});
    }

    // The gap whose rings and outer shells the mesh counts: p's own, or the
    // one of b/a = counts_aspect_ratio.
    EllipticalGapMeshParameters counted(const EllipticalGapMeshParameters &p)
    {
      EllipticalGapMeshParameters gap = p;
      if (p.counts_aspect_ratio > 0)
        gap.semi_axis_b = p.counts_aspect_ratio * p.semi_axis_a;
      return gap;
    }

    // Cos and sin of i pi/n, exact where they are 0 or +-1, so that vertices on
    // the planes x = 0, y = 0, z = 0 lie on them exactly.
    std::array<double, 2> cos_sin(const unsigned int i, const unsigned int n)
    {
      if (2 * i == n)
        return {{0, 1}};
      if (i == 0 || i == n)
        return {{i == 0 ? 1. : -1., 0}};
      return {{std::cos(i * M_PI / n), std::sin(i * M_PI / n)}};
    }
  } // namespace

  namespace internal
  {
    ReferenceOctant::ReferenceOctant(const EllipticalGapMeshParameters &p)
        : scale({p.semi_axis_a, p.semi_axis_b, std::sqrt(p.semi_axis_a * p.semi_axis_b)}),
          m(p.cells_along_front / 2), sectors(p.cells_around_front), tube_rows(sectors / 4),
          upper_rows(std::max(1L, std::lround(0.3 / radial_angle(m)))), rows(tube_rows + upper_rows),
          rings(front_ring_radii(p)), box(reference_box(p)), front(p.semi_axis_a, p.semi_axis_b),
          turn(p.semi_axis_a, p.semi_axis_b)
    {
      const double angle   = radial_angle(m);
      const double inner_g = std::exp(inner_shell_aspect * angle);
      const double outer_g = std::exp(p.outer_shell_aspect * angle);
      const double w       = tube_half_width;
      check(std::min({box[0], box[1], box[2]}) >= 2 * (1 + w),
            "the box must reach at least 2.8 a along x and y and 2.8 sqrt(a b) along z");

      tube_inner = 1 + std::max(0L, std::lround(std::log((1 - w) / innermost_sphere) / std::log(inner_g)));
      tube_outer = tube_inner + sectors / 2;
      radii.resize(tube_outer + 1);
      for (unsigned int s = 1; s <= tube_inner; ++s)
        radii[s] = (1 - w) * std::pow(inner_g, static_cast<double>(s) - tube_inner);
      // Shells through the nodes of the web's top edge, t = w cot(theta_i).
      for (unsigned int q = 0; q <= sectors / 2; ++q)
        {
          const auto [c, s]     = cos_sin(3 * sectors / 4 - q, sectors);
          radii[tube_inner + q] = 1 + w * c / s;
        }
      const Tensor<1, 3> counted_box = reference_box(counted(p));
      const double       mean_box    = std::cbrt(counted_box[0] * counted_box[1] * counted_box[2]);
      n_shells = tube_outer + std::max(1L, std::lround(std::log(mean_box / (1 + w)) / std::log(outer_g)));
      core     = radii[1] / (std::sqrt(3.) * inner_g);
    }

    Point<3> ReferenceOctant::lattice_point(const unsigned int s, const unsigned int i, const unsigned int j,
                                            const unsigned int l) const
    {
      // The height scale's weight: 1 on the X and Y patches, falling to 0
      // across the Z patch and the core towards the z-axis.
      const double across = (i == m || j == m) && s > 0 ? 1. : static_cast<double>(std::max(i, j)) / m;
      if (s == 0)
        return physical(core * cube_point(i, j, l), across);
      if (s <= tube_outer)
        return physical(Point<3>(radii[s] * direction(i, j, l)), across);
      // Blended shells, in physical space (in the reference space, whose box
      // is R x R a/b x H sqrt(a/b), the blend folds cells of slender gaps):
      // per node, the direction turning from the last sphere's node to the
      // box's and the distance growing geometrically.
      const Point<3> inner = physical(Point<3>(radii[tube_outer] * direction(i, j, l)), across);
      const Point<3> outer =
          physical(Point<3>(box[0] * cube_point(i, j, l)[0], box[1] * cube_point(i, j, l)[1],
                            box[2] * cube_point(i, j, l)[2]),
                   0);
      if (s == n_shells)
        return outer;
      const double       lambda = static_cast<double>(s - tube_outer) / (n_shells - tube_outer);
      const Tensor<1, 3> blend  = (1 - lambda) * inner / inner.norm() + lambda * outer / outer.norm();
      return Point<3>(inner.norm() * std::pow(outer.norm() / inner.norm(), lambda) * blend / blend.norm());
    }

    Point<3> ReferenceOctant::web_point(const unsigned int e, const Point<2> &node) const
    {
      const auto [cp, sp] = cos_sin(e, 4 * m);
      const double r = 1 + node[0], ct = std::cos(node[1]), st = std::sin(node[1]);
      return physical(Point<3>(r * ct * cp, r * ct * sp, r * st), 1);
    }

    Point<2> ReferenceOctant::web_node(const unsigned int e, const unsigned int k, const unsigned int i) const
    {
      const auto [c, s] = cos_sin(i, sectors);
      if (k + 1 == rings[0].size())
        return Point<2>(c, s) * (tube_half_width / std::max(std::abs(c), s));
      // Odd nodes sit further out, so that the kites have right angles at
      // their even nodes; every ring is a scaled copy of the kites' outline.
      const double radius = rings[e][k] / (i % 2 == 1 ? std::cos(M_PI / sectors) : 1.);
      return Point<2>(c, s) * radius;
    }

    double ReferenceOctant::row_latitude(const unsigned int l) const
    {
      return l == tube_rows ? tube_half_width : tube_half_width * std::tan(l * M_PI / sectors);
    }

    // Height of row l over the cube face at parameter u: the tube rows at
    // fixed latitudes, the rows above spaced evenly up to the cube's top.
    double ReferenceOctant::row_height(const double u, const unsigned int l) const
    {
      if (l == rows)
        return 1;
      const double secant = std::sqrt(1 + u * u);
      if (l <= tube_rows)
        return std::tan(row_latitude(l)) * secant;
      const double top_of_tube = std::tan(tube_half_width) * secant;
      return top_of_tube + (1 - top_of_tube) * (l - tube_rows) / upper_rows;
    }

    // Point (i, j, l) of the lattice in the unit cube; on its surface when
    // i = m, j = m or l = rows.
    Point<3> ReferenceOctant::cube_point(const unsigned int i, const unsigned int j,
                                         const unsigned int l) const
    {
      return {u(i), u(j), row_height(u(i) * u(j), l)};
    }

    // Unit direction of a surface node: on the X and Y patches from its
    // latitude and longitude, on the Z patch the projected cube point.
    Tensor<1, 3> ReferenceOctant::direction(const unsigned int i, const unsigned int j,
                                            const unsigned int l) const
    {
      if (i == m || j == m)
        {
          const unsigned int e   = i == m ? j : 2 * m - i;
          const double       par = u(i == m ? j : i);
          const double       theta =
              l <= tube_rows ? row_latitude(l) : std::atan(row_height(par, l) / std::sqrt(1 + par * par));
          const auto [cp, sp] = cos_sin(e, 4 * m);
          return Tensor<1, 3>({std::cos(theta) * cp, std::cos(theta) * sp, std::sin(theta)});
        }
      const Point<3> p = cube_point(i, j, l);
      return p / p.norm();
    }

    // Physical point of a reference point at polar angle psi in the
    // reference plane: where weight = 1 (every node of the swept cells) the
    // parametric angle phi of front coordinate psi, the height scale h(phi)
    // and the columns' turn; where it is 0 (the z-axis, the box) the angle
    // psi, the height sqrt(a b) and no turn; blended between. The planes
    // x = 0 and y = 0 map onto themselves exactly.
    Point<3> ReferenceOctant::physical(const Point<3> &reference, const double weight) const
    {
      const double X = reference[0], Y = reference[1], R = std::hypot(X, Y);
      if (X == 0 || Y == 0)
        return {scale[0] * X, scale[1] * Y,
                ((1 - weight) * scale[2] + weight * (Y == 0 ? scale[0] : scale[1])) * reference[2]};
      const double psi = std::atan2(Y, X), phi = front.parametric_angle(psi);
      const double height = (1 - weight) * scale[2] + weight * front.tangent_distance(phi);
      const double angle  = weight * (phi - psi + turn(std::cos(phi), std::sin(phi), R, reference[2]).turn);
      const double c = std::cos(angle), s = std::sin(angle);
      return {scale[0] * (c * X - s * Y), scale[1] * (s * X + c * Y), height * reference[2]};
    }
  } // namespace internal

  namespace
  {
    // The innermost ring radius of each column (see front_ring_radii).
    std::vector<double> innermost_ring_radii(const EllipticalGapMeshParameters &p)
    {
      const unsigned int    columns = p.cells_along_front + 1;
      const EllipticalFront front(p.semi_axis_a, p.semi_axis_b);
      std::vector<double>   innermost(columns);
      for (unsigned int e = 0; e < columns; ++e)
        {
          const double phi = front.parametric_angle(e * M_PI / (2 * p.cells_along_front));
          innermost[e]     = p.front_cell_size * std::min(p.semi_axis_b, 1 / front.curvature(phi)) /
                         front.tangent_distance(phi);
        }
      for (unsigned int e = 1; e < columns; ++e)
        innermost[e] = std::min(innermost[e], p.ring_ratio * innermost[e - 1]);
      for (unsigned int e = columns - 1; e-- > 0;)
        innermost[e] = std::min(innermost[e], p.ring_ratio * innermost[e + 1]);
      return innermost;
    }
  } // namespace

  // Rings of each column e = 0 ... cells_along_front (front coordinate
  // e pi/(2 cells_along_front), parametric angle phi_e) in the reference meridian plane,
  // geometric from the innermost to the tube boundary. The
  // innermost is front_cell_size x min(b, radius of curvature) in physical
  // distance (divided by h(phi_e), the chart's distance across the front per
  // unit of r), but at most ring_ratio times that of a neighbouring column,
  // so that a ring never jumps by more than one ring's growth from one column
  // to the next. Every column has as many rings as the nominal ratio needs
  // on the widest span of the counted gap.
  std::vector<std::vector<double>> front_ring_radii(const EllipticalGapMeshParameters &p)
  {
    check(p.front_cell_size > 0 && p.front_cell_size < tube_half_width / 1.2,
          "front_cell_size must lie in (0, " + std::to_string(tube_half_width / 1.2) + ")");
    check(p.ring_ratio > 1, "ring_ratio must exceed 1");
    const std::vector<double> innermost         = innermost_ring_radii(p);
    const std::vector<double> counted_innermost = innermost_ring_radii(counted(p));
    const double smallest = *std::min_element(counted_innermost.begin(), counted_innermost.end());
    const long   n = std::max(1L, std::lround(std::log(tube_half_width / smallest) / std::log(p.ring_ratio)));
    std::vector<std::vector<double>> radii(innermost.size(), std::vector<double>(n + 1));
    for (unsigned int e = 0; e < innermost.size(); ++e)
      for (long k = 0; k <= n; ++k)
        radii[e][k] =
            k == n ? tube_half_width : innermost[e] * std::pow(tube_half_width / innermost[e], double(k) / n);
    return radii;
  }
} // namespace penny
