#include "fe/penny_gap_mesh.h"

#include "fe/boundary_ids.h"
#include "fe/penny_gap_mesh_internal.h"
#include "fe/tip_graded_mesh.h"
#include "input/input_error.h"

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

namespace penny
{
  using namespace dealii;
  using internal::read_gmsh;

  namespace
  {
    // Quadtree of square cells (fe/tip_graded_mesh.h): a coarse grid of width
    // s = c 2^m (the largest such width not above min(R, H)/2, so that the first
    // coarse cell is [0, s]^2 and c falls on one of its dyadic vertices), then
    // every cell nearer to the tip than `grading_distance` of its own widths is
    // split until the tip cells are c/2^levels wide, and every cell over the gap
    // face until it is c/2^(gap face levels) wide: without those, w(0) is 20
    // times less accurate than K_I. Far from the tip cells double in
    // width every few cells: a geometric grading, ratio 2, out to R and H.
    void generate_quadtree(Triangulation<2> &triangulation, const GeometryParameters &physical_geometry,
                           const MeshParameters &mesh)
    {
      // Built on a domain whose part above z0 is compressed along z by the aspect
      // ratio, then stretched back: cells above z0 become that many times
      // taller than wide, while the tip zone keeps square cells.
      const double       ratio = mesh.cell_aspect_ratio;
      const double       z0    = std::min(physical_geometry.gap_radius, physical_geometry.domain_height / 2);
      GeometryParameters geometry = physical_geometry;
      geometry.domain_height      = z0 + (physical_geometry.domain_height - z0) / ratio;
      const double c              = geometry.gap_radius;
      const double s =
          c *
          std::pow(2.,
                   std::floor(std::log2(std::min(geometry.domain_radius, geometry.domain_height) / (2 * c))));
      const double tip_width = c / std::pow(2., mesh.tip_levels);
      make_tip_graded_mesh(triangulation, coarse_steps(geometry.domain_radius, s),
                           coarse_steps(geometry.domain_height, s), crack_tip(geometry),
                           {tip_width, mesh.grading_distance, c / std::pow(2., mesh.gap_face_levels)});

      const double tolerance = 1e-9 * tip_width;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            const Point<2> x = face->center();
            face->set_boundary_id(x[0] < tolerance   ? boundary_id::symmetry
                                  : x[1] > tolerance ? boundary_id::far
                                  : x[0] < c         ? boundary_id::gap_face
                                                     : boundary_id::ligament);
          }
      if (ratio != 1)
        GridTools::transform(
            [&](const Point<2> &x) { return Point<2>(x[0], x[1] <= z0 ? x[1] : z0 + ratio * (x[1] - z0)); },
            triangulation);
    }

    std::string point_text(const Point<2> &x)
    {
      std::ostringstream text;
      text.precision(6);
      text << "(r, z) = (" << x[0] << ", " << x[1] << ")";
      return text.str();
    }

