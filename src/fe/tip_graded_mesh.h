// The built-in meshes of every model: a rectangle [0, X] x [0, Z] of
// rectangular coarse cells, refined as a quadtree towards the crack tip
// (c, 0) (doc/theory.md, section 2). A cell is split while it lies closer to
// the tip than `grading_distance` of its own widths and is wider than the tip
// cells, so cell widths halve geometrically towards the tip. The tip must be
// a vertex of the coarse grid or a dyadic point of one of its cells; then it
// is a vertex of the refined mesh. Optionally the cells over the gap face are
// refined to a width of their own.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <limits>
#include <vector>

namespace penny
{
  // Steps of width `s` filling [0, length >= s]; the remainder widens the last
  // one, never the first.
  std::vector<double> coarse_steps(double length, double s);

  struct TipGrading
  {
    double tip_width;        // width of the cells at the tip (m)
    double grading_distance; // refine while closer to the tip than this many cell widths
    // Width of the cells over the gap face, those with a corner in
    // [0, tip_x) x [0, tip_x): they resolve the opening (m).
    double face_width = std::numeric_limits<double>::infinity();
  };

  // The coarse grid of `x_steps` and `z_steps` from the origin, refined
  // towards `tip`. Boundary ids are left to the model.
  void make_tip_graded_mesh(dealii::Triangulation<2> &triangulation, const std::vector<double> &x_steps,
                            const std::vector<double> &z_steps, const dealii::Point<2> &tip,
                            const TipGrading &grading);

  // Whether a vertex lies within `tolerance` of `point`.
  bool has_vertex_at(const dealii::Triangulation<2> &triangulation, const dealii::Point<2> &point,
                     double tolerance);

  // The degree of each cell's element graded towards the tip (hp, Finite
  // element/Degree grading): a cell length/2^k wide (k > 0) gets `degree`
  // lowered by one every `levels_per_degree` levels, down to 1, so the small
  // cells near the tip carry low degrees. `length` is the model's tip length
  // (c for the penny gap). Empty when levels_per_degree is 0: the degree on
  // every cell.
  std::function<unsigned int(const dealii::Triangulation<2>::active_cell_iterator &)>
  degree_graded_towards_tip(double length, unsigned int degree, unsigned int levels_per_degree);
} // namespace penny
