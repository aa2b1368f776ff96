// The subsections every finite-element model reads besides its geometry and
// mesh: the solid (Material), the element degree (Finite element) and the
// linear solver (Linear solver).
#pragma once

#include "fe/linear_elastic_system.h"
#include "input/entries.h"

namespace penny
{
  // Material, Finite element and Linear solver. The 2D models grade the
  // degree towards a crack tip (Degree grading); the 3D models keep one
  // degree and may solve without a matrix (Type = cg-multigrid).
  enum class ModelDimension
  {
    two,
    three
  };
  void elastic_model_sections(Sections &sections, ElasticModelParameters &model, ModelDimension dimension);
} // namespace penny