    // A mesh must be the half model of Geometry: cells that are proper
    // quadrilaterals filling 0 <= r <= R, 0 <= z <= H exactly once, and a
    // boundary made of the four sides, each face tagged for the side it lies
    // on. A mesh of another size, a self-intersecting or degenerate cell, a
    // hole, an overlap, a disconnected piece or a mistagged face is refused.
    void check_against_geometry(const Triangulation<2> &triangulation, const GeometryParameters &geometry,
                                const std::string &source)
    {
      const double         c = geometry.gap_radius, R = geometry.domain_radius, H = geometry.domain_height;
      const double         tolerance = 1e-10 * std::max(R, H);
      const BoundingBox<2> box       = GridTools::compute_bounding_box(triangulation);
      if (std::abs(box.lower_bound(0)) > tolerance || std::abs(box.lower_bound(1)) > tolerance ||
          std::abs(box.upper_bound(0) - R) > tolerance || std::abs(box.upper_bound(1) - H) > tolerance)
        {
          std::ostringstream message;
          message.precision(10);
          message << source << " spans r in [" << box.lower_bound(0) << ", " << box.upper_bound(0)
                  << "], z in [" << box.lower_bound(1) << ", " << box.upper_bound(1)
                  << "], not the half model 0 <= r <= R = " << R << ", 0 <= z <= H = " << H;
          throw InputError(message.str());
        }

      double area = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          // The Jacobian of a bilinear cell is positive inside if it is at the corners.
          const auto v     = [&](const unsigned int i) { return cell->vertex(i); };
          const auto cross = [](const Tensor<1, 2> &a, const Tensor<1, 2> &b) {
            return a[0] * b[1] - a[1] * b[0];
          };
          const double size2 = std::pow(cell->diameter(), 2);
          for (const double jacobian : {cross(v(1) - v(0), v(2) - v(0)), cross(v(1) - v(0), v(3) - v(1)),
                                        cross(v(3) - v(2), v(2) - v(0)), cross(v(3) - v(2), v(3) - v(1))})
            if (!(jacobian > 1e-12 * size2))
              throw InputError(source + " has a degenerate or self-intersecting cell at " +
                               point_text(cell->center()));
          area += cell->measure();
        }
      if (std::abs(area - R * H) > 1e-9 * R * H)
        throw InputError(source + (area > R * H ? " has overlapping cells" : " has holes") +
                         ": its cells cover " + dealii::Utilities::to_string(area) +
                         " m^2, not R H = " + dealii::Utilities::to_string(R * H) + " m^2");

