#include "output_files.h"

#include "parameters.h"

#include <deal.II/base/mpi.h>

#include <fstream>
#include <unistd.h>

namespace penny
{
  void prepare_output_directory(const std::filesystem::path &directory)
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory) || access(directory.c_str(), W_OK) != 0)
      throw InputError("Output/Directory = '" + directory.string() + "' cannot be created or is not writable");
  }

  void write_atomically(const std::filesystem::path &file, const std::function<void(std::ostream &)> &write)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const std::filesystem::path partial = file.string() + ".partial";
    {
      std::ofstream out(partial);
      write(out);
      out.close();
      if (!out)
        throw std::runtime_error("output: could not write " + partial.string());
    }
    std::filesystem::rename(partial, file);
  }
} // namespace penny
