// What the penny gap's mesh (fe/penny_gap_mesh.cc) takes from its gmsh
// reader (fe/penny_gap_gmsh.cc), for those two files alone.
#pragma once

#include "fe/penny_gap_mesh.h"

#include <deal.II/grid/tria.h>

namespace penny
{
  namespace internal
  {
    // Reads the gmsh mesh of `mesh.mesh_file` into `triangulation`: a .msh
    // file, or a .geo meshed by gmsh in a child process (rank 0; c, R and H
    // passed to it as parser numbers), the boundary ids taken from the
    // physical tags. Throws InputError, its message starting with the file
    // name in quotes, for a mesh that cannot be read or meshed, holds
    // triangles or lacks the tags 1-3; the geometry itself is checked by the
    // caller.
    void read_gmsh(dealii::Triangulation<2> &triangulation, const GeometryParameters &geometry,
                   const MeshParameters &mesh);
  } // namespace internal
} // namespace penny
