// Meshes of the penny gap's half model 0 <= r <= R, 0 <= z <= H with the
// crack tip (c, 0) at a vertex and the boundary ids of fe/boundary_ids.h.
#pragma once

#include "input/fe_parameters.h"

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <functional>

namespace penny
{
  inline dealii::Point<2> crack_tip(const GeometryParameters &geometry)
  {
    return {geometry.gap_radius, 0};
  }

  // Builds the scene's mesh (built-in generator or gmsh file), then applies the
  // global refinements. Throws InputError for a mesh that does not fit the
  // geometry; `check_size` sees the number of cells the mesh will have before
  // the built-in mesh or the refinements are built, and throws if too many.
  void make_penny_gap_mesh(dealii::Triangulation<2> &triangulation, const GeometryParameters &geometry,
                           const MeshParameters &mesh, const std::function<void(double)> &check_size);
} // namespace penny