      // Each boundary face on its side, and the sides covered once: their lengths add up.
      std::map<types::boundary_id, double> length;
      const auto                           on = [&](const double value, const double line) {
        return std::abs(value - line) <= tolerance;
      };
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            const Point<2> a = face->vertex(0), b = face->vertex(1);
            const auto     id = face->boundary_id();
            bool           placed;
            switch (id)
              {
              case boundary_id::symmetry:
                placed = on(a[0], 0) && on(b[0], 0);
                break;
              case boundary_id::gap_face:
                placed = on(a[1], 0) && on(b[1], 0) && std::max(a[0], b[0]) <= c * (1 + 1e-12);
                break;
              case boundary_id::ligament:
                placed = on(a[1], 0) && on(b[1], 0) && std::min(a[0], b[0]) >= c * (1 - 1e-12);
                break;
              case boundary_id::far:
                placed = (on(a[0], R) && on(b[0], R)) || (on(a[1], H) && on(b[1], H));
                break;
              default:
                throw InputError(source + " has a boundary face without a tag 1-4 at " +
                                 point_text(face->center()) +
                                 " (1 axis, 2 gap face, 3 ligament, 4 far boundary)");
              }
            if (!placed)
              throw InputError(source + " has a face tagged " + std::to_string(id) + " at " +
                               point_text(face->center()) +
                               " off its side (1 axis r = 0, 2 gap face z = 0 r < c, 3 ligament z = 0 r > "
                               "c, 4 far boundary r = R or z = H), or a boundary inside the solid");
            length[id] += a.distance(b);
          }
      for (const auto &[id, expected] : std::map<types::boundary_id, double>{{boundary_id::symmetry, H},
                                                                             {boundary_id::gap_face, c},
                                                                             {boundary_id::ligament, R - c},
                                                                             {boundary_id::far, R + H}})
        if (std::abs(length[id] - expected) > 1e-9 * expected)
          throw InputError(source + ": the faces tagged " + std::to_string(id) + " add up to " +
                           dealii::Utilities::to_string(length[id]) + " m, not the " +
                           dealii::Utilities::to_string(expected) + " m of their side");
    }

    // A gmsh mesh that is the half model of the geometry, with the tip at a vertex.
    void read_checked_gmsh(Triangulation<2> &triangulation, const GeometryParameters &geometry,
                           const MeshParameters &mesh)
    {
      read_gmsh(triangulation, geometry, mesh);
      const std::string source = in_quotes(mesh.mesh_file);
      if (!has_vertex_at(triangulation, crack_tip(geometry), 1e-12 * geometry.gap_radius))
        throw InputError(source + " has no vertex at the crack tip (c, 0) = (" +
                         shortest(geometry.gap_radius) + ", 0)");
      check_against_geometry(triangulation, geometry, source);
    }
  } // namespace

  void make_penny_gap_mesh(Triangulation<2> &triangulation, const GeometryParameters &geometry,
                           const MeshParameters &mesh)
  {
    if (mesh.generator == MeshParameters::Generator::builtin)
      {
        generate_quadtree(triangulation, geometry, mesh);
        check_against_geometry(triangulation, geometry, "the built-in mesh");
      }
    else
      read_checked_gmsh(triangulation, geometry, mesh);
    triangulation.refine_global(mesh.global_refinements);
  }

  double penny_gap_mesh_cells(const GeometryParameters &geometry, const MeshParameters &mesh,
                              const MPI_Comm communicator)
  {
    if (mesh.generator == MeshParameters::Generator::builtin)
      return quadtree_cells(geometry, mesh);
    parallel::shared::Triangulation<2> coarse(communicator);
    read_checked_gmsh(coarse, geometry, mesh);
    return coarse.n_active_cells() * std::pow(4., mesh.global_refinements);
  }

  // The quadtree's construction, counted: a coarse grid of width s, then at
  // each width w from s down to the tip width the cells of the lattice of
  // width w (origin 0) whose box lies closer to the tip than
  // `grading_distance` widths are split, each into four. A cell of width w
  // exists where its parent was split, and a cell close enough to be split
  // has a parent closer still, so the split cells of width w are exactly the
  // close lattice cells inside the domain. The same holds for the cells over
  // the gap face, split down to their own width. The balancing of levels across
  // vertices adds a few per cent (tests/test_problem_size.cc).
  double quadtree_cells(const GeometryParameters &physical_geometry, const MeshParameters &mesh)
  {
    const double c     = physical_geometry.gap_radius;
    const double ratio = mesh.cell_aspect_ratio;
    const double z0    = std::min(c, physical_geometry.domain_height / 2);
    const double R     = physical_geometry.domain_radius;
    const double H     = z0 + (physical_geometry.domain_height - z0) / ratio;
    const double s     = c * std::pow(2., std::floor(std::log2(std::min(R, H) / (2 * c))));
    const double n_r   = std::max(1., std::floor(R / s + 1e-12));
    const double n_z   = std::max(1., std::floor(H / s + 1e-12));
    const double g     = mesh.grading_distance;

    double       cells      = n_r * n_z;
    const double tip_width  = c / std::pow(2., mesh.tip_levels);
    const double face_width = c / std::pow(2., mesh.gap_face_levels);
    for (double w = s; w > std::min(tip_width, face_width) * (1 + 1e-9); w /= 2)
      {
        // Lattice columns i (r in [i w, (i + 1) w]) and rows j near the tip
        // (c, 0), or with their corner over the gap face.
        const double tip       = c / w;
        const bool   near_face = w > face_width * (1 + 1e-9);
        const bool   near_tip  = w > tip_width * (1 + 1e-9);
        const double first     = near_face ? 0. : std::max(0., std::floor(tip - g - 1));
        const double last      = std::min(n_r * s / w - 1, std::ceil(tip + g + 1));
        const double top       = std::min(n_z * s / w - 1, std::ceil(std::max(g, near_face ? tip : 0.)));
        double       n_refined = 0;
        for (double i = first; i <= last; ++i)
          for (double j = 0; j <= top; ++j)
            {
              const double dr = std::max({i - tip, tip - (i + 1), 0.});
              if ((near_tip && std::hypot(dr, j) < g * (1 - 1e-9)) ||
                  (near_face && i < tip * (1 - 1e-9) && j < tip * (1 - 1e-9)))
                ++n_refined;
            }
        cells += 3 * n_refined;
      }
    return cells * std::pow(4., mesh.global_refinements);
  }
} // namespace penny
