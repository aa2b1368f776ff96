#include "fe/elliptical_gap_mesh.h"

#include "fe/boundary_ids.h"

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace penny
{
  using namespace dealii;

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
    class ColumnTurn
    {
    public:
      ColumnTurn(const double a, const double b) : a(a), b(b) {}

      struct Value
      {
        double turn     = 0; // S
        double d_radius = 0; // dS/dR
        double d_height = 0; // dS/dZ
        double d_phi    = 0; // dS/dphi
        double lean     = 0; // g, also -h'/h
      };

      // S and its derivatives at parametric angle phi (cos, sin given so that
      // they are exact on the symmetry planes), R and Z.
      Value operator()(const double cp, const double sp, const double R, const double Z) const
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

    private:
      static constexpr double c = 0.5; // fraction of the distance to the centre of curvature
      static constexpr double k = 0.5; // bound of the largest turn's derivative in phi
      static constexpr double L = 1;   // largest turning depth, in units of r
      const double            a;
      const double            b;
    };

    // Stretched spherical coordinates (r, theta, psi), psi the front
    // coordinate (EllipticalFront::front_coordinate, in which the columns are
    // evenly spaced) of the parametric angle phi, with turned columns:
    // R = r cos(theta), Z = r sin(theta), beta = phi + S(phi, R, Z),
    // x = a R cos(beta), y = b R sin(beta), z = h(phi) Z,
    // h = EllipticalFront::tangent_distance. The front is r = 1, theta = 0.
    class EllipticalFrontChart : public ChartManifold<3>
    {
    public:
      EllipticalFrontChart(const double a, const double b) : a(a), b(b), front(a, b), turn(a, b) {}

      std::unique_ptr<Manifold<3>> clone() const override
      {
        return std::make_unique<EllipticalFrontChart>(a, b);
      }

      // R and beta from the stretched plane, then phi from beta = phi + S(phi,
      // R, z/h(phi)) by Newton's method kept inside a bracket (the left side
      // increases with phi: h' = -g h, d/dphi = 1 + S_phi + g Z S_Z > 0).
      Point<3> pull_back(const Point<3> &x) const override
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

      Point<3> push_forward(const Point<3> &chart) const override
      {
        const double R = chart[0] * std::cos(chart[1]), Z = chart[0] * std::sin(chart[1]);
        const double phi  = front.parametric_angle(chart[2]);
        const double beta = phi + turn(std::cos(phi), std::sin(phi), R, Z).turn;
        return {a * R * std::cos(beta), b * R * std::sin(beta), front.tangent_distance(phi) * Z};
      }

      DerivativeForm<1, 3, 3> push_forward_gradient(const Point<3> &chart) const override
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

    private:
      const double          a;
      const double          b;
      const EllipticalFront front;
      const ColumnTurn      turn;
    };

    void check(const bool condition, const std::string &message)
    {
      if (!condition)
        throw std::invalid_argument("make_elliptical_gap_mesh: " + message);
    }

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

    // The reference octant (front = unit circle) as a cube-sphere: a lattice
    // of nodes (s, i, j, l), s the shell (0 = the core cube, whose nodes fill
    // the lattice 0 <= i, j <= m, 0 <= l <= rows), and on each shell the nodes
    // of the cube surface i = m (X patch), j = m (Y patch), l = rows (Z patch).
    // The X and Y patches meet the equator in the columns e = 0 ... 2m
    // (front coordinates psi_e = e pi/(4m)); their first `tube_rows` rows lie at fixed
    // latitudes and hold the spider web between shells tube_inner and
    // tube_outer.
    class ReferenceOctant
    {
    public:
      explicit ReferenceOctant(const EllipticalGapMeshParameters &p)
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

      // Physical position of lattice node (s, i, j, l).
      Point<3> lattice_point(const unsigned int s, const unsigned int i, const unsigned int j,
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

      // Physical position of the web node (t, zeta) = (r - 1, theta) on column e.
      Point<3> web_point(const unsigned int e, const Point<2> &node) const
      {
        const auto [cp, sp] = cos_sin(e, 4 * m);
        const double r = 1 + node[0], ct = std::cos(node[1]), st = std::sin(node[1]);
        return physical(Point<3>(r * ct * cp, r * ct * sp, r * st), 1);
      }

      // Lattice indices (i, j) of column e of the X and Y patches.
      std::array<unsigned int, 2> column(const unsigned int e) const
      {
        return e <= m ? std::array<unsigned int, 2>{{m, e}} : std::array<unsigned int, 2>{{2 * m - e, m}};
      }

      // Web node k (0 ... n-1 rings, n the tube boundary), sector node i, in (t, zeta).
      Point<2> web_node(const unsigned int e, const unsigned int k, const unsigned int i) const
      {
        const auto [c, s] = cos_sin(i, sectors);
        if (k + 1 == rings[0].size())
          return Point<2>(c, s) * (tube_half_width / std::max(std::abs(c), s));
        // Odd nodes sit further out, so that the kites have right angles at
        // their even nodes; every ring is a scaled copy of the kites' outline.
        const double radius = rings[e][k] / (i % 2 == 1 ? std::cos(M_PI / sectors) : 1.);
        return Point<2>(c, s) * radius;
      }

      const Tensor<1, 3>                     scale;
      const unsigned int                     m;
      const unsigned int                     sectors;
      const unsigned int                     tube_rows;
      const unsigned int                     upper_rows;
      const unsigned int                     rows;
      const std::vector<std::vector<double>> rings;
      const Tensor<1, 3>                     box;
      unsigned int                           tube_inner;
      unsigned int                           tube_outer;
      unsigned int                           n_shells;
      std::vector<double>                    radii;
      double                                 core;

    private:
      double u(const unsigned int i) const { return i == m ? 1. : std::tan(i * M_PI / (4 * m)); }

      double row_latitude(const unsigned int l) const
      {
        return l == tube_rows ? tube_half_width : tube_half_width * std::tan(l * M_PI / sectors);
      }

      // Height of row l over the cube face at parameter u: the tube rows at
      // fixed latitudes, the rows above spaced evenly up to the cube's top.
      double row_height(const double u, const unsigned int l) const
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
      Point<3> cube_point(const unsigned int i, const unsigned int j, const unsigned int l) const
      {
        return {u(i), u(j), row_height(u(i) * u(j), l)};
      }

      // Unit direction of a surface node: on the X and Y patches from its
      // latitude and longitude, on the Z patch the projected cube point.
      Tensor<1, 3> direction(const unsigned int i, const unsigned int j, const unsigned int l) const
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
      Point<3> physical(const Point<3> &reference, const double weight) const
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

      const EllipticalFront front;
      const ColumnTurn      turn;
    };

    // Vertices by key: {0, s, i, j, l} for lattice nodes, {1, e, k, i, 0} for
    // web nodes (k = 0 the front, k = 1 ... n the rings).
    class VertexTable
    {
    public:
      template <typename Position>
      unsigned int operator()(const std::array<unsigned int, 5> &key, const Position &position)
      {
        const auto [it, inserted] = index.emplace(key, vertices.size());
        if (inserted)
          vertices.push_back(position());
        return it->second;
      }

      std::vector<Point<3>> vertices;

    private:
      std::map<std::array<unsigned int, 5>, unsigned int> index;
    };

    CellData<3> hexahedron(const std::array<unsigned int, 4> &lower, const std::array<unsigned int, 4> &upper,
                           const types::manifold_id manifold)
    {
      CellData<3> cell;
      for (unsigned int v = 0; v < 4; ++v)
        {
          cell.vertices[v]     = lower[v];
          cell.vertices[v + 4] = upper[v];
        }
      cell.manifold_id = manifold;
      return cell;
    }
  } // namespace

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

  namespace
  {
    void check_parameters(const EllipticalGapMeshParameters &p)
    {
      check(p.semi_axis_b >= smallest_aspect_ratio * p.semi_axis_a && p.semi_axis_a >= p.semi_axis_b,
            "the semi-axes must satisfy a >= b >= smallest_aspect_ratio a");
      check(p.outer_shell_aspect > 0, "outer_shell_aspect must be positive");
      check(p.counts_aspect_ratio == 0 ||
                (p.counts_aspect_ratio >= smallest_aspect_ratio && p.counts_aspect_ratio <= 1),
            "counts_aspect_ratio must be 0 or lie in [smallest_aspect_ratio, 1]");
      check(p.domain_width <= largest_box && p.domain_height <= largest_box,
            "the box must reach at most largest_box a along x, y and z");
      check(p.cells_along_front >= 2 && p.cells_along_front % 2 == 0,
            "cells_along_front must be even and >= 2");
      check(p.cells_around_front >= 4 && p.cells_around_front % 4 == 0,
            "cells_around_front must be a multiple of 4");
    }
  } // namespace

  // The loops of make_elliptical_gap_mesh, counted: the core cube, the
  // shells (their X and Y patches less the web's block, and the Z patch),
  // and the web's kites and rings on every column.
  double elliptical_gap_mesh_cells(const EllipticalGapMeshParameters &p)
  {
    check_parameters(p);
    const ReferenceOctant octant(p);
    const double          m = octant.m, rows = octant.rows, sectors = octant.sectors;
    const double          n_rings     = octant.rings[0].size() - 1;
    const double          tube_shells = octant.tube_outer - octant.tube_inner;
    return rows * m * m + octant.n_shells * (2 * m * rows + m * m) - tube_shells * 2 * m * octant.tube_rows +
           2 * m * (sectors / 2 + n_rings * sectors);
  }

  void make_elliptical_gap_mesh(Triangulation<3> &triangulation, const EllipticalGapMeshParameters &p)
  {
    check_parameters(p);
    const ReferenceOctant octant(p);
    const unsigned int    m = octant.m, rows = octant.rows;
    const auto            flat  = numbers::flat_manifold_id;
    const auto            swept = elliptical_front_manifold_id;

    VertexTable              vertex;
    std::vector<CellData<3>> cells;
    const auto               lattice = [&](const unsigned int s, const unsigned int i, const unsigned int j,
                             const unsigned int l) {
      return vertex({{0, s, i, j, l}}, [&]() { return octant.lattice_point(s, i, j, l); });
    };

    // Core cube.
    for (unsigned int l = 0; l < rows; ++l)
      for (unsigned int j = 0; j < m; ++j)
        for (unsigned int i = 0; i < m; ++i)
          cells.push_back(hexahedron({{lattice(0, i, j, l), lattice(0, i + 1, j, l), lattice(0, i, j + 1, l),
                                       lattice(0, i + 1, j + 1, l)}},
                                     {{lattice(0, i, j, l + 1), lattice(0, i + 1, j, l + 1),
                                       lattice(0, i, j + 1, l + 1), lattice(0, i + 1, j + 1, l + 1)}},
                                     flat));

    // Shells: each surface quad of shell s joined to the same quad of shell
    // s + 1, except the web's block of the X and Y patches.
    for (unsigned int s = 0; s < octant.n_shells; ++s)
      {
        const bool in_tube   = s >= octant.tube_inner && s < octant.tube_outer;
        const auto side_type = s >= 1 && s + 1 <= octant.tube_outer ? swept : flat;
        for (unsigned int e = 0; e < 2 * m; ++e)
          for (unsigned int l = (in_tube ? octant.tube_rows : 0); l < rows; ++l)
            {
              const auto [i0, j0] = octant.column(e);
              const auto [i1, j1] = octant.column(e + 1);
              cells.push_back(hexahedron({{lattice(s, i0, j0, l), lattice(s, i1, j1, l),
                                           lattice(s, i0, j0, l + 1), lattice(s, i1, j1, l + 1)}},
                                         {{lattice(s + 1, i0, j0, l), lattice(s + 1, i1, j1, l),
                                           lattice(s + 1, i0, j0, l + 1), lattice(s + 1, i1, j1, l + 1)}},
                                         side_type));
            }
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int i = 0; i < m; ++i)
            cells.push_back(hexahedron({{lattice(s, i, j, rows), lattice(s, i + 1, j, rows),
                                         lattice(s, i, j + 1, rows), lattice(s, i + 1, j + 1, rows)}},
                                       {{lattice(s + 1, i, j, rows), lattice(s + 1, i + 1, j, rows),
                                         lattice(s + 1, i, j + 1, rows), lattice(s + 1, i + 1, j + 1, rows)}},
                                       flat));
      }

    // Spider web around the front, swept along it: its outline is the block
    // boundary, whose nodes are lattice nodes.
    const unsigned int n_rings = octant.rings[0].size() - 1, n_s = octant.sectors;
    const auto         web = [&](const unsigned int e, const int k, const unsigned int i) {
      if (k < 0)
        return vertex({{1, e, 0, 0, 0}}, [&]() { return octant.web_point(e, Point<2>()); });
      if (static_cast<unsigned int>(k) < n_rings)
        return vertex({{1, e, static_cast<unsigned int>(k) + 1, i, 0}},
                              [&]() { return octant.web_point(e, octant.web_node(e, k, i)); });
      const auto [ci, cj] = octant.column(e);
      if (4 * i <= n_s)
        return lattice(octant.tube_outer, ci, cj, i);
      if (4 * i <= 3 * n_s)
        return lattice(octant.tube_inner + 3 * n_s / 4 - i, ci, cj, octant.tube_rows);
      return lattice(octant.tube_inner, ci, cj, n_s - i);
    };
    for (unsigned int e = 0; e < 2 * m; ++e)
      {
        const auto quad = [&](const unsigned int                                 slice,
                              const std::array<std::pair<int, unsigned int>, 4> &nodes) {
          std::array<unsigned int, 4> ids;
          for (unsigned int v = 0; v < 4; ++v)
            ids[v] = web(slice, nodes[v].first, nodes[v].second);
          return ids;
        };
        // Kites: the front, two ring nodes and the odd node between them.
        for (unsigned int i = 0; i < n_s; i += 2)
          {
            const std::array<std::pair<int, unsigned int>, 4> kite = {
                {{-1, 0}, {0, i}, {0, i + 2}, {0, i + 1}}};
            cells.push_back(hexahedron(quad(e, kite), quad(e + 1, kite), swept));
          }
        for (unsigned int k = 0; k < n_rings; ++k)
          for (unsigned int i = 0; i < n_s; ++i)
            {
              const int                                         in = k, out = k + 1;
              const std::array<std::pair<int, unsigned int>, 4> ring = {
                  {{in, i}, {out, i}, {in, i + 1}, {out, i + 1}}};
              cells.push_back(hexahedron(quad(e, ring), quad(e + 1, ring), swept));
            }
      }

    GridTools::invert_cells_with_negative_measure(vertex.vertices, cells);
    GridTools::consistently_order_cells(cells);

    Triangulation<3> coarse;
    coarse.create_triangulation(vertex.vertices, cells, SubCellData());
    for (const auto &cell : coarse.active_cell_iterators())
      if (cell->manifold_id() == swept)
        cell->set_all_manifold_ids(swept);
    coarse.set_manifold(swept, EllipticalFrontChart(p.semi_axis_a, p.semi_axis_b));

    const double a = p.semi_axis_a, b = p.semi_axis_b, tolerance = 1e-10 * a;
    for (const auto &face : coarse.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<3> x = face->center();
          if (std::abs(x[2]) < tolerance)
            {
              // Inside the ellipse when all vertices are: the centre of a thin
              // face outside it may lie inside, on the chord of the front.
              bool inside = true;
              for (const unsigned int v : face->vertex_indices())
                {
                  const Point<3> &y = face->vertex(v);
                  inside &= (y[0] / a) * (y[0] / a) + (y[1] / b) * (y[1] / b) < 1 + 1e-12;
                }
              face->set_boundary_id(inside ? boundary_id::gap_face : boundary_id::ligament);
            }
          else if (std::abs(x[0]) < tolerance)
            face->set_boundary_id(boundary_id::symmetry);
          else if (std::abs(x[1]) < tolerance)
            face->set_boundary_id(boundary_id::second_symmetry);
          else
            face->set_boundary_id(boundary_id::far);
        }
    triangulation.copy_triangulation(coarse);
  }
} // namespace penny
