// Meshes of the half model 0 <= r <= R, 0 <= z <= H with the crack tip (c, 0)
// at a vertex, and the boundary ids (= gmsh physical curve tags) the model uses.
#pragma once

#include "parameters.h"

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

namespace penny
{
  namespace boundary_id
  {
    constexpr dealii::types::boundary_id axis     = 1; // r = 0
    constexpr dealii::types::boundary_id gap_face = 2; // z = 0, r < c: loaded
    constexpr dealii::types::boundary_id ligament = 3; // z = 0, r > c: u_z = 0
    constexpr dealii::types::boundary_id far      = 4; // r = R and z = H
  } // namespace boundary_id

  inline dealii::Point<2> crack_tip(const GeometryParameters &geometry)
  {
    return {geometry.gap_radius, 0};
  }

  // Builds the scene's mesh (built-in generator or gmsh file), then applies the
  // global refinements. Throws InputError for a mesh that does not fit.
  void make_gap_mesh(dealii::Triangulation<2> &triangulation,
                     const GeometryParameters &geometry,
                     const MeshParameters     &mesh);
} // namespace penny
