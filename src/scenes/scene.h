// A scene: one question put to the models, answered in tables and a verdict.
// Each scene is a class in a file of its own under src/scenes/ that lists the
// subsections it reads, runs, writes its tables and judges its results; the
// file registers it with PENNY_REGISTER_SCENE (in the spirit of ASPECT's
// plugins), and the registry builds 'Scene', --help, --print-parameters and
// the dispatch from those registrations alone.
#pragma once

#include "input/entries.h"
#include "output/result_folder.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  // A scene's judgement of its own results: a failed check is reported after
  // the results are written, and makes the run exit non-zero. A scene without
  // a check passes with an empty message.
  struct Verdict
  {
    bool        passed = true;
    std::string message;
  };

  class Scene
  {
  public:
    virtual ~Scene() = default;

    // What the scene reads, into its own members: the entries of its own
    // subsection (named by its registration; none if that name is empty),
    // then the subsections it shares with other scenes (a model's input,
    // Fields, ...) with the checks across them. Each is called once to declare
    // the entries and, once the file is parsed, to read them, in that order.
    virtual void entries(Entries &) {}
    virtual void inputs(Sections &) {}

    // Computes, prints to `log` and writes its tables into `results`.
    virtual Verdict run(const ResultFolder &results, std::ostream &log) = 0;

    // What the scene's verdict measures, as its registration names it (empty
    // for a scene without one), and the largest value that passes: the
    // entry Verification/Tolerance, which the registry lists for it.
    std::string measure;
    double      tolerance = 0;

  protected:
    // PASS when `error`, the measure, is within the tolerance.
    Verdict verdict(double error) const;
  };

  struct SceneType
  {
    std::string                             name;
    std::string                             section;     // the scene's own subsection; empty: none
    std::string                             description; // one line: what the run computes
    std::string                             measure;     // what its verdict measures; empty: none
    std::function<std::unique_ptr<Scene>()> create;
  };

  // Adds a scene type to the registry; returns true (for a static initialiser).
  bool register_scene(SceneType type);

  // Every registered scene, by name.
  const std::vector<SceneType> &scene_types();

  // Throws InputError for a name that is not registered.
  const SceneType &find_scene(const std::string &name);

  // The scene a parameter file runs when it does not set 'Scene'.
  constexpr const char *default_scene = "penny-gap";

  // The entries `type` reads, with their defaults and documentation, as a .prm file.
  void print_parameters(const SceneType &type, std::ostream &out);

  // A parameter file read into its scene, ready to run.
  struct SceneFile
  {
    const SceneType       *type;
    std::unique_ptr<Scene> scene;
    std::string            output_directory;
    std::string            used_parameters; // the parameters of the run, as a .prm file
    // Every file the run reads: parameter files (the scene file and those it
    // includes), a mesh, a spectrum. Replacing the output folder must not remove one.
    std::vector<std::filesystem::path> input_files;
  };

  // Reads the file in two steps (input/parameter_file.h): its 'Scene'
  // entry, then the subsections that scene reads. Throws InputError (one
  // line) for any problem.
  SceneFile read_scene_file(const std::string &filename);

  // Reads the file, says which scene runs, runs it, moves the results into
  // place and says where they went.
  Verdict run_scene_file(const std::string &filename, std::ostream &log);

  // Fields/Write fields, of the scenes that can write their fields for ParaView.
  void fields_section(Sections &sections, bool &write_fields);
} // namespace penny

// Registers the Scene subclass `Class` under `name`, its own entries in the
// subsection `section` (empty: none), its verdict held to
// Verification/Tolerance on `measure` (empty: no verdict); used once, at the
// end of the scene's file.
#define PENNY_REGISTER_SCENE(Class, name, section, description, measure)                                     \
  namespace                                                                                                  \
  {                                                                                                          \
    const bool registered_##Class = ::penny::register_scene(                                                 \
        {name, section, description, measure,                                                                \
         []() -> std::unique_ptr<::penny::Scene> { return std::make_unique<Class>(); }});                    \
  }
