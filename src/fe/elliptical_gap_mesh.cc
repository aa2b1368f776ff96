#include "fe/elliptical_gap_mesh.h"

#include "fe/boundary_ids.h"
#include "fe/elliptical_gap_mesh_internal.h"

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria_description.h>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace penny
{
  using namespace dealii;
  using internal::check;
  using internal::EllipticalFrontChart;
  using internal::ReferenceOctant;

  namespace
  {
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
