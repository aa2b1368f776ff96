#include "scenes/scene.h"

#include "input/input_error.h"
#include "input/parameter_file.h"
#include "numerics/solver_failure.h"

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

namespace penny
{
  using dealii::ParameterHandler;

  namespace
  {
    std::vector<SceneType> &registry()
    {
      static std::vector<SceneType> types;
      return types;
    }

    // A scene of `type`, its verdict's measure set.
    std::unique_ptr<Scene> create(const SceneType &type)
    {
      std::unique_ptr<Scene> scene = type.create();
      scene->measure               = type.measure;
      return scene;
    }

    // The subsections of `scene` of `type`, its tolerance and the output
    // folder, declared or read.
    void list_parameters(Sections &sections, const SceneType &type, Scene &scene,
                         std::string &output_directory)
    {
      if (!type.section.empty())
        sections.subsection(type.section, [&](Entries &entries) { scene.entries(entries); });
      scene.inputs(sections);
      if (!scene.measure.empty())
        sections.subsection("Verification", [&](Entries &entries) {
          entries.number(
              "Tolerance", scene.tolerance, 1e-6, above(0),
              "The run passes when the " + scene.measure +
                  " is at most this; otherwise it prints FAIL and exits with status 1. Units: none.");
        });
      sections.subsection("Output", [&](Entries &entries) {
        entries.text("Directory", output_directory, "output",
                     "Folder for results, replaced whole by each run; created if missing (relative to the "
                     "working folder).");
      });
    }

    // The 'Scene' entry, then the subsections.
    void declare(ParameterHandler &prm, const SceneType &type, Scene &scene, std::string &output_directory)
    {
      std::string names, documentation = "What the run computes:";
      for (const SceneType &other : scene_types())
        {
          names += (names.empty() ? "" : "|") + other.name;
          documentation += " " + other.name + ": " + other.description + ".";
        }
      prm.declare_entry("Scene", type.name, dealii::Patterns::Selection(names), documentation);
      Sections sections(prm, false);
      list_parameters(sections, type, scene, output_directory);
    }
  } // namespace

  Verdict Scene::verdict(const double error) const
  {
    std::ostringstream message;
    message.precision(2);
    message << std::scientific << measure << ' ' << error << (error <= tolerance ? " <= " : " > ")
            << "Verification/Tolerance = " << tolerance;
    return {error <= tolerance, message.str()};
  }

  bool register_scene(SceneType type)
  {
    auto &types = registry();
    auto  place = types.begin();
    while (place != types.end() && place->name < type.name)
      ++place;
    if (place != types.end() && place->name == type.name)
      throw std::logic_error("two scenes are named " + type.name);
    types.insert(place, std::move(type));
    return true;
  }

  const std::vector<SceneType> &scene_types()
  {
    return registry();
  }

  const SceneType &find_scene(const std::string &name)
  {
    for (const SceneType &type : scene_types())
      if (type.name == name)
        return type;
    throw InputError("Scene = " + in_quotes(name) + " is not a scene (penny --help lists them)");
  }

  void print_parameters(const SceneType &type, std::ostream &out)
  {
    const std::unique_ptr<Scene> scene = create(type);
    std::string                  output_directory;
    ParameterHandler             prm;
    declare(prm, type, *scene, output_directory);
    prm.print_parameters(out, ParameterHandler::PRM);
  }

  SceneFile read_scene_file(const std::string &filename)
  {
    const ParameterFile file = read_parameter_file(filename);
    const SceneType    &type = find_scene(file.scene.value_or(default_scene));
    SceneFile           scene{&type, create(type), "", "", {file.files.begin(), file.files.end()}};
    ParameterHandler    prm;
    declare(prm, type, *scene.scene, scene.output_directory);
    parse_parameter_file(prm, file, type.name);
    Sections sections(prm, true, std::filesystem::path(filename).parent_path().string());
    list_parameters(sections, type, *scene.scene, scene.output_directory);
    for (const std::string &input : sections.input_files())
      scene.input_files.emplace_back(input);
    std::ostringstream used;
    prm.print_parameters(used, ParameterHandler::PRM);
    scene.used_parameters = used.str();
    return scene;
  }

  // The output folder is checked (and locked) before the scene runs, and the
  // parameters are recorded last: a run that fails leaves the previous
  // results as they were. Replacing the folder must not remove an input.
  Verdict run_scene_file(const std::string &filename, std::ostream &log)
  {
    const SceneFile  file = read_scene_file(filename);
    const SceneType &type = *file.type;
    log << "penny: scene " << type.name << " (" << filename << "): " << type.description << "\n\n";
    std::optional<ResultFolder> results;
    try
      {
        results.emplace(file.output_directory, file.input_files);
      }
    catch (const InputError &error)
      {
        throw InputError("Output/Directory = " + std::string(error.what()));
      }
    Verdict verdict;
    try
      {
        verdict = file.scene->run(*results, log);
      }
    catch (const SolverFailure &failure)
      {
        throw std::runtime_error(std::string(failure.what()) + " (" + failure.settings + ")");
      }
    results->write("parameters.prm", file.used_parameters);
    results->commit();

    std::set<std::string> files;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      for (const auto &entry : std::filesystem::directory_iterator(results->directory()))
        if (entry.path().filename().string().front() != '.')
          files.insert(entry.path().filename().string());
    log << "\nResults in " << results->directory().string() << "/:";
    for (const auto &name : files)
      log << ' ' << name;
    log << '\n';
    return verdict;
  }

  void fields_section(Sections &sections, bool &write_fields)
  {
    sections.subsection("Fields", [&](Entries &entries) {
      entries.flag("Write fields", write_fields, true, "Write VTU files with a PVD record for ParaView.");
    });
  }
} // namespace penny
