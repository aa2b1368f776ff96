#include "input/parameter_file.h"

#include "input/input_error.h"
#include "input/json_xml_entries.h"
#include "input/prm_statements.h"

#include <deal.II/base/exceptions.h>

#include <boost/algorithm/string/case_conv.hpp>

#include <filesystem>
#include <regex>
#include <typeinfo>

namespace penny
{
  using dealii::ParameterHandler;

  ParameterFile read_parameter_file(const std::string &filename)
  {
    if (!std::filesystem::is_regular_file(filename))
      throw InputError("parameter file " + in_quotes(filename) + " does not exist or is not a file");
    // Of any case, as deal.II reads it.
    const std::string extension =
        boost::algorithm::to_lower_copy(std::filesystem::path(filename).extension().string());
    ParameterFile file{filename, "", {filename}, {}, {}};
    bool          sets_any = false;
    if (extension == ".prm")
      {
        file.statements = scan_prm_statements(filename);
        file.files      = file.statements.files;
        file.scene      = file.statements.scene;
        sets_any        = file.statements.sets_any;
      }
    else if (extension == ".json" || extension == ".xml")
      {
        file.tree  = read_json_xml_tree(filename, extension == ".json");
        file.scene = scene_of(file.tree);
        sets_any   = !file.tree.empty();
      }
    else
      throw InputError("parameter file " + in_quotes(filename) + " is neither .prm, .json nor .xml");
    // An empty file would run the default scene unasked.
    if (!sets_any)
      throw InputError("parameter file " + in_quotes(filename) +
                       " sets no parameter (add 'set Scene = NAME'; 'penny --help' lists the scenes)");
    return file;
  }

  void parse_parameter_file(ParameterHandler &prm, const ParameterFile &file, const std::string &scene)
  {
    // A JSON or XML file's entries are set one by one (input/json_xml_entries.h).
    if (!file.tree.empty())
      {
        set_json_xml_entries(prm, file.tree, scene);
        return;
      }
    try
      {
        prm.parse_input(file.filename);
      }
    catch (const dealii::ExceptionBase &exception)
      {
        std::string message = one_line(exception);
        // The scene as the messages below name it.
        const std::string which =
            "Scene = " + scene + (file.scene ? "" : ", the default, as the file sets no Scene");
        std::smatch match;
        // The set statement at the line and file of `match` ([1] and [2]):
        // where it is, as messages name it, and its "Subsection/Name"; none
        // if deal.II names a line the scan did not see as one.
        const auto statement = [&]() -> const std::pair<std::string, std::string> * {
          const auto found = file.statements.set_statements.find(
              {std::filesystem::weakly_canonical(match[2].str()).string(), std::stoul(match[1].str())});
          return found == file.statements.set_statements.end() ? nullptr : &found->second;
        };
        // With only the scene's subsections declared, any other subsection
        // is one the scene does not read.
        if (typeid(exception) == typeid(ParameterHandler::ExcNoSubsection) &&
            std::regex_search(message, match,
                              std::regex("Line <([0-9]+)> of file <(.*): There is no such subsection to be "
                                         "entered: (.*)$")))
          {
            // An included file is named, as the scan names its lines; deal.II joins the path with dots.
            const bool included = std::filesystem::weakly_canonical(match[2].str()) !=
                                  std::filesystem::weakly_canonical(file.filename);
            message = (included ? in_quotes(match[2].str()) + ", " : "") + "line " + match[1].str() +
                      ": subsection '" + std::regex_replace(match[3].str(), std::regex("\\."), "/") +
                      "' is not read by " + which + " ('penny --print-parameters " + scene +
                      "' lists what it reads)";
          }
        // A value outside a choice (Selection or Bool), named with its subsection, the choices listed.
        else if (std::regex_search(
                     message, match,
                     std::regex("Line <([0-9]+)> of file <(.*)>: The entry value ?(.*) for the entry "
                                "named .* does not match the given pattern: \\[(Selection .* |Bool)\\]$")))
          {
            if (const auto set = statement())
              message = set->first + ": " + set->second + " = " + in_quotes(match[3].str()) +
                        " is not one of " + choices_in(message);
          }
        // An entry the scene does not declare, named with its subsection.
        else if (std::regex_search(message, match,
                                   std::regex("Line <([0-9]+)> of file <(.*)>: No entry with name <.*> was "
                                              "declared in the current subsection")))
          {
            if (const auto set = statement())
              message = set->first + ": " + set->second + " is not an entry of " + which +
                        " ('penny --print-parameters " + scene + "' lists them)";
          }
        throw InputError(message);
      }
  }
} // namespace penny
