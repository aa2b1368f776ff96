#include "fe/tip_graded_mesh.h"

#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // Distance from point p to the axis-aligned box of a cell (0 inside).
    double distance_to_cell(const Point<2> &p, const Triangulation<2>::active_cell_iterator &cell)
    {
      const BoundingBox<2> box = cell->bounding_box();
      double               gap[2];
      for (unsigned int i = 0; i < 2; ++i)
        gap[i] = std::max({box.lower_bound(i) - p[i], p[i] - box.upper_bound(i), 0.});
      return std::hypot(gap[0], gap[1]); // without overflow at any scale
    }
  } // namespace

  std::vector<double> coarse_steps(const double length, const double s)
  {
    const unsigned int  n = std::max(1u, static_cast<unsigned int>(std::floor(length / s + 1e-12)));
    std::vector<double> steps(n, s);
    steps.back() += length - n * s;
    return steps;
  }

  void make_tip_graded_mesh(Triangulation<2> &triangulation, const std::vector<double> &x_steps,
                            const std::vector<double> &z_steps, const Point<2> &tip,
                            const TipGrading &grading)
  {
    GridGenerator::subdivided_hyper_rectangle(triangulation, {x_steps, z_steps}, Point<2>(0, 0),
                                              Point<2>(std::accumulate(x_steps.begin(), x_steps.end(), 0.),
                                                       std::accumulate(z_steps.begin(), z_steps.end(), 0.)));
    while (true)
      {
        bool refined = false;
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            const double width = cell->extent_in_direction(0);
            // Ties (distance exactly a multiple of the width) are common on a
            // quadtree; the relative margin decides them the same way at every
            // scale, so meshes built for similar domains are exactly similar.
            const bool near_tip = width > grading.tip_width * (1 + 1e-9) &&
                                  distance_to_cell(tip, cell) < grading.grading_distance * width * (1 - 1e-9);
            const bool over_face = width > grading.face_width * (1 + 1e-9) &&
                                   cell->bounding_box().lower_bound(0) < tip[0] * (1 - 1e-9) &&
                                   cell->bounding_box().lower_bound(1) < tip[0] * (1 - 1e-9);
            if (near_tip || over_face)
              {
                cell->set_refine_flag();
                refined = true;
              }
          }
        if (!refined)
          break;
        triangulation.execute_coarsening_and_refinement();
      }
    // Within rounding: a tip at a dyadic point of a cell far from the origin
    // is as exact as the cell's vertices.
    if (!has_vertex_at(triangulation, tip, 1e-3 * grading.tip_width + 1e-14 * tip.norm()))
      throw std::logic_error("mesh: the tip-graded quadtree has no vertex at the crack tip");
  }

  bool has_vertex_at(const Triangulation<2> &triangulation, const Point<2> &point, const double tolerance)
  {
    return std::any_of(triangulation.get_vertices().begin(), triangulation.get_vertices().end(),
                       [&](const Point<2> &v) { return v.distance(point) < tolerance; });
  }

  std::function<unsigned int(const Triangulation<2>::active_cell_iterator &)>
  degree_graded_towards_tip(const double length, const unsigned int degree,
                            const unsigned int levels_per_degree)
  {
    if (levels_per_degree == 0)
      return {};
    return [length, degree = static_cast<int>(degree),
            step = static_cast<int>(levels_per_degree)](const Triangulation<2>::active_cell_iterator &cell) {
      const int k = static_cast<int>(std::round(std::log2(length / cell->extent_in_direction(0))));
      return static_cast<unsigned int>(std::max(1, degree - std::max(k, 0) / step));
    };
  }
} // namespace penny
