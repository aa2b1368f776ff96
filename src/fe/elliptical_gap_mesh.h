// Mesh of the quarter x, y, z >= 0 of a box [0, R]^2 x [0, H] around a flat
// elliptical gap x^2/a^2 + y^2/b^2 < 1 on z = 0 (a >= b), graded towards the
// crack front, for 3D elasticity on a serial or a p4est-distributed
// triangulation.
//
// Construction. The mesh is built in a reference space (X, Y, Z) in which the
// front is the unit circle X^2 + Y^2 = 1, Z = 0: a cube-sphere octant, a core
// cube [0, c0]^3 of m x m x m' cells, spherical shells around it (each shell
// one cell thick, its surface split into the three patches of the
// cube-sphere: X and Y next to the equator, Z around the pole) and, beyond
// the shell r = 1.4, shells blended in physical space from that shell to the
// box (per node, the direction turning from the shell's node to the box's,
// the distance growing geometrically): cells
// grow like the distance from the crack in every direction, so the far field
// costs few cells and none is a needle. The shells' thickness follows the
// angular cell width (times 1.5 below the tube, times `outer_shell_aspect`
// beyond it), but stops shrinking past 16 cells along the front, so that a
// finer front costs cells like m^2. The equator of every shell has
// 2m = `cells_along_front` edges at azimuths psi_e = e pi/(4m), which are
// the front coordinates of the columns (EllipticalFront::front_coordinate:
// (1 + a/b)/2 columns per column of even parametric angles at phi = 0, where
// the front turns fastest). In the meridian half-plane (r, theta) of the spherical coordinates the front is
// the point (1, 0); the block 0.6 <= r <= 1.4, 0 <= theta <= 0.4 of the X and
// Y patches is replaced by a conforming spider web around that point:
// `cells_around_front` sectors (kite cells at the front, each spanning two
// sectors), rings growing geometrically from the innermost to the block,
// swept along the front. So the front is a line of mesh edges and the
// grading towards it lies in the coarse mesh itself (p4est allows only about
// 18 refinement levels in 3D); the coarse mesh is conforming.
//
// Mapping. The swept cells (the X and Y patches from the innermost sphere to
// r = 1.4, spider web included) carry a ChartManifold, stretched spherical
// coordinates (r, theta, psi) with turned columns: phi the parametric angle
// of front coordinate psi,
//   R = r cos(theta), Z = r sin(theta), beta = phi + S(phi, R, Z),
//   x = a R cos(beta), y = b R sin(beta), z = h(phi) Z,
// h(phi) = a b/|(b cos phi, a sin phi)| the distance across the front in its
// normal plane per unit of r, so that the web's circles are circles in the
// front's normal plane at every phi (cells across the front are as tall as
// wide), and S the turn that makes each column leave the front along its
// normal (the stretched plane's radial lines lean on the front, by up to 79
// degrees at b/a = 0.1), fading beyond a depth limited where the front's
// normals cross. Refinement places new front points at r = 1, theta = 0,
// exactly on the ellipse. Towards the z-axis (across the pole patch and the
// core) the height scale blends into sqrt(a b), phi into psi and the turn
// into none; those cells, and the outer shells', are flat, their interior
// points interpolated from their faces by deal.II, so refined cells stay
// well shaped.
//
// Rings. The innermost ring has the physical radius `front_cell_size` x
// min(b, radius of curvature of the front) (b at phi = pi/2, b^2/a at
// phi = 0), but grows by at most `ring_ratio` from one column to the next;
// every column has the same number of rings: as many as `ring_ratio` needs
// on the gap itself or on the one of b/a = `counts_aspect_ratio`.
//
// Angles: the front point at parametric angle phi is (a cos phi, b sin phi, 0).
#pragma once

#include "fe/elliptical_front.h"

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace penny
{
  struct EllipticalGapMeshParameters
  {
    double semi_axis_a   = 1;               // a (m), along x; a >= b
    double semi_axis_b   = 0.5;             // b (m), along y; b/a >= smallest_aspect_ratio
    double domain_width  = 40;              // R/a: the box reaches x = R and y = R
    double domain_height = 40;              // H/a: the box reaches z = H (a free far boundary raised
                                            // K_I of the circle by 1.2e-4 more at 20 than at 40)
    unsigned int cells_along_front  = 16;   // edges along the quarter front (even)
    unsigned int cells_around_front = 8;    // sectors of the half-plane around the front (multiple of 4)
    double       front_cell_size    = 1e-3; // innermost ring radius / min(b, radius of curvature)
    double       outer_shell_aspect = 3;    // radial thickness / angular width of the shells beyond the tube
    double       ring_ratio         = 1.6;  // nominal ratio of successive ring radii (the rings fill
                                            // the tube exactly, so the ratio used is close to it)
    double counts_aspect_ratio = 0;         // the rings and outer shells are as many as the gap of this b/a
                                            // needs (0: this gap's b/a), so that the mesh of a family of gaps
                                            // counted alike moves with b/a instead of changing in steps
  };

  // The slenderest gap b/a the mesh is built for: below it the cells around
  // the tip degenerate (measured on the default mesh, degree 1: at 0.01 the
  // J-integral finds K_I = 0, at 0.005 cells turn inside out).
  constexpr double smallest_aspect_ratio = 0.02;

  // The largest box R/a and H/a the mesh is built for (measured on the test
  // mesh, b/a = 0.5, 2 ranks: K_I within 7.2e-2 at 40 a and at 1e5 a, 1.2e-1
  // at 1e6 a; from 1e12 a CG with AMG does not converge).
  constexpr double largest_box = 1e5;

  // Manifold id of the cells swept along the front (the chart above).
  constexpr dealii::types::manifold_id elliptical_front_manifold_id = 1;

  // Builds the coarse mesh into an empty `triangulation` (serial or
  // parallel::distributed: every rank builds the same coarse mesh), with the
  // boundary ids of fe/boundary_ids.h (symmetry: x = 0, second_symmetry:
  // y = 0, gap_face: z = 0 inside the ellipse, ligament: z = 0 outside it,
  // far: x = R, y = R, z = H) and the front manifold attached. Throws
  // std::invalid_argument for parameters out of range.
  void make_elliptical_gap_mesh(dealii::Triangulation<3>          &triangulation,
                                const EllipticalGapMeshParameters &p);

  // The cells make_elliptical_gap_mesh would build, counted without building
  // them (a fine web can hold millions).
  double elliptical_gap_mesh_cells(const EllipticalGapMeshParameters &p);

  // Radii of the rings around the front in the reference meridian plane of
  // each column e = 0 ... cells_along_front (front coordinate e pi/(2
  // cells_along_front)), from the innermost to the tube boundary (0.4), the
  // same number on every column; physical distances are these times h(phi)
  // (see above).
  std::vector<std::vector<double>> front_ring_radii(const EllipticalGapMeshParameters &p);

} // namespace penny
