// Meshes of the penny gap's half model 0 <= r <= R, 0 <= z <= H with the
// crack tip (c, 0) at a vertex and the boundary ids of fe/boundary_ids.h.
#pragma once

#include "fe/boundary_ids.h"

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <string>

namespace penny
{
  // The half model of the penny gap.
  struct GeometryParameters
  {
    double      gap_radius;    // c (m)
    double      domain_radius; // R (m)
    double      domain_height; // H (m)
    FarBoundary far_boundary;  // on r = R and z = H
  };

  struct MeshParameters
  {
    enum class Generator
    {
      builtin, // a quadtree graded towards the tip
      gmsh     // read from mesh_file
    };
    Generator    generator;
    unsigned int tip_levels;         // refinement levels below cell size c at the tip
    unsigned int gap_face_levels;    // cells over the gap face are at most c/2^levels wide
    double       grading_distance;   // refine a cell closer to the tip than this many cell sizes
    unsigned int global_refinements; // uniform refinements after the grading
    double       cell_aspect_ratio;  // builtin cells are this many times taller than wide
    std::string  mesh_file;          // gmsh .geo or .msh
  };

  inline dealii::Point<2> crack_tip(const GeometryParameters &geometry)
  {
    return {geometry.gap_radius, 0};
  }

  // Builds the mesh (built-in generator or gmsh file), then applies the
  // global refinements. Throws InputError for a gmsh mesh that does not fit
  // the geometry, its message starting with the file name in quotes.
  void make_penny_gap_mesh(dealii::Triangulation<2> &triangulation, const GeometryParameters &geometry,
                           const MeshParameters &mesh);

  // The cells the mesh will have, known before it is built: the built-in
  // quadtree counted level by level, a gmsh mesh read (and checked as above)
  // without its refinements. Collective on `communicator` (rank 0 runs gmsh).
  double penny_gap_mesh_cells(const GeometryParameters &geometry, const MeshParameters &mesh,
                              MPI_Comm communicator);

  // Active cells of the built-in quadtree after the global refinements.
  double quadtree_cells(const GeometryParameters &geometry, const MeshParameters &mesh);
} // namespace penny
