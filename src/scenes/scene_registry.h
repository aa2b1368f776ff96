// Every scene penny runs, in one table: its name, a one-line description, the
// parameter sections it reads and its entry point. The 'Scene' selection,
// --help, --print-parameters and the dispatch all come from it.
#pragma once

#include "input/parameters.h"
#include "output/result_folder.h"
#include "scenes/scene_support.h"

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  struct Scene
  {
    std::string                                                                      name;
    std::string                                                                      description;
    std::vector<Section>                                                             sections;
    std::function<Verdict(const Parameters &, const ResultFolder &, std::ostream &)> run;
  };

  // The first scene is the default.
  const std::vector<Scene> &scene_registry();

  // Throws InputError for a name that is not in the registry.
  const Scene &find_scene(const std::string &name);

  // The 'Scene' entry and the sections `scene` reads.
  void declare_scene(dealii::ParameterHandler &prm, const Scene &scene);

  // A parameter file read in two passes: the 'Scene' entry (with every section
  // declared, so that an unknown entry or bad value is reported as such), then
  // only the sections that scene reads; any other subsection is an error.
  struct SceneFile
  {
    const Scene *scene;
    Parameters   parameters;
    std::string  used_parameters; // the parameters of the run, as a .prm file
    // Every file the run reads: parameter files (the scene file and those it
    // includes), a mesh, a spectrum. Replacing the output folder must not remove one.
    std::vector<std::filesystem::path> input_files;
  };
  SceneFile read_scene_file(const std::string &filename);

  // Reads the file, says which scene runs, runs it, moves the results into
  // place and says where they went.
  Verdict run_scene_file(const std::string &filename, std::ostream &log);
} // namespace penny
