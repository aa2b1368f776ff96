// deal.II's matrix-free templates, for a file compiled at this machine's SIMD
// width (penny_native_simd() in CMakeLists.txt): Debian's library holds them
// for one cell at a time only. Included by those files, after their other
// headers.
#pragma once

#include <deal.II/base/vectorization.h>

#include <deal.II/matrix_free/dof_info.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#include <deal.II/matrix_free/mapping_info.templates.h>
#include <deal.II/matrix_free/mapping_info_storage.templates.h>
#include <deal.II/matrix_free/matrix_free.templates.h>
#include <deal.II/matrix_free/shape_info.templates.h>
// deal.II 9.4's face factory shares the include guard of the cell factory.
#undef dealii_matrix_free_evaluation_template_factory_templates_h
#include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>
