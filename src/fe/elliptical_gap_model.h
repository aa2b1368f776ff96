// The finite-element model of one elliptical gap: 3D linear elasticity on the
// quarter x, y, z >= 0 of a box around the flat gap x^2/a^2 + y^2/b^2 < 1 on
// z = 0 (doc/theory.md, section 8). u_x = 0 on the symmetry plane x = 0,
// u_y = 0 on y = 0, u_z = 0 on the ligament, the face traction t(x, y) on
// the gap face, the far faces free, clamped or under the traction of the
// gap's far field (fe/far_field_load.h). The mesh (fe/elliptical_gap_mesh.h) has
// the front as a line of mesh edges on a manifold and is graded towards it in
// the coarse mesh, so that a p4est parallel::distributed::Triangulation<3>
// holds it and refines it globally; cells, degrees of freedom and the
// Trilinos matrix are distributed over the MPI ranks, and the cells are
// mapped with polynomials of the element's degree so that the curved cells
// along the front keep their shape.
#pragma once

#include "fe/elliptical_gap_mesh.h"
#include "fe/far_field_load.h"
#include "fe/linear_elastic_system.h"

#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <optional>
#include <vector>

namespace penny
{
  // Built on all ranks, with the degree on every cell.
  struct EllipticalGapModelParameters : ElasticModelParameters
  {
    EllipticalGapMeshParameters mesh;
    unsigned int                global_refinements;
    // Then the cells within tip_refinement_radius x a of the tip (a, 0, 0)
    // that do not touch the front, refined tip_refinements times.
    unsigned int tip_refinements       = 0;
    double       tip_refinement_radius = 0;
    FarBoundary  far_boundary          = FarBoundary::free; // on the box's far faces
  };

  // The active cells of the model, known from its coarse mesh before it is
  // refined: each refinement makes a cell 8, and the coarse cells that meet
  // the ball of the tip refinements are refined again that many times (an
  // upper bound, but for the cells the refinement's balance adds).
  double elliptical_model_cells(const EllipticalGapModelParameters &parameters);

  class EllipticalGapModel
  {
  public:
    using Traction = LinearElasticSystem<Solid>::Traction;

    // Builds and refines the mesh, the constraints and the stiffness matrix
    // with its preconditioner (or factorisation).
    EllipticalGapModel(const EllipticalGapModelParameters &parameters, dealii::TimerOutput &timer);

    // The displacement under the normal traction t(x) on the gap face.
    DisplacementVector solve(const Traction &traction);
    // The last solve's iterations (all of them with the far field), residual
    // and condition estimate.
    const SolveReport &last_solve() const;

    // Parametric angles of the front vertices, 0 to pi/2.
    std::vector<double> front_vertex_angles() const;
    // u_z at the centre of the gap face: the opening of one face at (0, 0) (m).
    double opening_at_centre(const DisplacementVector &u) const;
    // Volume between the faces of the whole gap, 8 int_quarter u_z dA (m^3).
    double gap_volume(const DisplacementVector &u) const;

    const LinearElasticSystem<Solid>   &get_system() const { return system; }
    const EllipticalFront              &front() const { return crack_front; }
    const MaterialParameters           &material() const { return parameters.material; }
    const EllipticalGapModelParameters &get_parameters() const { return parameters; }

  private:
    const EllipticalGapModelParameters              parameters;
    dealii::TimerOutput                            &timer;
    dealii::parallel::distributed::Triangulation<3> triangulation;
    LinearElasticSystem<Solid>                      system;
    const EllipticalFront                           crack_front;
    std::optional<FarFieldLoad<Solid>>              far_field;
  };
} // namespace penny
