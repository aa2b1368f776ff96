#include "problems/contact_solver.h"

namespace penny
{
  void contact_solver_section(Sections &sections, ContactSolverControl &control,
                              const double default_tolerance)
  {
    sections.subsection("Contact solver", [&](Entries &entries) {
      entries.number("Tolerance", control.tolerance, default_tolerance, interval("[]", 1e-14, 1e-4),
                     "Residual of the bound-constrained CG: the displacement the unbalanced traction of the "
                     "free points would cause there, rms over the grid, in units of the rms height. Units: "
                     "none.");
      entries.integer("Maximum iterations", control.max_iterations, 100000u, 1u, 100000000u,
                      "Iteration limit of one solve; reaching it is an error. Units: none.");
    });
  }
} // namespace penny
