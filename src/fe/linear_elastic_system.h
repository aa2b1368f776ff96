// The solve pipeline every model shares: degrees of freedom on the model's
// mesh, zero-displacement constraints (with those of hanging nodes), the
// stiffness matrix a(u, v) = int sigma(u):e(v) dmu of the model's kinematics,
// its factorisation (or AMG preconditioner), and any number of right-hand
// sides, each a traction on one boundary. Cells, degrees of freedom and the
// Trilinos matrix are partitioned over the MPI ranks of the triangulation (the
// step-40 pattern); one rank is the serial case. Cells are mapped with
// polynomials of a chosen degree: 1 for straight-sided meshes, the element's
// degree where cells follow a curved crack front (MappingQ takes the curved
// positions from the triangulation's manifolds). The degree may differ from
// cell to cell (hp): a model may grade it down towards a crack tip, where
// the cells are small; the elements of the degrees 1 ... the model's degree
// then form an hp::FECollection, and hanging-node constraints join cells of
// different degrees.
#pragma once

#include "fe/elasticity.h"
#include "numerics/solver_failure.h"

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace penny
{
  // A displacement with the ghost entries each rank needs to evaluate its cells.
  using DisplacementVector = dealii::TrilinosWrappers::MPI::Vector;

  struct LinearSolverParameters
  {
    enum class Type
    {
      direct,      // CHOLMOD on one rank, MUMPS on several
      cg_amg,      // conjugate gradients with Trilinos' algebraic multigrid
      cg_multigrid // conjugate gradients with matrix-free p-multigrid (3D, one degree on every cell)
    };
    Type         type;
    double       tolerance; // relative residual |A u - b|/|b| every solve must reach
    unsigned int max_iterations;
  };

  // What every model is built with besides its geometry and mesh.
  struct ElasticModelParameters
  {
    MaterialParameters material;
    unsigned int       degree;
    // Tip refinement levels per step down in degree towards a crack tip
    // (fe/tip_graded_mesh.h): 0 for the degree on every cell.
    unsigned int           levels_per_degree = 0;
    LinearSolverParameters linear_solver;
    // The ranks that share the model: all of them, or one alone when a sweep
    // gives each rank its own solves.
    MPI_Comm communicator = MPI_COMM_WORLD;
  };

  // A solve that failed or missed its tolerance.
  struct LinearSolverFailure : SolverFailure
  {
    explicit LinearSolverFailure(const std::string &message)
        : SolverFailure(message, "subsection 'Linear solver' sets the solver, its tolerance and iterations")
    {
    }
  };

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

  // The sparse Cholesky factors of the stiffness matrix on one rank (CHOLMOD).
  struct SerialCholesky;
  class MatrixFreeElasticity;

  // "CHOLMOD" (direct, one MPI rank), "MUMPS" (direct, several), "CG + AMG" or
  // "CG + matrix-free p-multigrid":
  // the solver of a system on the ranks of `communicator`.
  std::string solver_name(const LinearSolverParameters &linear_solver, MPI_Comm communicator);

  template <typename Kinematics> class LinearElasticSystem
  {
  public:
    static constexpr int dim = Kinematics::dim;

    // The normal traction t(x) on a face: it acts along +z on the upper half
    // model and opens the gap (Pa).
    using Traction = std::function<double(const dealii::Point<dim> &)>;
    // A stress field sigma(x) in the kinematics' components (Pa).
    using Stress = std::function<dealii::SymmetricTensor<2, dim>(const dealii::Point<dim> &)>;

    // The degree of a cell's element, from 1 to the model's degree.
    using CellDegree =
        std::function<unsigned int(const typename dealii::Triangulation<dim>::active_cell_iterator &)>;

    // `degree` on every cell, or `cell_degree` of each cell if given.
    LinearElasticSystem(const dealii::Triangulation<dim> &triangulation, unsigned int degree,
                        unsigned int mapping_degree, const MaterialParameters &material,
                        const LinearSolverParameters &linear_solver,
                        std::vector<ZeroDisplacement> zero_displacements, dealii::TimerOutput &timer,
                        CellDegree cell_degree = {});
    ~LinearElasticSystem();

    // Distributes the degrees of freedom, assembles and factorises; again
    // after the triangulation was refined.
    void setup();

    // The load vector int_face t v_z of the traction t on `face`.
    dealii::TrilinosWrappers::MPI::Vector load_vector(dealii::types::boundary_id face,
                                                      const Traction            &traction) const;
    // The load vector int_face (sigma n).v of the traction of the stress sigma
    // on `face` (n its outward normal).
    dealii::TrilinosWrappers::MPI::Vector stress_load_vector(dealii::types::boundary_id face,
                                                             const Stress              &stress) const;

    // u = A^-1 b. Throws if the solve misses the tolerance or produces NaN/Inf.
    DisplacementVector solve(const dealii::TrilinosWrappers::MPI::Vector &load);

    // The same to the relative residual `tolerance`; the iterative solvers
    // start from `start` (from zero if it is empty).
    DisplacementVector solve(const dealii::TrilinosWrappers::MPI::Vector &load, double tolerance,
                             const DisplacementVector &start);

    // Both together: the displacement under the traction t on `face`.
    DisplacementVector solve(dealii::types::boundary_id face, const Traction &traction);

    const SolveReport &last_solve() const { return report; }
    // The relative residual every solve reaches unless told otherwise.
    double                         tolerance() const { return linear_solver.tolerance; }
    const dealii::DoFHandler<dim> &get_dof_handler() const { return dof_handler; }
    // The elements, indexed by the cells' active FE index.
    const dealii::hp::FECollection<dim>      &get_fe() const { return fe; }
    const dealii::hp::MappingCollection<dim> &get_mapping() const { return mapping; }
    // The highest degree.
    unsigned int degree() const { return fe.max_degree(); }
    // Gauss quadratures on cells and faces, degree + extra points per
    // direction for each element of the collection.
    dealii::hp::QCollection<dim>      gauss(unsigned int extra) const;
    dealii::hp::QCollection<dim - 1>  face_gauss(unsigned int extra) const;
    const IsotropicElasticity        &get_elasticity() const { return elasticity; }
    const dealii::Triangulation<dim> &get_triangulation() const { return dof_handler.get_triangulation(); }
    MPI_Comm get_communicator() const { return get_triangulation().get_communicator(); }

    // Entries of the stiffness matrix, all ranks together (none matrix-free).
    std::size_t n_matrix_entries() const { return stiffness.n_nonzero_elements(); }

    std::string solver_name() const { return penny::solver_name(linear_solver, get_communicator()); }

  private:
    // A force per area f(x, n) on the faces of outward normal n (Pa).
    using FaceForce =
        std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &, const dealii::Tensor<1, dim> &)>;
    // int_face f.v.
    dealii::TrilinosWrappers::MPI::Vector face_load(dealii::types::boundary_id face,
                                                    const FaceForce           &force) const;

    void distribute_and_constrain();
    // The zero displacements and hanging nodes of one DoFHandler on the mesh.
    void constrain(const dealii::DoFHandler<dim> &dofs, dealii::AffineConstraints<double> &constraints) const;
    bool matrix_free() const { return linear_solver.type == LinearSolverParameters::Type::cg_multigrid; }
    // A u, assembled or matrix-free.
    void vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
               const dealii::TrilinosWrappers::MPI::Vector &src) const;
    void assemble_matrix();
    void factorise();
    void build_solver();
    // x = A^-1 b with the factorisation, or the preconditioned CG from x to
    // the relative residual `tolerance`.
    void apply_inverse(dealii::TrilinosWrappers::MPI::Vector       &x,
                       const dealii::TrilinosWrappers::MPI::Vector &b, double tolerance);

    const CellDegree                         cell_degree;
    const dealii::hp::FECollection<dim>      fe;
    const dealii::hp::MappingCollection<dim> mapping;
    const IsotropicElasticity                elasticity;
    const LinearSolverParameters             linear_solver;
    const std::vector<ZeroDisplacement>      zero_displacements;
    dealii::TimerOutput                     &timer;

    dealii::DoFHandler<dim>                dof_handler;
    dealii::IndexSet                       owned, relevant;
    dealii::AffineConstraints<double>      constraints;
    dealii::TrilinosWrappers::SparseMatrix stiffness;

    // Direct solvers: CHOLMOD on one rank (on a copy of the matrix), MUMPS on several.
    std::unique_ptr<SerialCholesky>                         cholesky;
    dealii::SolverControl                                   mumps_control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> mumps;
    dealii::TrilinosWrappers::PreconditionAMG               amg;
    // The matrix-free operator with its multigrid, instead of the matrix (3D).
    std::unique_ptr<MatrixFreeElasticity> operator_without_matrix;

    SolveReport report{};
  };
} // namespace penny
