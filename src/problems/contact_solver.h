// What the boundary-element scenes read: the subsection Contact solver, the
// tolerance and iteration limit of the contact solver
// (contact/half_space_contact.h), and the cohesive zones of the scenes that
// extrapolate to the JKR limit.
#pragma once

#include "contact/half_space_contact.h"
#include "input/entries.h"

#include <string>
#include <vector>

namespace penny
{
  // Contact solver: Tolerance (default `default_tolerance`, the scene's own)
  // and Maximum iterations.
  void contact_solver_section(Sections &sections, ContactSolverControl &control, double default_tolerance);

  // The cohesive zones of a scene's own subsection: 'Cohesive zones
  // l_pz/UNIT', the lengths l_pz = E* rho^2/(pi w) of the exponential law in
  // units of `unit` (at least `min_zones`, decreasing, in `range`, the JKR
  // limit extrapolated through them as `documentation` says), and 'Points
  // per cohesive zone', the grid points over l_pz.
  struct CohesiveZones
  {
    std::vector<double> lengths; // l_pz/unit
    double              points_per_zone;

    void entries(Entries &entries, const std::string &unit, const CohesiveZones &defaults,
                 std::size_t min_zones, const Range &range, const std::string &documentation);
  };
} // namespace penny
