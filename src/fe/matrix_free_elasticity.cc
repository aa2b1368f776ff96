#include "fe/matrix_free_elasticity.h"

#include "fe/elastic_operator.h"

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>
#include <deal.II/multigrid/multigrid.h>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // The system's operator and CG work in double; the multigrid, only a
    // preconditioner, in float: the same CG iterations, the solve 10.1 s ->
    // 6.9 s (b/a = 0.5, degree 3) and 380 s -> 253 s (b/a = 0.1, degree 6,
    // memory 4.2 -> 3.7 GB), 2 ranks.
    using Vector      = ElasticOperator<double>::Vector;
    using LevelVector = ElasticOperator<float>::Vector;

    // The coarsest degree solved exactly: MUMPS' factors of its matrix.
    class DirectCoarseSolve : public MGCoarseGridBase<LevelVector>
    {
    public:
      // `coarsest`: the level's operator, for the layout of its vectors.
      DirectCoarseSolve(const TrilinosWrappers::SparseMatrix &matrix, const ElasticOperator<float> &coarsest)
          : solver(control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"))
      {
        solver.initialize(matrix);
        LevelVector layout;
        coarsest.initialize_dof_vector(layout);
        x.reinit(layout.get_partitioner());
        b.reinit(layout.get_partitioner());
      }

      // MUMPS solves in double: the level vectors are copied in and out.
      void operator()(const unsigned int, LevelVector &dst, const LevelVector &src) const override
      {
        b.copy_locally_owned_data_from(src);
        solver.solve(x, b);
        dst.copy_locally_owned_data_from(x);
      }

    private:
      SolverControl                          control;
      mutable TrilinosWrappers::SolverDirect solver;
      mutable Vector                         x, b;
    };

    using Smoother = PreconditionChebyshev<ElasticOperator<float>, LevelVector, DiagonalMatrix<LevelVector>>;
    using Transfer = MGTransferGlobalCoarsening<3, LevelVector>;

    void copy(Vector &dst, const TrilinosWrappers::MPI::Vector &src)
    {
      for (const auto i : src.locally_owned_elements())
        dst[i] = src[i];
    }

    void copy(TrilinosWrappers::MPI::Vector &dst, const Vector &src)
    {
      for (const auto i : dst.locally_owned_elements())
        dst[i] = src[i];
      dst.compress(VectorOperation::insert);
    }
  } // namespace

  namespace
  {
    // CG applies the system's operator, with the assembled matrix's p + 2
    // Gauss points per direction on the curved cells, so that its solution
    // is the assembled system's. The multigrid that preconditions it needs
    // only an operator spectrally close to that one: its levels take p + 1
    // points, at about half the cost of an application (elliptical-gap scene,
    // b/a = 0.5, one rank: degree 2, 133 CG iterations either way, solve 35
    // s against 62 s; degree 3, 170 against 169 iterations, 123 s against
    // 224 s; K_I the same to 1e-10).
    constexpr unsigned int system_points = 2;
    constexpr unsigned int level_points  = 1;
  } // namespace

  // Level l carries the l-th degree of the sequence 1, ..., p/2, p; `fine` is
  // the system's operator.
  struct MatrixFreeElasticity::Hierarchy
  {
    std::vector<std::unique_ptr<DoFHandler<3>>>                           coarser_dofs;
    MGLevelObject<AffineConstraints<float>>                               level_constraints;
    ElasticOperator<double>                                               fine;
    MGLevelObject<ElasticOperator<float>>                                 operators;
    MGLevelObject<MGTwoLevelTransfer<3, LevelVector>>                     transfers;
    std::unique_ptr<Transfer>                                             transfer;
    TrilinosWrappers::SparseMatrix                                        coarse_matrix;
    std::unique_ptr<DirectCoarseSolve>                                    coarse;
    mg::Matrix<LevelVector>                                               level_matrices;
    MGSmootherPrecondition<ElasticOperator<float>, Smoother, LevelVector> smoother;
    std::unique_ptr<Multigrid<LevelVector>>                               multigrid;
    std::unique_ptr<PreconditionMG<3, LevelVector, Transfer>>             preconditioner;
  };

  MatrixFreeElasticity::MatrixFreeElasticity(const DoFHandler<3>             &dof_handler,
                                             const AffineConstraints<double> &constraints,
                                             const Mapping<3> &mapping, const Constrain &constrain,
                                             const IsotropicElasticity &elasticity)
      : hierarchy(std::make_unique<Hierarchy>())
  {
    Hierarchy &h = *hierarchy;
    // Degrees p, p/2, ..., 1 (deal.II's bisect sequence), where p, p - 1, ...,
    // 1 took fewer CG iterations but more time on more levels (b/a = 0.1 of
    // the six-digit scene, 2 ranks: degree 4, 363 against 324 iterations,
    // solve 91 s against 113 s; degree 6, 537 against 392, 380 s against
    // 498 s; b/a = 0.5, degree 3, 132 against 126, 10.1 s against 11.1 s).
    const std::vector<unsigned int> degrees =
        MGTransferGlobalCoarseningTools::create_polynomial_coarsening_sequence(
            dof_handler.get_fe().degree,
            MGTransferGlobalCoarseningTools::PolynomialCoarseningSequenceType::bisect);
    const unsigned int                 top = degrees.size() - 1;
    std::vector<const DoFHandler<3> *> dofs(top + 1, &dof_handler);
    h.level_constraints.resize(0, top);
    h.level_constraints[top].copy_from(constraints);
    for (unsigned int level = 0; level < top; ++level)
      {
        auto coarser = std::make_unique<DoFHandler<3>>(dof_handler.get_triangulation());
        coarser->distribute_dofs(FESystem<3>(FE_Q<3>(degrees[level]), 3));
        AffineConstraints<double> coarser_constraints;
        constrain(*coarser, coarser_constraints);
        h.level_constraints[level].copy_from(coarser_constraints);
        dofs[level] = coarser.get();
        h.coarser_dofs.push_back(std::move(coarser));
      }

    h.operators.resize(0, top);
    h.transfers.resize(0, top);
    MGLevelObject<Smoother::AdditionalData> smoothing(0, top);
    for (unsigned int level = 0; level <= top; ++level)
      {
        h.operators[level].reinit(mapping, *dofs[level], h.level_constraints[level], elasticity,
                                  level_points);
        if (level > 0)
          h.transfers[level].reinit(*dofs[level], *dofs[level - 1], h.level_constraints[level],
                                    h.level_constraints[level - 1]);
        // Chebyshev of degree 5, its upper bound from 20 CG steps (as deal.II's
        // matrix-free tutorials), on the upper 1/300 of the spectrum instead
        // of their 1/20: a lower degree's space leaves more of the spectrum to
        // the smoother than a coarser mesh does (elliptical-gap scene, 2 ranks,
        // levels p, p - 1, ..., 1 in double: b/a = 0.5, degree 3, 126 against
        // 170 CG iterations, solve 30 s against 40 s; b/a = 0.1, degree 4, 329
        // against 421, 295 s against 376 s; degree 2 unchanged; ranges 100 to
        // 1000 and degrees 4 to 12 gained no more).
        smoothing[level].smoothing_range     = 300;
        smoothing[level].degree              = 5;
        smoothing[level].eig_cg_n_iterations = 20;
        smoothing[level].preconditioner      = std::make_shared<DiagonalMatrix<LevelVector>>();
        h.operators[level].compute_inverse_diagonal(smoothing[level].preconditioner->get_vector());
      }
    h.fine.reinit(mapping, dof_handler, constraints, elasticity, system_points);
    h.transfer = std::make_unique<Transfer>(h.transfers, [&h](const unsigned int level, LevelVector &v) {
      h.operators[level].initialize_dof_vector(v);
    });

    h.operators[0].assemble(h.coarse_matrix, h.level_constraints[0]);
    h.coarse = std::make_unique<DirectCoarseSolve>(h.coarse_matrix, h.operators[0]);
    h.level_matrices.initialize(h.operators);
    h.smoother.initialize(h.operators, smoothing);
    h.multigrid = std::make_unique<Multigrid<LevelVector>>(h.level_matrices, *h.coarse, *h.transfer,
                                                           h.smoother, h.smoother, 0, top);
    h.preconditioner =
        std::make_unique<PreconditionMG<3, LevelVector, Transfer>>(dof_handler, *h.multigrid, *h.transfer);
  }

  MatrixFreeElasticity::~MatrixFreeElasticity() = default;

  void MatrixFreeElasticity::vmult(TrilinosWrappers::MPI::Vector       &dst,
                                   const TrilinosWrappers::MPI::Vector &src) const
  {
    const ElasticOperator<double> &fine = hierarchy->fine;
    Vector                         u, a_u;
    fine.initialize_dof_vector(u);
    fine.initialize_dof_vector(a_u);
    copy(u, src);
    fine.vmult(a_u, u);
    copy(dst, a_u);
  }

  void MatrixFreeElasticity::solve(TrilinosWrappers::MPI::Vector &x, const TrilinosWrappers::MPI::Vector &b,
                                   SolverControl &control, const std::function<void(double)> &condition)
  {
    const ElasticOperator<double> &fine = hierarchy->fine;
    Vector                         u, load;
    fine.initialize_dof_vector(u);
    fine.initialize_dof_vector(load);
    copy(load, b);
    copy(u, x);
    SolverCG<Vector> cg(control);
    cg.connect_condition_number_slot(condition);
    cg.solve(fine, u, load, *hierarchy->preconditioner);
    copy(x, u);
  }
} // namespace penny
