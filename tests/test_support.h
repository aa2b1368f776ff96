// Shared set-up for the unit tests: a scene's parameters at their declared
// defaults, the penny-gap model at test size, and scratch folders.
#pragma once

#include "scenes/scene_registry.h"
#include "scenes/scene_support.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <filesystem>
#include <string>

// The parameters `scene` reads, at their declared defaults.
inline penny::Parameters default_parameters(const std::string &scene = "penny-gap")
{
  const penny::Scene      &entry = penny::find_scene(scene);
  dealii::ParameterHandler prm;
  penny::declare_scene(prm, entry);
  return penny::Parameters::parse(prm, entry.sections);
}

// The default penny-gap model with tip cells c/2^tip_levels wide.
inline penny::PennyGapModelParameters test_size_model(const unsigned int tip_levels,
                                                      const unsigned int degree)
{
  penny::PennyGapModelParameters model = penny::penny_gap_model(default_parameters());
  model.mesh.tip_levels                = tip_levels;
  model.degree                         = degree;
  return model;
}

// A fresh folder in the temporary directory, the same on every MPI rank,
// removed with its contents at the end of the scope.
class ScratchFolder
{
public:
  ScratchFolder()
  {
    std::string name;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        name = (std::filesystem::temp_directory_path() / "penny-test-XXXXXX").string();
        if (!mkdtemp(name.data()))
          throw std::runtime_error("cannot create a scratch folder");
      }
    path = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, name, 0);
  }
  ScratchFolder(const ScratchFolder &) = delete;
  ~ScratchFolder()
  {
    MPI_Barrier(MPI_COMM_WORLD);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::remove_all(path);
  }

  std::filesystem::path path;
};
