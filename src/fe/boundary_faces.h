// The loop over the locally owned cell faces on one boundary, written once:
// the load vector, the gap volume and the loaded-face term of the J-integral
// all integrate over the gap face.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

namespace penny
{
  // Calls f(cell, fe_face) with the values of `hp_face` reinitialised on
  // every locally owned face on boundary `id`, with the cell's element.
  template <int dim, typename F>
  void for_each_boundary_face(const dealii::DoFHandler<dim> &dof_handler, const dealii::types::boundary_id id,
                              dealii::hp::FEFaceValues<dim> &hp_face, F &&f)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == id)
            {
              hp_face.reinit(cell, face);
              f(cell, hp_face.get_present_fe_values());
            }
  }
} // namespace penny
