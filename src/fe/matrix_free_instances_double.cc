// deal.II's MatrixFree for double at this machine's SIMD width
// (penny_native_simd() in CMakeLists.txt), instantiated once, here: Debian's
// library holds it for one cell at a time only. The files that use it see
// only its declarations, and so compile in seconds; the cell kernels are in
// cell_kernel_instances_double.cc, the twin for the other precision beside it.
#include <deal.II/matrix_free/dof_info.templates.h>
#include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#include <deal.II/matrix_free/mapping_info.templates.h>
#include <deal.II/matrix_free/mapping_info_storage.templates.h>
#include <deal.II/matrix_free/matrix_free.templates.h>
#include <deal.II/matrix_free/shape_info.templates.h>

namespace dealii
{
  template class MatrixFree<3, double>;
  template void MatrixFree<3, double>::internal_reinit<double, 3>(
      const std::shared_ptr<hp::MappingCollection<3>> &, const std::vector<const DoFHandler<3> *> &,
      const std::vector<const AffineConstraints<double> *> &, const std::vector<IndexSet> &,
      const std::vector<hp::QCollection<3>> &, const AdditionalData &);
  template struct internal::FEEvaluationHangingNodesFactory<3, double>;
  // The mapping's data on faces, which MatrixFree computes in double for
  // either precision (its face kernels are otherwise unused).
  template void internal::FEFaceEvaluationFactory<3, VectorizedArray<double>>::evaluate(
      unsigned int, EvaluationFlags::EvaluationFlags, const VectorizedArray<double> *,
      FEEvaluationData<3, VectorizedArray<double>, true> &);
} // namespace dealii
