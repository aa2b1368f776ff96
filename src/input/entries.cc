#include "input/entries.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>

namespace penny
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  namespace
  {
    // An end of an interval as a reader writes it: inf, 0.5, 1e30, 1e-8.
    std::string end_text(const double x)
    {
      if (std::isinf(x))
        return x < 0 ? "-inf" : "inf";
      std::string       text = shortest(x);
      const std::size_t e    = text.find('e');
      if (e == std::string::npos)
        return text;
      std::string exponent = text.substr(e + 1);
      const bool  negative = exponent[0] == '-';
      exponent             = exponent.substr(exponent[0] == '-' || exponent[0] == '+' ? 1 : 0);
      exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
      return text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
    }

    // The documentation as printed: what the entry is, then what it allows.
    std::string documented(const std::string &documentation, const std::string &range)
    {
      return documentation + (range.empty() ? "" : " Allowed: " + range + ".");
    }

    // The error for a text that gives no double: a word, or a number no
    // double holds (a denormal, an overflow), which is outside the range.
    InputError no_number(const std::string &name, const std::string &text, const std::string &range)
    {
      char *end = nullptr;
      std::strtod(text.c_str(), &end);
      const bool number = !text.empty() && *end == '\0';
      return InputError(name + " = " + in_quotes(text) + (number ? " is outside" : " is not a number in") +
                        " the allowed range " + range);
    }

    // deal.II reads numbers with strtod, which also takes hexadecimal ones
    // ("0x10", "0x1p-6"): a parameter file means decimals.
    void require_decimal(const std::string &name, const std::string &text, const std::string &range)
    {
      if (text.find_first_of("xX") != std::string::npos)
        throw InputError(name + " = " + in_quotes(text) + " is not a decimal number in the allowed range " +
                         range);
    }

    std::string joined(const std::vector<std::string> &items, const std::string &separator)
    {
      std::string text;
      for (const std::string &item : items)
        text += (text.empty() ? "" : separator) + item;
      return text;
    }
  } // namespace

  Range interval(const std::string &brackets, const double lo, const double hi, const std::string &unit)
  {
    if (brackets.size() != 2 || std::string("[(").find(brackets[0]) == std::string::npos ||
        std::string("])").find(brackets[1]) == std::string::npos)
      throw std::logic_error("interval: brackets must be one of [], [), (], ()");
    const bool lo_open = brackets[0] == '(', hi_open = brackets[1] == ')';
    return {brackets.substr(0, 1) + end_text(lo) + ", " + end_text(hi) + brackets.substr(1) +
                (unit.empty() ? "" : " " + unit),
            [=](const double x) { return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi); }};
  }

  Range above(const double lo, const std::string &unit)
  {
    return interval("()", lo, std::numeric_limits<double>::infinity(), unit);
  }

  Range at_least(const double lo, const std::string &unit)
  {
    return interval("[)", lo, std::numeric_limits<double>::infinity(), unit);
  }

  Range magnitude(const std::string &unit)
  {
    return {"[1e-30, 1e30] " + unit,
            [](const double x) { return x >= smallest_magnitude && x <= largest_magnitude; }};
  }

  Range signed_magnitude(const std::string &unit)
  {
    return {"0 or |x| in [1e-30, 1e30] " + unit, [](const double x) {
              return x == 0 || (std::abs(x) >= smallest_magnitude && std::abs(x) <= largest_magnitude);
            }};
  }

  Entries::Entries(ParameterHandler &prm, std::string subsection, const bool reading,
                   const std::string &folder)
      : prm(prm), subsection(std::move(subsection)), reading_(reading), folder(folder)
  {
  }

  void Entries::number(const std::string &entry, double &value, const double default_value,
                       const Range &range, const std::string &documentation)
  {
    if (!reading_)
      {
        prm.declare_entry(entry, shortest(default_value), Patterns::Anything(),
                          documented(documentation, range.text));
        return;
      }
    require_decimal(name(entry), prm.get(entry), range.text);
    try
      {
        value = prm.get_double(entry);
      }
    catch (const dealii::ExceptionBase &)
      {
        throw no_number(name(entry), prm.get(entry), range.text);
      }
    require(range.contains(value), entry, value, range.text);
  }

  void Entries::integer_entry(const std::string &entry, long long &value, const long long default_value,
                              const long long lo, const long long hi, const std::string &documentation)
  {
    const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!reading_)
      {
        prm.declare_entry(entry, std::to_string(default_value), Patterns::Anything(),
                          documented(documentation, range));
        return;
      }
    // Read as a 64-bit integer here: deal.II's get_integer goes through int
    // and would wrap 2^32 + 2 to 2.
    const std::string text  = prm.get(entry);
    const char       *first = text.c_str();
    while (std::isspace(static_cast<unsigned char>(*first)))
      ++first;
    const char *last = text.c_str() + text.size();
    while (last > first && std::isspace(static_cast<unsigned char>(last[-1])))
      --last;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error == std::errc::result_out_of_range)
      throw InputError(name(entry) + " = " + std::string(first, last) + " is outside the allowed range " +
                       range);
    if (error != std::errc() || end != last)
      throw InputError(name(entry) + " = " + in_quotes(text) + " is not an integer in the allowed range " +
                       range);
    if (value < lo || value > hi)
      throw InputError(name(entry) + " = " + std::to_string(value) + " is outside the allowed range " +
                       range);
  }

  void Entries::numbers(const std::string &entry, std::vector<double> &values,
                        const std::vector<double> &defaults, const Range &range,
                        const std::string &documentation)
  {
    number_list(entry, values, defaults, range, "a list of distinct", documentation);
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
      throw InputError(name(entry) + " = " + in_quotes(prm.get(entry)) + " holds " + shortest(*twice) +
                       " twice: a list of distinct numbers in " + range.text);
  }

  void Entries::number_list(const std::string &entry, std::vector<double> &values,
                            const std::vector<double> &defaults, const Range &range, const std::string &kind,
                            const std::string &documentation)
  {
    if (!reading_)
      {
        std::vector<std::string> texts;
        for (const double x : defaults)
          texts.push_back(shortest(x));
        prm.declare_entry(entry, joined(texts, ", "), Patterns::Anything(),
                          documented(documentation, kind + " numbers in " + range.text));
        return;
      }
    values.clear();
    // deal.II's split drops an empty last item: "1, 2," would read as "1, 2".
    const std::string text = dealii::Utilities::trim(prm.get(entry));
    if (!text.empty() && text.back() == ',')
      throw InputError(name(entry) + " = " + in_quotes(text) + " ends with a comma: " + kind +
                       " numbers in " + range.text);
    for (const std::string &item : dealii::Utilities::split_string_list(text))
      {
        require_decimal(name(entry), item, range.text);
        double x;
        try
          {
            x = dealii::Utilities::string_to_double(item);
          }
        catch (const dealii::ExceptionBase &)
          {
            throw no_number(name(entry), item, range.text);
          }
        require(range.contains(x), entry, x, range.text);
        values.push_back(x);
      }
    if (values.empty())
      throw no_number(name(entry), prm.get(entry), range.text);
  }

  double Sweep::at(const unsigned int i) const
  {
    if (n_points == 1)
      return smallest;
    if (logarithmic)
      return smallest * std::pow(largest / smallest, static_cast<double>(i) / (n_points - 1));
    return smallest + i * (largest - smallest) / (n_points - 1);
  }

  void Entries::sweep(const std::string &quantity, const std::string &count, Sweep &sweep,
                      const Sweep &defaults, const unsigned int min_points, const unsigned int max_points,
                      const Range &range, const std::string &documentation)
  {
    sweep.logarithmic = defaults.logarithmic;
    // "(Smallest QUANTITY, " and the upper end of the interval: "(Smallest alpha, 0.56]".
    const std::string upper = range.text.substr(range.text.find(", ") + 2);
    number("Smallest " + quantity, sweep.smallest, defaults.smallest, range, documentation);
    number("Largest " + quantity, sweep.largest, defaults.largest,
           {"(Smallest " + quantity + ", " + upper, [](double) { return true; }}, documentation);
    require(range.contains(sweep.largest) && sweep.largest > sweep.smallest, "Largest " + quantity,
            sweep.largest, "(Smallest " + quantity + " = " + shortest(sweep.smallest) + ", " + upper);
    integer(count, sweep.n_points, defaults.n_points, min_points, max_points,
            "Points from the smallest to the largest " + quantity + ", evenly spaced" +
                (defaults.logarithmic ? " in log(" + quantity + ")" : "") + ". Units: none.");
  }

  void Entries::decreasing_numbers(const std::string &entry, std::vector<double> &values,
                                   const std::vector<double> &defaults, const std::size_t min_count,
                                   const Range &range, const std::string &documentation)
  {
    ordered_numbers(entry, values, defaults, min_count, range, false, documentation);
  }

  void Entries::increasing_numbers(const std::string &entry, std::vector<double> &values,
                                   const std::vector<double> &defaults, const std::size_t min_count,
                                   const Range &range, const std::string &documentation)
  {
    ordered_numbers(entry, values, defaults, min_count, range, true, documentation);
  }

  void Entries::ordered_numbers(const std::string &entry, std::vector<double> &values,
                                const std::vector<double> &defaults, const std::size_t min_count,
                                const Range &range, const bool increasing, const std::string &documentation)
  {
    const std::string kind = std::string(increasing ? "an increasing" : "a decreasing") + " list of" +
                             (min_count > 1 ? " at least " + std::to_string(min_count) : "");
    number_list(entry, values, defaults, range, kind, documentation);
    const std::string allowed = kind + " numbers in " + range.text;
    if (!reading_)
      return;
    if (values.size() < min_count)
      throw InputError(name(entry) + " = " + in_quotes(prm.get(entry)) + " is outside the allowed range " +
                       allowed);
    for (std::size_t k = 1; k < values.size(); ++k)
      require(increasing ? values[k] > values[k - 1] : values[k] < values[k - 1], entry, values[k], allowed);
  }

  void Entries::flag(const std::string &entry, bool &value, const bool default_value,
                     const std::string &documentation)
  {
    if (!reading_)
      prm.declare_entry(entry, default_value ? "true" : "false", Patterns::Bool(),
                        documented(documentation, "true, false"));
    else
      value = prm.get_bool(entry);
  }

  void Entries::selection(const std::string &entry, std::string &value, const std::string &default_value,
                          const std::vector<std::string> &options, const std::string &documentation)
  {
    text_entry(entry, value, default_value, Patterns::Selection(joined(options, "|")),
               documented(documentation, joined(options, ", ")));
  }

  void Entries::text_entry(const std::string &entry, std::string &value, const std::string &default_value,
                           const Patterns::PatternBase &pattern, const std::string &documentation)
  {
    if (!reading_)
      prm.declare_entry(entry, default_value, pattern, documentation);
    else
      value = prm.get(entry);
  }

  void Entries::text(const std::string &entry, std::string &value, const std::string &default_value,
                     const std::string &documentation)
  {
    text_entry(entry, value, default_value, Patterns::Anything(), documentation);
  }

  void Entries::file(const std::string &entry, std::string &value, const std::string &default_value,
                     const std::string &documentation)
  {
    text_entry(entry, value, default_value, Patterns::FileName(), documentation);
    if (reading_ && std::filesystem::path(value).is_relative())
      value = (std::filesystem::path(folder) / value).lexically_normal().string();
  }

  void Entries::require(const bool ok, const std::string &entry, const double value,
                        const std::string &range) const
  {
    if (reading_)
      penny::require(ok, name(entry), value, range);
  }

  Sections::Sections(ParameterHandler &prm, const bool reading, std::string folder, const bool checks)
      : prm(prm), reading_(reading), folder(std::move(folder)), checks(checks)
  {
  }

  void Sections::subsection(const std::string &subsection, const std::function<void(Entries &)> &list)
  {
    prm.enter_subsection(subsection);
    Entries entries(prm, subsection, reading_, folder);
    try
      {
        list(entries);
      }
    catch (...)
      {
        prm.leave_subsection();
        throw;
      }
    prm.leave_subsection();
  }

  void Sections::require(const bool ok, const std::string &entry, const double value,
                         const std::string &range) const
  {
    if (reading_)
      penny::require(ok, entry, value, range);
  }

  void Sections::check(const std::function<void()> &check) const
  {
    if (reading_ && checks)
      check();
  }

  void Sections::input_file(const std::string &path)
  {
    if (reading_)
      files.push_back(path);
  }
} // namespace penny
