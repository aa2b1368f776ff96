#include "input/json_xml_entries.h"

#include "input/input_error.h"

#include <deal.II/base/exceptions.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <vector>

namespace penny
{
  using dealii::ParameterHandler;

  namespace
  {
    // Far beyond any parameter file's subsections.
    constexpr unsigned int max_nesting = 1000;

    // deal.II writes names in XML (and may in JSON) with every character
    // other than a letter or digit as _XX, its code in hex. Anything else
    // (_00, _41: a control character, a letter) is not such a code and
    // stays as written, so an error message shows it.
    std::string demangled(const std::string &name)
    {
      std::string plain;
      for (std::size_t i = 0; i < name.size(); ++i)
        {
          const bool code = name[i] == '_' && i + 2 < name.size() &&
                            std::isxdigit(static_cast<unsigned char>(name[i + 1])) &&
                            std::isxdigit(static_cast<unsigned char>(name[i + 2]));
          const int c = code ? std::stoi(name.substr(i + 1, 2), nullptr, 16) : 0;
          if (code && std::isprint(c) && !std::isalnum(c))
            {
              plain += static_cast<char>(c);
              i += 2;
            }
          else
            plain += name[i];
        }
      return plain;
    }

    // An entry's value: the text of a leaf, or the 'value' of deal.II's own
    // format (which also records defaults and documentation).
    std::string value_of(const boost::property_tree::ptree &node)
    {
      return node.empty() ? node.data() : node.get<std::string>("value");
    }

    // The deepest nesting of a JSON file's objects and arrays, counted
    // before Boost's recursive parser, which a deep enough file overflows the
    // stack of. A null is refused: Boost reads it as the text "null".
    unsigned int json_depth(const std::string &text)
    {
      unsigned int depth = 0, deepest = 0;
      bool         in_string = false;
      for (std::size_t i = 0; i < text.size(); ++i)
        {
          const char c = text[i];
          if (in_string && c == '\\')
            ++i; // an escaped character
          else if (c == '"')
            in_string = !in_string;
          else if (!in_string && (c == '{' || c == '['))
            deepest = std::max(deepest, ++depth);
          else if (!in_string && (c == '}' || c == ']'))
            depth -= depth > 0;
          else if (!in_string && text.compare(i, 4, "null") == 0)
            throw InputError(
                "a null on line " + std::to_string(1 + std::count(text.begin(), text.begin() + i, '\n')) +
                ": a value is text (\"name\": \"value\"); leave an entry out to keep its default");
        }
      return deepest;
    }

    // The same for an XML file's elements: a start tag opens one (unless it
    // ends in '/>'), an end tag closes one; comments, CDATA and processing
    // instructions are skipped whole. A DOCTYPE is refused: Boost's reader
    // would leave the entities it declares unexpanded in the values.
    unsigned int xml_depth(const std::string &text)
    {
      unsigned int depth = 0, deepest = 0;
      std::size_t  i         = text.find('<');
      const auto   skip_past = [&](const std::string &end) {
        const std::size_t at = text.find(end, i + 1);
        return at == std::string::npos ? text.size() : at + end.size();
      };
      while (i != std::string::npos && i + 1 < text.size())
        {
          if (text.compare(i, 4, "<!--") == 0)
            i = skip_past("-->");
          else if (text.compare(i, 9, "<![CDATA[") == 0)
            i = skip_past("]]>");
          else if (text[i + 1] == '!')
            throw InputError("a DOCTYPE or other declaration (" + text.substr(i, 10) +
                             "...): its entities would not be expanded; write the values themselves");
          else if (text[i + 1] == '?')
            i = skip_past(">");
          else if (text[i + 1] == '/')
            {
              depth -= depth > 0;
              i = skip_past(">");
            }
          else
            {
              // The tag's end, past quoted attribute values.
              std::size_t end = i + 1;
              for (char quote = 0; end < text.size() && (quote || text[end] != '>'); ++end)
                if (quote ? text[end] == quote : (text[end] == '"' || text[end] == '\''))
                  quote = quote ? 0 : text[end];
              if (end < text.size() && text[end - 1] != '/')
                deepest = std::max(deepest, ++depth);
              i = end;
            }
          i = text.find('<', i);
        }
      return deepest;
    }

    // Every name and value is text without NUL, and no JSON array or XML
    // attribute stands where an entry or a subsection belongs.
    void check_tree(const boost::property_tree::ptree &node, const std::string &where)
    {
      const std::string here = where.empty() ? "at the top" : "in " + where;
      // Boost's XML reader keeps an element's attributes under this key.
      if (node.count("<xmlattr>"))
        throw InputError("an XML attribute " + here +
                         "; entries are elements <name>value</name>, subsections elements holding them");
      // deal.II's own format: of an entry's record only the value is read,
      // which is text; the record holds only what deal.II writes in it. The
      // top level is no record.
      const auto value = where.empty() ? boost::none : node.get_child_optional("value");
      if ((value ? value->data() : node.data()).find('\0') != std::string::npos)
        throw InputError(where.empty() ? "a NUL byte in the text at the top"
                                       : "a NUL byte in the value of " + where);
      if (value)
        {
          check_tree(*value, where + "/value");
          if (!value->empty())
            throw InputError("an element in the value of " + where);
          for (const auto &[key, child] : node)
            if (key != "value" && key != "default_value" && key != "documentation" && key != "pattern" &&
                key != "pattern_description" && key != "actions")
              throw InputError("'" + demangled(key) + "' in the entry record of " + where +
                               ": a record holds value, default_value, documentation, pattern, "
                               "pattern_description, actions");
          return;
        }
      for (const auto &[key, child] : node)
        {
          if (key.empty())
            throw InputError("an array " + here +
                             "; entries are \"name\": \"value\" pairs, subsections objects");
          if (key.find('\0') != std::string::npos)
            throw InputError("a NUL byte in a name " + here);
          check_tree(child, (where.empty() ? "" : where + "/") + demangled(key));
        }
    }

