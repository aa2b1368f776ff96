// The elliptical-gap mesh (front on the ellipse before and after refinement,
// positive Jacobians with the quadratic mapping the 3D model uses, boundary
// ids on their planes, the box volume, the front's chart and its derivative,
// serial and distributed builds) and the Green-Sneddon closed forms (circle
// limit, symmetries, volume and K_I from w).
#include "closed_forms/elliptical_crack.h"
#include "fe/boundary_ids.h"
#include "fe/elliptical_gap_mesh.h"
#include "test_support.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/manifold.h>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

BOOST_AUTO_TEST_SUITE(test_elliptical_gap_mesh)

namespace tt = boost::test_tools;
using namespace penny;
using namespace dealii;

namespace
{
  double ellipse_residual(const Point<3> &x, const EllipticalGapMeshParameters &p)
  {
    return std::abs(std::pow(x[0] / p.semi_axis_a, 2) + std::pow(x[1] / p.semi_axis_b, 2) - 1);
  }

  // Front vertices: on the ellipse and on z = 0 to 1e-12, at the front
  // coordinates e pi/(2n) of n equal steps, joined by n mesh edges.
  void check_front(const Triangulation<3> &triangulation, const EllipticalGapMeshParameters &p,
                   const unsigned int n)
  {
    const EllipticalFront     front(p.semi_axis_a, p.semi_axis_b);
    const std::vector<double> angles = front_vertex_angles(triangulation, front);
    BOOST_TEST_REQUIRE(angles.size() == n + 1);
    for (unsigned int e = 0; e <= n; ++e)
      BOOST_TEST(front.front_coordinate(angles[e]) == e * M_PI / (2 * n), tt::tolerance(1e-12));

    // Edges with both ends on the front, by the angle of their midpoint (on a
    // distributed mesh gathered over the ranks, whose cells share edges).
    std::vector<double> local;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int l : cell->line_indices())
          {
            const auto line     = cell->line(l);
            bool       on_front = true;
            for (const unsigned int v : {0u, 1u})
              {
                const Point<3> &x = line->vertex(v);
                on_front &= std::abs(x[2]) <= 1e-12 * p.semi_axis_a && ellipse_residual(x, p) <= 1e-12;
              }
            if (on_front)
              local.push_back(
                  std::atan2(line->center()[1] / p.semi_axis_b, line->center()[0] / p.semi_axis_a));
          }
    std::vector<double> midpoints;
    for (const auto &part : Utilities::MPI::all_gather(triangulation.get_communicator(), local))
      midpoints.insert(midpoints.end(), part.begin(), part.end());
    std::sort(midpoints.begin(), midpoints.end());
    const auto front_edges = std::unique(midpoints.begin(), midpoints.end(),
                                         [](const double x, const double y) { return y - x < 1e-12; }) -
                             midpoints.begin();
    BOOST_TEST(front_edges == n);
  }

  // Total volume with a degree-2 mapping (exact with 3 Gauss points), and the
  // smallest Jacobian determinant over the quadrature points relative to the
  // cell's mean one.
  std::pair<double, double> volume_and_worst_jacobian(const Triangulation<3> &triangulation)
  {
    const MappingQ<3>   mapping(2);
    const FE_Nothing<3> fe;
    const QGauss<3>     quadrature(3);
    FEValues<3>         fe_values(mapping, fe, quadrature, update_JxW_values);
    double              volume = 0, worst = 1;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          double cell_volume = 0, smallest = fe_values.JxW(0) / quadrature.weight(0);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              cell_volume += fe_values.JxW(q);
              smallest = std::min(smallest, fe_values.JxW(q) / quadrature.weight(q));
            }
          volume += cell_volume;
          worst = std::min(worst, smallest / cell_volume);
        }
    return {volume, worst};
  }

  // Every boundary face lies in the plane its id names: all its vertices, and
  // the gap face inside, the ligament outside the ellipse.
  void check_boundary_ids(const Triangulation<3> &triangulation, const EllipticalGapMeshParameters &p)
  {
    const double a = p.semi_axis_a, R = p.domain_width * a, H = p.domain_height * a, tol = 1e-12 * a;
    std::map<types::boundary_id, double> area;
    for (const auto &face : triangulation.active_face_iterators())
      if (face->at_boundary())
        {
          const types::boundary_id id = face->boundary_id();
          area[id] += face->measure();
          for (const unsigned int v : face->vertex_indices())
            {
              const Point<3> &x = face->vertex(v);
              switch (id)
                {
                case boundary_id::symmetry:
                  BOOST_TEST(std::abs(x[0]) <= tol);
                  break;
                case boundary_id::second_symmetry:
                  BOOST_TEST(std::abs(x[1]) <= tol);
                  break;
                case boundary_id::gap_face:
                case boundary_id::ligament:
                  {
                    BOOST_TEST(std::abs(x[2]) <= tol);
                    const double g = std::pow(x[0] / a, 2) + std::pow(x[1] / p.semi_axis_b, 2);
                    if (id == boundary_id::gap_face)
                      BOOST_TEST(g <= 1 + 1e-12);
                    else
                      BOOST_TEST(g >= 1 - 1e-12);
                    break;
                  }
                case boundary_id::far:
                  BOOST_TEST(
                      (std::abs(x[0] - R) <= tol || std::abs(x[1] - R) <= tol || std::abs(x[2] - H) <= tol));
                  break;
                default:
                  BOOST_FAIL("unexpected boundary id " << static_cast<int>(id));
                }
            }
        }
    // Flat faces: the areas are exact sums (the gap's polygonal outline aside).
    BOOST_TEST(area[boundary_id::symmetry] == R * H, tt::tolerance(1e-12));
    BOOST_TEST(area[boundary_id::second_symmetry] == R * H, tt::tolerance(1e-12));
    BOOST_TEST(area[boundary_id::far] == R * R + 2 * R * H, tt::tolerance(1e-12));
    BOOST_TEST(area[boundary_id::gap_face] + area[boundary_id::ligament] == R * R, tt::tolerance(1e-12));
  }
} // namespace

