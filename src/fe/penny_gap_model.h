// The finite-element model of one penny gap: axisymmetric linear elasticity
// on the half model 0 <= r <= R, 0 <= z <= H with the gap face loaded
// (doc/theory.md, section 2). The mesh is a parallel::shared::Triangulation,
// held whole on every rank: p4est, behind parallel::distributed, stops at 29
// refinement levels below a coarse cell, and a quadtree from cells of 256 c
// down to tips of 1e-9 c needs 38. Degrees of freedom and the matrix are
// distributed (fe/linear_elastic_system.h); the stiffness matrix is
// factorised once, and each load is one more right-hand side.
#pragma once

#include "closed_forms/face_load.h"
#include "fe/far_field_load.h"
#include "fe/linear_elastic_system.h"
#include "fe/penny_gap_mesh.h"

#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>

#include <optional>

namespace penny
{
  // What a penny-gap model is built from.
  struct PennyGapModelParameters : ElasticModelParameters
  {
    GeometryParameters geometry;
    MeshParameters     mesh;

    // The same model for a gap of radius c: R/c and H/c kept, so the meshes
    // of a search over c are exactly similar.
    PennyGapModelParameters scaled_to(double c) const;
  };

  // The face load p(r) as the normal traction at a point (r, 0) of the gap
  // face; `load` must outlive the function.
  inline LinearElasticSystem<Axisymmetric>::Traction face_traction(const FaceLoad &load)
  {
    return [&load](const dealii::Point<2> &x) { return load(x[0]); };
  }

  class PennyGapModel
  {
  public:
    // Builds the mesh, the constraints and the factorised stiffness matrix.
    PennyGapModel(const PennyGapModelParameters &parameters, dealii::TimerOutput &timer);

    // The displacement under the face traction `load`. Throws if the solve
    // misses the tolerance or produces NaN/Inf.
    DisplacementVector solve(const FaceLoad &load);
    // The last solve's iterations (all of them with the far field), residual
    // and condition estimate.
    const SolveReport &last_solve() const;

    // Refines the `fraction` of cells with the largest Kelly indicators of u
    // (the same cells on every rank), then rebuilds and factorises the system.
    void refine_by_kelly(const DisplacementVector &u, double fraction);
    // The cells after such a refinement, about: each refined cell becomes
    // four, and balancing the levels refines about as many again.
    static double cells_after_refinement(double cells, double fraction) { return cells * (1 + 6 * fraction); }

    // u_z at the centre of the gap face: the opening of one face at r = 0 (m).
    double opening_at_centre(const DisplacementVector &u) const;
    // Volume between the two faces, 2 int_0^c 2 pi r u_z dr (m^3).
    double gap_volume(const DisplacementVector &u) const;

    const LinearElasticSystem<Axisymmetric> &get_system() const { return system; }
    const MaterialParameters                &material() const { return parameters.material; }
    double                                   gap_radius() const { return parameters.geometry.gap_radius; }
    dealii::Point<2>                         crack_tip() const { return {gap_radius(), 0}; }

  private:
    const PennyGapModelParameters              parameters;
    dealii::TimerOutput                       &timer;
    dealii::parallel::shared::Triangulation<2> triangulation;
    LinearElasticSystem<Axisymmetric>          system;
    // With a far-field far boundary: its load, per mesh.
    std::optional<FarFieldLoad<Axisymmetric>> far_field;

    void load_far_field();
  };
} // namespace penny
