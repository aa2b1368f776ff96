#include "fe/rigid_body_modes.h"

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <vector>

namespace penny
{
  using namespace dealii;

  Epetra_MultiVector rigid_body_modes(const DoFHandler<3>            &dof_handler,
                                      const hp::MappingCollection<3> &mapping, const Epetra_Map &rows)
  {
    const FiniteElement<3>              &fe    = dof_handler.get_fe(0); // one degree in 3D
    const IndexSet                      &owned = dof_handler.locally_owned_dofs();
    Epetra_MultiVector                   modes(rows, 6);
    const Quadrature<3>                  support_points(fe.get_unit_support_points());
    FEValues<3>                          fe_values(mapping[0], fe, support_points, update_quadrature_points);
    std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(local_dofs);
          for (unsigned int i = 0; i < local_dofs.size(); ++i)
            if (owned.is_element(local_dofs[i]))
              {
                const unsigned int row = owned.index_within_set(local_dofs[i]);
                const unsigned int c   = fe.system_to_component_index(i).first;
                const Point<3>    &x   = fe_values.quadrature_point(i);
                modes[c][row]          = 1;
                // Rotation about axis r: (e_r x x)_c = eps_crj x_j.
                modes[3 + (c + 1) % 3][row] = x[(c + 2) % 3];
                modes[3 + (c + 2) % 3][row] = -x[(c + 1) % 3];
              }
        }
    return modes;
  }
} // namespace penny