BOOST_AUTO_TEST_CASE(front_stays_on_the_ellipse_under_refinement)
{
  for (const double b_over_a : {1., 0.5, 0.25})
    {
      const EllipticalGapMeshParameters p = small_elliptical_mesh(b_over_a);
      Triangulation<3>                  triangulation;
      make_elliptical_gap_mesh(triangulation, p);
      for (unsigned int refinement = 0; refinement <= 2; ++refinement)
        {
          BOOST_TEST_CONTEXT("b/a = " << b_over_a << ", refinements " << refinement)
          check_front(triangulation, p, p.cells_along_front << refinement);
          if (refinement < 2)
            triangulation.refine_global();
        }
    }
}

BOOST_AUTO_TEST_CASE(positive_jacobians_and_box_volume)
{
  for (const double b_over_a : {1., 0.5, 0.25})
    {
      const EllipticalGapMeshParameters p = small_elliptical_mesh(b_over_a);
      const double     box = std::pow(p.domain_width * p.semi_axis_a, 2) * p.domain_height * p.semi_axis_a;
      Triangulation<3> triangulation;
      make_elliptical_gap_mesh(triangulation, p);
      for (unsigned int refinement = 0; refinement <= 2; ++refinement)
        {
          BOOST_TEST_CONTEXT("b/a = " << b_over_a << ", refinements " << refinement)
          {
            const auto [volume, worst] = volume_and_worst_jacobian(triangulation);
            BOOST_TEST(volume == box, tt::tolerance(1e-11));
            // det J at every quadrature point is at least a tenth of the cell's mean.
            BOOST_TEST(worst > 0.1);
          }
          if (refinement < 2)
            triangulation.refine_global();
        }
    }
}

