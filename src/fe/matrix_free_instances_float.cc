// deal.II's MatrixFree for float at this machine's SIMD width
// (penny_native_simd() in CMakeLists.txt), instantiated once, here: Debian's
// library holds it for one cell at a time only. The files that use it see
// only its declarations, and so compile in seconds; the cell kernels are in
// cell_kernel_instances_float.cc, the twin for the other precision beside it.
#include <deal.II/matrix_free/dof_info.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#include <deal.II/matrix_free/mapping_info.templates.h>
#include <deal.II/matrix_free/mapping_info_storage.templates.h>
#include <deal.II/matrix_free/matrix_free.templates.h>
#include <deal.II/matrix_free/shape_info.templates.h>

namespace dealii
{
  template class MatrixFree<3, float>;
  template void MatrixFree<3, float>::internal_reinit<float, 3>(
      const std::shared_ptr<hp::MappingCollection<3>> &, const std::vector<const DoFHandler<3> *> &,
      const std::vector<const AffineConstraints<float> *> &, const std::vector<IndexSet> &,
      const std::vector<hp::QCollection<3>> &, const AdditionalData &);
  template struct internal::FEEvaluationHangingNodesFactory<3, float>;
} // namespace dealii
