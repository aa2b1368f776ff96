// The subsection every boundary-element scene reads: Contact solver, the
// tolerance and iteration limit of the contact solver (contact/half_space_contact.h).
#pragma once

#include "contact/half_space_contact.h"
#include "input/entries.h"

namespace penny
{
  // Contact solver: Tolerance (default `default_tolerance`, the scene's own)
  // and Maximum iterations.
  void contact_solver_section(Sections &sections, ContactSolverControl &control, double default_tolerance);
} // namespace penny
