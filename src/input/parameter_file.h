// A parameter file (.prm, .json or .xml), read in two steps: first what
// deal.II's reader does not check, and the 'Scene' entry, which decides the
// subsections to declare; then, with those declared, the values themselves.
#pragma once

#include "input/prm_statements.h"

#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/ptree.hpp>

#include <optional>
#include <string>
#include <vector>

namespace penny
{
  struct ParameterFile
  {
    std::string                 filename;
    std::optional<std::string>  scene;      // the 'Scene' entry, if the file sets it
    std::vector<std::string>    files;      // the file and every file it includes
    boost::property_tree::ptree tree;       // a JSON or XML file's entries
    PrmStatements               statements; // a .prm file's set statements
  };

  // Throws InputError (one line) for a file that is missing, of another kind,
  // malformed (input/prm_statements.h, input/json_xml_entries.h) or empty.
  ParameterFile read_parameter_file(const std::string &filename);

  // Parses the file into `prm`, in which the 'Scene' entry and the scene's
  // subsections are declared. Throws InputError (one line) for any problem,
  // naming the line of a subsection the scene does not read.
  void parse_parameter_file(dealii::ParameterHandler &prm, const ParameterFile &file,
                            const std::string &scene);
} // namespace penny
