// The subsections of every finite-element model's discretisation: the
// element degree ('Finite element') and the linear solver ('Linear solver').
#pragma once

#include "fe/linear_elastic_system.h"
#include "input/entries.h"

namespace penny
{
  // Finite element: the polynomial degree and, for the models that grade it
  // towards a crack tip (`levels_per_degree` not null), the Degree grading.
  void finite_element_section(Sections &sections, unsigned int &degree, unsigned int *levels_per_degree);

  void linear_solver_section(Sections &sections, LinearSolverParameters &linear_solver);
} // namespace penny
