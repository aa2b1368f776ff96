#include "problems/fe_sections.h"

#include "problems/solid.h"

namespace penny
{
  void elastic_model_sections(Sections &sections, ElasticModelParameters &model,
                              const ModelDimension dimension)
  {
    using Type = LinearSolverParameters::Type;
    material_section(sections, model.material);
    // The displacement formulation's stiffness has a condition that grows like
    // lambda/mu = 2 nu/(1 - 2 nu). Beyond what the stability scenes verify the
    // solves lose the verdicts' digits: penny-gap's direct solve missed 1e-9
    // from nu = 0.49999 on (residual 2e-9); an elliptical gap's CG + AMG had
    // not converged after 150 s at 0.4999 (18 s at 0.3), and its direct
    // solve gave K_I = 0 at 0.499999.
    const double largest_nu = dimension == ModelDimension::two ? 0.4999 : 0.499;
    sections.require(model.material.poissons_ratio <= largest_nu, "Material/Poisson's ratio nu",
                     model.material.poissons_ratio,
                     "(-1, " + shortest(largest_nu) + "] for the " +
                         (dimension == ModelDimension::two ? "2D" : "3D") +
                         " finite-element models, as far as the stability scenes verify them");
    sections.subsection("Finite element", [&](Entries &entries) {
      entries.integer("Polynomial degree", model.degree, 4u, 1u, 8u,
                      "Degree of the continuous Lagrange elements of the displacement. Units: none.");
      if (dimension == ModelDimension::two)
        entries.integer(
            "Degree grading", model.levels_per_degree, 0u, 0u, 64u,
            "Tip refinement levels per step down in degree. Cells b/2^k wide (b = c, or min(c, lambda/2 - "
            "c) for the periodic gap) get degree max(1, degree - floor(k / this)), so the small cells near "
            "the tip carry low degrees (hp); 0 keeps the degree on every cell. Units: levels.");
    });
    sections.subsection("Linear solver", [&](Entries &entries) {
      auto           &solver = model.linear_solver;
      EnumNames<Type> types{{"direct", Type::direct}, {"cg-amg", Type::cg_amg}};
      std::string     help =
          "direct: sparse Cholesky (CHOLMOD) on one MPI rank, sparse LU (MUMPS through Trilinos "
          "Amesos) on several. cg-amg: conjugate gradients preconditioned with Trilinos' "
          "algebraic multigrid, for large meshes.";
      if (dimension == ModelDimension::three)
        {
          types.emplace_back("cg-multigrid", Type::cg_multigrid);
          help += " cg-multigrid: conjugate gradients preconditioned with polynomial multigrid, the operator "
                  "evaluated cell by cell without a matrix (degrees p, p-1, ..., 1, Chebyshev smoothing, "
                  "a direct solve at degree 1): the memory of a few vectors, for high degrees.";
        }
      // In 3D a direct solve at the default degree needs more memory than a
      // workstation has; the matrix-free solver needs a few vectors.
      entries.choice("Type", solver.type,
                     dimension == ModelDimension::three ? Type::cg_multigrid : Type::direct, types, help);
      entries.number("Tolerance", solver.tolerance, 1e-9, interval("(]", 0, 1),
                     "Relative residual |A u - b|/|b| the iterative solver must reach; a direct solve that "
                     "misses it is an error too. Units: none.");
      entries.integer("Maximum iterations", solver.max_iterations, 10000u, 1u, 100000000u,
                      "Iteration limit of the iterative solver. Units: none.");
    });
  }
} // namespace penny
