// Small helpers every parameter subsection uses: a Selection entry backed by
// an enum (one table of names serves the pattern, the parsing and the
// printing), and lists of numbers.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace penny
{
  template <typename Enum> using EnumNames = std::vector<std::pair<std::string, Enum>>;

  // "a|b|c": the pattern of a Selection entry.
  template <typename Enum> dealii::Patterns::Selection selection(const EnumNames<Enum> &names)
  {
    std::string pattern;
    for (const auto &[name, value] : names)
      pattern += (pattern.empty() ? "" : "|") + name;
    return dealii::Patterns::Selection(pattern);
  }

  // The value a name stands for; the name has passed its Selection pattern.
  template <typename Enum> Enum to_enum(const EnumNames<Enum> &names, const std::string &name)
  {
    for (const auto &[candidate, value] : names)
      if (candidate == name)
        return value;
    throw std::logic_error("'" + name + "' is not a name of this selection");
  }

  template <typename Enum> const std::string &to_name(const EnumNames<Enum> &names, const Enum value)
  {
    for (const auto &[name, candidate] : names)
      if (candidate == value)
        return name;
    throw std::logic_error("no name for this enum value");
  }

  // The comma-separated list of numbers in `entry` of the current subsection.
  std::vector<double> get_doubles(const dealii::ParameterHandler &prm, const std::string &entry);
} // namespace penny
