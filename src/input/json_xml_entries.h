// Parameter files in JSON or XML (deal.II's ParameterHandler reads both): a
// tree of subsections and entries. deal.II reads them without naming the
// entry whose value it rejects, and lets a repeated key win silently; here
// each entry is set on its own instead, so that an error names it.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/ptree.hpp>

#include <optional>
#include <string>

namespace penny
{
  // The tree of `filename`, JSON if `json`, else XML. Throws InputError (one
  // line) if it is not valid JSON or XML.
  boost::property_tree::ptree read_json_xml_tree(const std::string &filename, bool json);

  // The top-level 'Scene' entry of the tree, if it is set.
  std::optional<std::string> scene_of(const boost::property_tree::ptree &tree);

  // Sets every entry of the tree in `prm` (whose entries are declared), so
  // that a key set twice, an undeclared subsection or entry, or a value that
  // does not match its pattern is an InputError naming it. `scene` names the
  // scene whose subsections are declared.
  void set_json_xml_entries(dealii::ParameterHandler &prm, const boost::property_tree::ptree &tree,
                            const std::string &scene);
} // namespace penny
