// deal.II's sum-factorisation kernels of FEEvaluation for float at this
// machine's SIMD width, for every degree its factory dispatches to (1 to 6,
// and the generic one above), instantiated once, here (see
// matrix_free_instances_float.cc): the heaviest file of the build, so each
// precision has its own, and the two compile in parallel.
#include <deal.II/matrix_free/evaluation_template_factory.templates.h>

namespace dealii::internal
{
  template struct FEEvaluationFactory<3, VectorizedArray<float>>;
} // namespace dealii::internal
