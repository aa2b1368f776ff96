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

  void CohesiveZones::entries(Entries &entries, const std::string &unit, const CohesiveZones &defaults,
                              const std::size_t min_zones, const Range &range,
                              const std::string &documentation)
  {
    entries.decreasing_numbers("Cohesive zones l_pz/" + unit, lengths, defaults.lengths, min_zones, range,
                               "l_pz = E* rho^2/(pi w) of the exponential law, in units of " + documentation +
                                   " Units: " + unit + ".");
    entries.number("Points per cohesive zone", points_per_zone, defaults.points_per_zone,
                   interval("[]", HalfSpaceContact::min_process_zone_points, 100),
                   "Grid points over l_pz: the grid refines with the zone, and its error goes with the "
                   "extrapolation to the JKR limit. Units: none.");
  }
} // namespace penny
