// Boundary ids shared by the models (= gmsh physical curve tags of the
// penny-gap meshes). Every model is a half model z >= 0 whose plane z = 0
// holds the gap face (loaded) and the ligament (u_z = 0).
#pragma once

#include <deal.II/base/types.h>

namespace penny::boundary_id
{
  constexpr dealii::types::boundary_id symmetry        = 1; // the axis r = 0, or the plane x = 0
  constexpr dealii::types::boundary_id gap_face        = 2; // z = 0 inside the gap: loaded
  constexpr dealii::types::boundary_id ligament        = 3; // z = 0 outside the gap: u_z = 0
  constexpr dealii::types::boundary_id far             = 4; // the truncation of the solid
  constexpr dealii::types::boundary_id second_symmetry = 5; // x = lambda/2 (periodic gap), or y = 0 (3D)
} // namespace penny::boundary_id

namespace penny
{
  // What holds the solid at its far boundary.
  enum class FarBoundary
  {
    free,     // traction free
    clamped,  // u = 0
    far_field // the traction of the gap's far field (fe/far_field_load.h)
  };
} // namespace penny