// Thinner shells beyond the tube: more cells, the same box, still well shaped.
BOOST_AUTO_TEST_CASE(finer_outer_shells)
{
  EllipticalGapMeshParameters p = small_elliptical_mesh(0.25);
  Triangulation<3>            standard;
  make_elliptical_gap_mesh(standard, p);
  p.outer_shell_aspect = 1.5;
  Triangulation<3> finer;
  make_elliptical_gap_mesh(finer, p);
  BOOST_TEST(finer.n_active_cells() > standard.n_active_cells());
  const double box           = std::pow(p.domain_width * p.semi_axis_a, 2) * p.domain_height * p.semi_axis_a;
  const auto [volume, worst] = volume_and_worst_jacobian(finer);
  BOOST_TEST(volume == box, tt::tolerance(1e-11));
  BOOST_TEST(worst > 0.1);
  p.outer_shell_aspect = 0;
  Triangulation<3> none;
  BOOST_CHECK_THROW(make_elliptical_gap_mesh(none, p), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(boundary_ids_on_their_planes)
{
  for (const double b_over_a : {1., 0.25})
    {
      const EllipticalGapMeshParameters p = small_elliptical_mesh(b_over_a);
      Triangulation<3>                  triangulation;
      make_elliptical_gap_mesh(triangulation, p);
      check_boundary_ids(triangulation, p);
      triangulation.refine_global();
      check_boundary_ids(triangulation, p);
    }
}

// Columns leave the front along its normal: every mesh edge from a front
// vertex into the plane z = 0 (to the innermost ring, before and after a
// refinement) is within 2 degrees of the front's normal there (1.2 measured). The
// stretched columns leaned by up to 62 degrees at b/a = 0.25.
BOOST_AUTO_TEST_CASE(columns_normal_to_the_front)
{
  for (const double b_over_a : {0.5, 0.25, 0.1})
    {
      const EllipticalGapMeshParameters p = small_elliptical_mesh(b_over_a);
      const EllipticalFront             front(p.semi_axis_a, p.semi_axis_b);
      Triangulation<3>                  triangulation;
      make_elliptical_gap_mesh(triangulation, p);
      for (unsigned int refinement = 0; refinement <= 1; ++refinement)
        {
          double       worst = 0;
          unsigned int edges = 0;
          for (const auto &cell : triangulation.active_cell_iterators())
            for (const unsigned int l : cell->line_indices())
              for (const unsigned int v : {0u, 1u})
                {
                  const Point<3> &x = cell->line(l)->vertex(v), &y = cell->line(l)->vertex(1 - v);
                  const double    tol = 1e-12 * p.semi_axis_a;
                  if (std::abs(x[2]) > tol || std::abs(y[2]) > tol || ellipse_residual(x, p) > 1e-12 ||
                      ellipse_residual(y, p) <= 1e-12)
                    continue;
                  const Tensor<1, 3> n =
                      front.unit_normal(std::atan2(x[1] / p.semi_axis_b, x[0] / p.semi_axis_a));
                  worst = std::max(worst, std::abs(cross_product_3d(n, (y - x) / (y - x).norm())[2]));
                  ++edges;
                }
          BOOST_TEST_CONTEXT("b/a = " << b_over_a << ", refinements " << refinement)
          {
            BOOST_TEST(edges > 0u);
            const double degrees = std::asin(worst) * 180 / M_PI;
            BOOST_TEST(degrees < 2);
          }
          triangulation.refine_global();
        }
    }
}

// The front's chart: pull_back inverts push_forward, and push_forward_gradient
// is its derivative (central differences), over the swept cells' range of
// (r, theta, psi), including points on the front and next to it.
BOOST_AUTO_TEST_CASE(front_chart_is_consistent)
{
  for (const double b_over_a : {1., 0.5, 0.1, 0.02})
    {
      const EllipticalGapMeshParameters p = small_elliptical_mesh(b_over_a);
      Triangulation<3>                  triangulation;
      make_elliptical_gap_mesh(triangulation, p);
      const auto &chart =
          dynamic_cast<const ChartManifold<3> &>(triangulation.get_manifold(elliptical_front_manifold_id));
      for (const double r : {0.4, 0.99, 1., 1.0001, 1.3})
        for (const double theta : {0., 1e-4, 0.2, 1.2})
          for (const double psi : {0., 1e-3, 0.05, 0.3, 0.785, 1.5, M_PI / 2})
            BOOST_TEST_CONTEXT("b/a = " << b_over_a << ", (r, theta, psi) = " << Point<3>(r, theta, psi))
            {
              const Point<3> c(r, theta, psi), x = chart.push_forward(c);
              BOOST_TEST(chart.pull_back(x).distance(c) < 1e-12);
              const DerivativeForm<1, 3, 3> gradient = chart.push_forward_gradient(c);
              for (unsigned int j = 0; j < 3; ++j)
                {
                  Tensor<1, 3> step;
                  step[j] = 1e-7;
                  const Tensor<1, 3> slope =
                      (chart.push_forward(c + step) - chart.push_forward(c - step)) / 2e-7;
                  for (unsigned int i = 0; i < 3; ++i)
                    BOOST_TEST(std::abs(gradient[i][j] - slope[i]) <=
                               1e-6 * (p.semi_axis_a + std::abs(slope[i])));
                }
            }
    }
}

// The same coarse mesh on every rank of a p4est triangulation: the same cells
// in all, the box volume, the front complete on every rank.
BOOST_AUTO_TEST_CASE(distributed_triangulation)
{
  const EllipticalGapMeshParameters p = small_elliptical_mesh(0.5);
  Triangulation<3>                  serial;
  make_elliptical_gap_mesh(serial, p);
  parallel::distributed::Triangulation<3> distributed(MPI_COMM_WORLD);
  make_elliptical_gap_mesh(distributed, p);
  const double box = std::pow(p.domain_width * p.semi_axis_a, 2) * p.domain_height * p.semi_axis_a;
  for (unsigned int refinement = 0; refinement <= 1; ++refinement)
    {
      BOOST_TEST(distributed.n_global_active_cells() == serial.n_active_cells() * (1u << (3 * refinement)));
      const double volume = Utilities::MPI::sum(volume_and_worst_jacobian(distributed).first, MPI_COMM_WORLD);
      BOOST_TEST(volume == box, tt::tolerance(1e-11));
      check_front(distributed, p, p.cells_along_front << refinement);
      distributed.refine_global();
    }
}

BOOST_AUTO_TEST_CASE(local_front_coordinates)
{
  const double          a = 2, b = 0.5;
  const EllipticalFront front(a, b);
  for (const double phi : {0., 0.1, 0.7, 1.2, M_PI / 2})
    for (const double d : {1e-6, 1e-3, 0.05})
      for (const double theta : {0., 0.4, M_PI / 2, 2.5, M_PI})
        {
          const Point<3> x = front.point(phi) + d * (std::cos(theta) * front.unit_normal(phi) +
                                                     std::sin(theta) * Tensor<1, 3>({0, 0, 1}));
          const auto     c = front.local_coordinates(x);
          BOOST_TEST_CONTEXT("phi " << phi << ", d " << d << ", theta " << theta)
          {
            BOOST_TEST(c.phi == phi, tt::tolerance(1e-10));
            BOOST_TEST(c.distance == d, tt::tolerance(1e-9));
            BOOST_TEST(c.theta == theta, tt::tolerance(1e-9));
          }
        }
  // The unit normal is normal to the tangent and to the ellipse.
  for (const double phi : {0.3, 1.1})
    BOOST_TEST(std::abs(front.unit_normal(phi) * front.unit_tangent(phi)) < 1e-15);
}

// Each column's rings grow geometrically from its innermost, front_cell_size
// x min(b, radius of curvature) over the height scale h(phi), to the tube
// boundary, as many on every column; the innermost grows by at most
// ring_ratio from one column to the next.
BOOST_AUTO_TEST_CASE(geometric_rings)
{
  for (const double b_over_a : {1., 0.5, 0.1})
    BOOST_TEST_CONTEXT("b/a = " << b_over_a)
    {
      EllipticalGapMeshParameters p;
      p.semi_axis_a                                = 2;
      p.semi_axis_b                                = 2 * b_over_a;
      p.cells_along_front                          = 8;
      p.front_cell_size                            = 1e-3;
      p.ring_ratio                                 = 1.6;
      const std::vector<std::vector<double>> rings = front_ring_radii(p);
      BOOST_TEST_REQUIRE(rings.size() == 9u);
      const double a = p.semi_axis_a, b = p.semi_axis_b;
      for (unsigned int e = 0; e < rings.size(); ++e)
        {
          const std::vector<double> &r = rings[e];
          BOOST_TEST(r.size() == rings[0].size());
          BOOST_TEST(r.back() == 0.4, tt::tolerance(1e-15));
          for (unsigned int k = 1; k + 1 < r.size(); ++k)
            BOOST_TEST(r[k + 1] / r[k] == r[1] / r[0], tt::tolerance(1e-12));
          BOOST_TEST(r[1] / r[0] <= 1.6 * 1.05);
          if (e > 0)
            BOOST_TEST(std::max(r[0] / rings[e - 1][0], rings[e - 1][0] / r[0]) <= 1.6 * (1 + 1e-12));
        }
      // The innermost: front_cell_size x min(b, radius of curvature) over h,
      // bounded by that of every other column times ring_ratio^(columns apart).
      const auto unlimited = [&](const unsigned int e) {
        const double phi = EllipticalFront(a, b).parametric_angle(e * M_PI / 16),
                     n   = std::hypot(b * std::cos(phi), a * std::sin(phi));
        const double radius_of_curvature =
            std::pow(std::hypot(a * std::sin(phi), b * std::cos(phi)), 3) / (a * b);
        return 1e-3 * std::min(b, radius_of_curvature) / (a * b / n);
      };
      for (unsigned int e = 0; e < rings.size(); ++e)
        {
          double expected = unlimited(e);
          for (unsigned int f = 0; f < rings.size(); ++f)
            expected = std::min(expected, unlimited(f) * std::pow(1.6, std::abs(int(e) - int(f))));
          BOOST_TEST(rings[e][0] == expected, tt::tolerance(1e-12));
        }
      if (b_over_a == 1.)
        BOOST_TEST(rings[3][0] == 1e-3, tt::tolerance(1e-12));
    }
}

// A gap counted as a slenderer one keeps its own innermost rings but has as
// many rings, and as many cells, as that one: a family of gaps meshed so has
// one mesh whose vertices move with b/a (its own counts differ).
BOOST_AUTO_TEST_CASE(gaps_counted_alike_share_their_cells)
{
  EllipticalGapMeshParameters slenderest;
  slenderest.semi_axis_b     = 0.13;
  slenderest.front_cell_size = 1e-4;
  slenderest.ring_ratio      = 2;
  for (const double b_over_a : {0.3, 0.6, 1.})
    BOOST_TEST_CONTEXT("b/a = " << b_over_a)
    {
      EllipticalGapMeshParameters own     = slenderest;
      own.semi_axis_b                     = b_over_a;
      EllipticalGapMeshParameters counted = own;
      counted.counts_aspect_ratio         = slenderest.semi_axis_b;
      const auto rings = front_ring_radii(counted), own_rings = front_ring_radii(own);
      BOOST_TEST(rings[0].size() == front_ring_radii(slenderest)[0].size());
      BOOST_TEST(own_rings[0].size() < rings[0].size());
      for (unsigned int e = 0; e < rings.size(); ++e)
        BOOST_TEST(rings[e][0] == own_rings[e][0]);
      BOOST_TEST(elliptical_gap_mesh_cells(counted) == elliptical_gap_mesh_cells(slenderest));
      BOOST_TEST(elliptical_gap_mesh_cells(own) < elliptical_gap_mesh_cells(slenderest));
    }
}

BOOST_AUTO_TEST_CASE(bad_parameters_are_rejected)
{
  EllipticalGapMeshParameters p = small_elliptical_mesh(0.5);
  p.cells_around_front          = 6;
  Triangulation<3> triangulation;
  BOOST_CHECK_THROW(make_elliptical_gap_mesh(triangulation, p), std::invalid_argument);
  p             = small_elliptical_mesh(0.5);
  p.semi_axis_b = 3;
  BOOST_CHECK_THROW(make_elliptical_gap_mesh(triangulation, p), std::invalid_argument);
  p                     = small_elliptical_mesh(0.5);
  p.counts_aspect_ratio = 1.5;
  BOOST_CHECK_THROW(make_elliptical_gap_mesh(triangulation, p), std::invalid_argument);
}

// The circle b = a is Sneddon's penny: 2 p sqrt(a/pi), 4 p sqrt(a^2 - r^2)/(pi E'), 16 p a^3/(3 E').
BOOST_AUTO_TEST_CASE(circle_limit, *boost::unit_test::tolerance(1e-14))
{
  const double               a = 0.7, p = 3e5, e_prime = 2e9;
  const GreenSneddonSolution penny(a, a, p, e_prime);
  for (const double phi : {0., 0.4, M_PI / 2})
    BOOST_TEST(penny.stress_intensity_factor(phi) == 2 * p * std::sqrt(a / M_PI));
  for (const double r : {0., 0.3, 0.69})
    BOOST_TEST(penny.opening(r / std::sqrt(2.), r / std::sqrt(2.)) ==
               4 * p * std::sqrt(a * a - r * r) / (M_PI * e_prime));
  BOOST_TEST(penny.gap_volume() == 16 * p * a * a * a / (3 * e_prime));
}

// K_I(phi) is even about both axes; largest at the minor axis end, by sqrt(a/b).
BOOST_AUTO_TEST_CASE(stress_intensity_symmetries, *boost::unit_test::tolerance(1e-14))
{
  const double               a = 2, b = 1;
  const GreenSneddonSolution exact(a, b, 1e6, 1e9);
  for (const double phi : {0.2, 0.9, 1.4})
    {
      BOOST_TEST(exact.stress_intensity_factor(-phi) == exact.stress_intensity_factor(phi));
      BOOST_TEST(exact.stress_intensity_factor(M_PI - phi) == exact.stress_intensity_factor(phi));
      BOOST_TEST(exact.stress_intensity_factor(phi) < exact.stress_intensity_factor(M_PI / 2));
    }
  BOOST_TEST(exact.stress_intensity_factor(M_PI / 2) / exact.stress_intensity_factor(0) == std::sqrt(a / b));
  // E(k) for k^2 = 3/4 (b/a = 1/2), a tabulated value.
  BOOST_TEST(exact.elliptic_integral() == 1.2110560275684595, tt::tolerance(1e-15));
}

// Volume: 2 int w dA over the ellipse by double tanh-sinh quadrature; K_I from
// the opening at a small distance d behind the front,
// K_I ~ E' w sqrt(2 pi)/(4 sqrt(d)) (relative error of order d over the
// front's radius of curvature).
BOOST_AUTO_TEST_CASE(volume_and_front_asymptotics)
{
  for (const double b_over_a : {1., 0.5, 0.25})
    {
      const double                               a = 1.5, b = a * b_over_a, p = 2e5, e_prime = 3e9;
      const GreenSneddonSolution                 exact(a, b, p, e_prime);
      boost::math::quadrature::tanh_sinh<double> integrator;
      const double                               quarter = integrator.integrate(
          [&](const double x) {
            const double y_max = b * std::sqrt(std::max(0., 1 - (x / a) * (x / a)));
            return y_max > 0
                                                     ? integrator.integrate([&](const double y) { return exact.opening(x, y); }, 0., y_max)
                                                     : 0.;
          },
          0., a);
      BOOST_TEST(8 * quarter == exact.gap_volume(), tt::tolerance(1e-11));

      const EllipticalFront front(a, b);
      for (const double phi : {0., 0.5, 1.0, M_PI / 2})
        {
          const double   d = 1e-7 * b;
          const Point<3> x = front.point(phi) - d * front.unit_normal(phi);
          const double   k = e_prime * exact.opening(x[0], x[1]) * std::sqrt(2 * M_PI / d) / 4;
          BOOST_TEST(k == exact.stress_intensity_factor(phi), tt::tolerance(1e-5));
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
