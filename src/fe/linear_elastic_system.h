// The solve pipeline every model shares: degrees of freedom on the model's
// mesh, zero-displacement constraints (with those of hanging nodes), the
// stiffness matrix a(u, v) = int sigma(u):e(v) dmu of the model's kinematics,
// its factorisation (or AMG preconditioner), and any number of right-hand
// sides, each a traction on one boundary. Cells, degrees of freedom and the
// Trilinos matrix are partitioned over the MPI ranks of the triangulation (the
// step-40 pattern); one rank is the serial case. Cells are mapped with
// polynomials of a chosen degree: 1 for straight-sided meshes, the element's
// degree where cells follow a curved crack front (MappingQ takes the curved
// positions from the triangulation's manifolds).
#pragma once

#include "fe/elasticity.h"
#include "input/fe_parameters.h"

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace penny
{
  // A displacement with the ghost entries each rank needs to evaluate its cells.
  using DisplacementVector = dealii::TrilinosWrappers::MPI::Vector;

  struct SolveReport
  {
    double       relative_residual;  // |A u - b| / |b|
    unsigned int iterations;         // 0 for the direct solver
    double       condition_estimate; // of the preconditioned matrix, from CG; 0 for the direct solver
  };

  // u_i = 0 for the components in `components` on boundary `boundary`.
  struct ZeroDisplacement
  {
    dealii::types::boundary_id boundary;
    dealii::ComponentMask      components;
  };

  template <typename Kinematics> class LinearElasticSystem
  {
  public:
    static constexpr int dim = Kinematics::dim;

    // The normal traction t(x) on a face: it acts along +z on the upper half
    // model and opens the gap (Pa).
    using Traction = std::function<double(const dealii::Point<dim> &)>;

    LinearElasticSystem(const dealii::Triangulation<dim> &triangulation, unsigned int degree,
                        unsigned int mapping_degree, const MaterialParameters &material,
                        const LinearSolverParameters &linear_solver,
                        std::vector<ZeroDisplacement> zero_displacements, dealii::TimerOutput &timer);

    // Distributes the degrees of freedom, assembles and factorises; again
    // after the triangulation was refined.
    void setup();

    // The load vector int_face t v_z of the traction t on `face`.
    dealii::TrilinosWrappers::MPI::Vector load_vector(dealii::types::boundary_id face,
                                                      const Traction            &traction) const;

    // u = A^-1 b. Throws if the solve misses the tolerance or produces NaN/Inf.
    DisplacementVector solve(const dealii::TrilinosWrappers::MPI::Vector &load);

    // Both together: the displacement under the traction t on `face`.
    DisplacementVector solve(dealii::types::boundary_id face, const Traction &traction);

    const SolveReport                &last_solve() const { return report; }
    const dealii::DoFHandler<dim>    &get_dof_handler() const { return dof_handler; }
    const dealii::FESystem<dim>      &get_fe() const { return fe; }
    const dealii::Mapping<dim>       &get_mapping() const { return mapping; }
    const IsotropicElasticity        &get_elasticity() const { return elasticity; }
    const dealii::Triangulation<dim> &get_triangulation() const { return dof_handler.get_triangulation(); }
    MPI_Comm get_communicator() const { return get_triangulation().get_communicator(); }

    // Entries of the stiffness matrix, all ranks together.
    std::size_t n_matrix_entries() const { return stiffness.n_nonzero_elements(); }

    // "UMFPACK" (one MPI rank), "MUMPS" (several) or "CG + AMG".
    std::string solver_name() const;

    // The last component of u (u_z) at the origin, which must be a vertex:
    // read on the rank that owns that degree of freedom, known on every rank.
    double normal_displacement_at_origin(const DisplacementVector &u) const;

  private:
    void distribute_and_constrain();
    void assemble_matrix();
    void factorise();
    void build_solver();
    // x = A^-1 b with the factorisation or the preconditioned CG.
    void apply_inverse(dealii::TrilinosWrappers::MPI::Vector       &x,
                       const dealii::TrilinosWrappers::MPI::Vector &b);

    const dealii::FESystem<dim>         fe;
    const dealii::MappingQ<dim>         mapping;
    const IsotropicElasticity           elasticity;
    const LinearSolverParameters        linear_solver;
    const std::vector<ZeroDisplacement> zero_displacements;
    dealii::TimerOutput                &timer;

    dealii::DoFHandler<dim>                dof_handler;
    dealii::IndexSet                       owned, relevant;
    dealii::AffineConstraints<double>      constraints;
    dealii::TrilinosWrappers::SparseMatrix stiffness;

    // Direct solvers: UMFPACK on one rank (on a copy of the matrix), MUMPS on several.
    dealii::SparsityPattern                                 serial_sparsity;
    dealii::SparseMatrix<double>                            serial_stiffness;
    dealii::SparseDirectUMFPACK                             umfpack;
    dealii::SolverControl                                   mumps_control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> mumps;
    dealii::TrilinosWrappers::PreconditionAMG               amg;

    SolveReport report{};
  };
} // namespace penny
