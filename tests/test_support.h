// Shared set-up for the unit tests: the models at the defaults of their
// parameter entries and at test size, and scratch folders.
#pragma once

#include "fe/elliptical_gap_mesh.h"
#include "problems/penny_gap.h"
#include "problems/periodic_gap.h"
#include "scenes/scene.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

// The penny-gap model at the defaults of its entries.
inline penny::PennyGapModelParameters default_penny_gap_model()
{
  return penny::default_values<penny::PennyGapModelParameters>(penny::penny_gap_model_sections);
}

// The default penny-gap model with tip cells c/2^tip_levels wide.
inline penny::PennyGapModelParameters test_size_model(const unsigned int tip_levels,
                                                      const unsigned int degree)
{
  penny::PennyGapModelParameters model = default_penny_gap_model();
  model.mesh.tip_levels                = tip_levels;
  model.degree                         = degree;
  return model;
}

// The face load at the defaults of its entries.
inline penny::LoadParameters default_load()
{
  const auto geometry = default_penny_gap_model().geometry;
  return penny::default_values<penny::LoadParameters>(
      [&](penny::Sections &sections, penny::LoadParameters &load) {
        penny::face_load_section(sections, load, geometry);
      });
}

// The periodic-gap model at the defaults of its entries, and its J-integral rings.
inline penny::PeriodicGapInput default_periodic_gap()
{
  return penny::default_values<penny::PeriodicGapInput>(
      [](penny::Sections &sections, penny::PeriodicGapInput &periodic) { periodic.sections(sections); });
}

// A small elliptical-gap mesh (a = 2): 4 cells along the front, 8 sectors,
// 4 rings.
inline penny::EllipticalGapMeshParameters small_elliptical_mesh(const double b_over_a)
{
  penny::EllipticalGapMeshParameters p;
  p.semi_axis_a        = 2;
  p.semi_axis_b        = 2 * b_over_a;
  p.domain_width       = 6;
  p.domain_height      = 5;
  p.cells_along_front  = 4;
  p.cells_around_front = 8;
  p.front_cell_size    = 0.025;
  p.ring_ratio         = 2;
  return p;
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

// Runs the scene of the parameter file `text`, written into `folder`, with
// its results committed to folder/results; returns its verdict.
inline penny::Verdict run_scene_text(const std::string &text, const std::filesystem::path &folder)
{
  const auto prm = folder / "scene.prm";
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream(prm) << text;
  MPI_Barrier(MPI_COMM_WORLD);
  const penny::SceneFile file = penny::read_scene_file(prm.string());
  penny::ResultFolder    results(folder / "results", file.input_files);
  std::ostringstream     log;
  const penny::Verdict   verdict = file.scene->run(results, log);
  results.commit();
  return verdict;
}
