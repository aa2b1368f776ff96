// The subsections every finite-element model reads besides its geometry and
// mesh: the solid (Material), the element degree (Finite element) and the
// linear solver (Linear solver).
#pragma once

#include "fe/linear_elastic_system.h"
#include "input/entries.h"

namespace penny
{
  // Material, Finite element (with its Degree grading for the models that
  // grade the degree towards a crack tip) and Linear solver.
  void elastic_model_sections(Sections &sections, ElasticModelParameters &model, bool graded_degree);
} // namespace penny
