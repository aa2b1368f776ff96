// VTU files written like every other result: each MPI rank formats the cells
// it owns, rank 0 gathers the pieces into one file and writes it, checked,
// into the result folder, with a PVD record beside it for ParaView.
#pragma once

#include "output/result_folder.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>

#include <sstream>
#include <string>
#include <vector>

namespace penny
{
  // A DataOut that hands out one rank's piece of a VTU file: its cells,
  // between the header and the footer.
  template <int dim> class VtuPieces : public dealii::DataOut<dim>
  {
  public:
    std::string piece(const dealii::DataOutBase::VtkFlags &flags) const
    {
      std::ostringstream out;
      dealii::DataOutBase::write_vtu_main(this->get_patches(), this->get_dataset_names(),
                                          this->get_nonscalar_data_ranges(), flags, out);
      return out.str();
    }
  };

  // NAME.vtu and NAME.pvd from the patches every rank has built. Collective.
  // The data is compressed by zlib's fastest level: deal.II's default, the
  // smallest files, took longer than the solve (penny-uniform: 0.5 of 0.8 s).
  template <int dim>
  void write_vtu(const VtuPieces<dim> &data_out, const std::string &name, dealii::DataOutBase::VtkFlags flags,
                 const ResultFolder &results, const MPI_Comm comm)
  {
    flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
    const std::vector<std::string> pieces = dealii::Utilities::MPI::gather(comm, data_out.piece(flags), 0);
    std::ostringstream             vtu;
    dealii::DataOutBase::write_vtu_header(vtu, flags);
    for (const std::string &piece : pieces)
      vtu << piece;
    dealii::DataOutBase::write_vtu_footer(vtu);
    results.write(name + ".vtu", vtu.str());
    std::ostringstream pvd;
    dealii::DataOutBase::write_pvd_record(pvd, {{0., name + ".vtu"}});
    results.write(name + ".pvd", pvd.str());
  }
} // namespace penny
