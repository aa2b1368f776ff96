// The near-null space of 3D elasticity from which Trilinos' algebraic
// multigrid (ML's smoothed aggregation) builds its coarse spaces: the six
// rigid-body motions, three translations and three rotations.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>

#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>

namespace penny
{
  // The translations e_i and the rotations e_i x x at the support points of
  // the locally owned degrees of freedom, in the row order of the matrix.
  Epetra_MultiVector rigid_body_modes(const dealii::DoFHandler<3>            &dof_handler,
                                      const dealii::hp::MappingCollection<3> &mapping,
                                      const Epetra_Map                       &rows);
} // namespace penny