    void set_entries(ParameterHandler &prm, const boost::property_tree::ptree &node,
                     const std::vector<std::string> &path, const std::string &scene)
    {
      std::set<std::string> seen;
      for (const auto &[key, child] : node)
        {
          const std::string name = demangled(key);
          std::string       full;
          for (const std::string &subsection : path)
            full += subsection + "/";
          full += name;
          if (!seen.insert(name).second)
            throw InputError(full + " appears twice; set each entry once");
          std::vector<std::string> subsection_path = path;
          subsection_path.push_back(name);
          // Boost reads an empty subsection ({} or <Output/>) as an empty entry: it sets nothing.
          if (child.empty() && child.data().empty() && prm.subsection_path_exists(subsection_path))
            continue;
          if (!child.empty() && !child.get_child_optional("value"))
            {
              if (!prm.subsection_path_exists(subsection_path))
                throw InputError("subsection '" + full + "' is not read by Scene = " + scene +
                                 " ('penny --print-parameters " + scene + "' lists what it reads)");
              set_entries(prm, child, subsection_path, scene);
              continue;
            }
          const std::string value = value_of(child);
          for (const std::string &subsection : path)
            prm.enter_subsection(subsection);
          try
            {
              prm.set(name, value);
            }
          catch (const ParameterHandler::ExcEntryUndeclared &)
            {
              // A name with blanks at its ends is shown as written: it is not the entry it resembles.
              const bool blank_ends =
                  !name.empty() && (std::isblank(name.front()) || std::isblank(name.back()));
              throw InputError((blank_ends ? in_quotes(full) + " (a name with blanks at its ends)" : full) +
                               " is not an entry of Scene = " + scene + " ('penny --print-parameters " +
                               scene + "' lists them)");
            }
          catch (const dealii::ExceptionBase &exception)
            {
              const std::string text    = one_line(exception);
              const std::string choices = choices_in(text);
              throw InputError(full + " = " + in_quotes(value) +
                               (choices.empty() ? ": " + text : " is not one of " + choices));
            }
          for (std::size_t i = 0; i < path.size(); ++i)
            prm.leave_subsection();
        }
    }
  } // namespace

  boost::property_tree::ptree read_json_xml_tree(const std::string &filename, const bool json)
  {
    boost::property_tree::ptree tree;
    std::ifstream               in(filename);
    if (!in)
      throw InputError("parameter file " + in_quotes(filename) + " cannot be read");
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if ((json ? json_depth(text) : xml_depth(text)) > max_nesting)
      throw InputError("its objects or elements nest deeper than " + std::to_string(max_nesting) + " levels");
    const auto invalid = [&](const std::string &detail) {
      return InputError("parameter file " + in_quotes(filename) + " is not valid " + (json ? "JSON" : "XML") +
                        ": " + detail);
    };
    try
      {
        std::istringstream stream(text);
        if (json)
          boost::property_tree::read_json(stream, tree);
        else
          {
            boost::property_tree::read_xml(stream, tree, boost::property_tree::xml_parser::no_comments);
            // As deal.II's reader: one top-level element, ParameterHandler.
            if (tree.size() != 1 || tree.front().first != "ParameterHandler")
              throw InputError("parameter file " + in_quotes(filename) +
                               " is not one element <ParameterHandler> holding the entries");
            tree = tree.front().second;
          }
      }
    catch (const boost::property_tree::file_parser_error &error)
      {
        throw invalid("line " + std::to_string(error.line()) + ": " + one_line(error.message()));
      }
    catch (const boost::property_tree::ptree_error &error)
      {
        throw invalid(one_line(error.what()));
      }
    check_tree(tree, "");
    return tree;
  }

  std::optional<std::string> scene_of(const boost::property_tree::ptree &tree)
  {
    for (const auto &[key, child] : tree)
      if (demangled(key) == "Scene")
        {
          if (!child.empty() && !child.get_child_optional("value"))
            throw InputError("Scene holds entries, not a scene's name (\"Scene\": \"NAME\"; 'penny --help' "
                             "lists the scenes)");
          return value_of(child);
        }
    return std::nullopt;
  }

  void set_json_xml_entries(ParameterHandler &prm, const boost::property_tree::ptree &tree,
                            const std::string &scene)
  {
    set_entries(prm, tree, {}, scene);
  }
} // namespace penny
