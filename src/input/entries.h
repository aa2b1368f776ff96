// The entries of a parameter file, each listed once. A function that lists
// the entries of its subsections (name, variable, default, allowed range,
// documentation) serves twice: to declare them in a ParameterHandler (the
// default, a pattern, the documentation ending in the range) and, once the
// file is parsed, to read them into their variables, checking each range and
// throwing a one-line InputError "Subsection/Entry = VALUE is outside the
// allowed range RANGE". deal.II's ParameterHandler::add_parameter binds a
// variable in the same spirit, but it prints defaults with six digits and
// reads them back, and its errors name neither the subsection nor the range.
#pragma once

#include "input/input_error.h"

#include <deal.II/base/parameter_handler.h>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace penny
{
  // The values an entry allows, and how messages and documentation show them.
  struct Range
  {
    std::string                 text; // e.g. "[1e-30, 1e30] Pa"
    std::function<bool(double)> contains;
  };

  // An interval with its ends open or closed as `brackets` says, one of
  // "[]", "[)", "(]", "()", e.g. interval("(]", 0, 1) for 0 < x <= 1. An
  // infinite end reads "inf".
  Range interval(const std::string &brackets, double lo, double hi, const std::string &unit = "");

  // (lo, inf) and [lo, inf): the open-ended intervals.
  Range above(double lo, const std::string &unit = "");
  Range at_least(double lo, const std::string &unit = "");

  // [1e-30, 1e30] `unit`: moduli, lengths and tractions, far inside the range
  // of double, so that no product the solvers form (stiffness E R, load P c^2,
  // energy P^2 c^3/E', and their squares in norms) overflows or underflows.
  Range            magnitude(const std::string &unit);
  constexpr double smallest_magnitude = 1e-30, largest_magnitude = 1e30;

  // The same for a signed quantity that may vanish: 0 or |x| in [1e-30, 1e30].
  Range signed_magnitude(const std::string &unit);

  // The points of a curve: n_points values from the smallest to the largest,
  // evenly spaced in the value or in its logarithm.
  struct Sweep
  {
    double       smallest, largest;
    unsigned int n_points;
    bool         logarithmic = false;

    // The i-th point; the smallest if it is the only one.
    double at(unsigned int i) const;
  };

  // The names of a Selection entry and the values they stand for.
  template <typename Enum> using EnumNames = std::vector<std::pair<std::string, Enum>>;

  // The entries of one subsection, while they are declared or read.
  class Entries
  {
  public:
    Entries(dealii::ParameterHandler &prm, std::string subsection, bool reading, const std::string &folder);

    // A real number in `range`.
    void number(const std::string &entry, double &value, double default_value, const Range &range,
                const std::string &documentation);

    // A whole number in [lo, hi].
    template <typename Integer>
    void integer(const std::string &entry, Integer &value, Integer default_value, Integer lo, Integer hi,
                 const std::string &documentation)
    {
      long long read = 0;
      integer_entry(entry, read, default_value, lo, hi, documentation);
      if (reading_)
        value = static_cast<Integer>(read);
    }

    // A comma-separated list of at least one number, each in `range`, none
    // twice: a list of cases.
    void numbers(const std::string &entry, std::vector<double> &values, const std::vector<double> &defaults,
                 const Range &range, const std::string &documentation);

    // The same, at least `min_count` numbers and each below the one before:
    // a refinement sequence, the finest last.
    void decreasing_numbers(const std::string &entry, std::vector<double> &values,
                            const std::vector<double> &defaults, std::size_t min_count, const Range &range,
                            const std::string &documentation);

    // The same, each above the one before: a list of cases, none twice.
    void increasing_numbers(const std::string &entry, std::vector<double> &values,
                            const std::vector<double> &defaults, std::size_t min_count, const Range &range,
                            const std::string &documentation);

    void flag(const std::string &entry, bool &value, bool default_value, const std::string &documentation);

    // One of the names in `names`.
    template <typename Enum>
    void choice(const std::string &entry, Enum &value, Enum default_value, const EnumNames<Enum> &names,
                const std::string &documentation)
    {
      std::vector<std::string> options;
      std::string              chosen, default_name;
      for (const auto &[name, option] : names)
        {
          options.push_back(name);
          if (option == default_value)
            default_name = name;
        }
      selection(entry, chosen, default_name, options, documentation);
      for (const auto &[name, option] : names)
        if (reading_ && name == chosen)
          value = option;
    }

    // Any text, e.g. an expression.
    void text(const std::string &entry, std::string &value, const std::string &default_value,
              const std::string &documentation);

    // A file name; a relative one starts at the parameter file's folder.
    void file(const std::string &entry, std::string &value, const std::string &default_value,
              const std::string &documentation);

    // A sweep's 'Smallest QUANTITY' and 'Largest QUANTITY', both in `range`
    // (an interval) and the largest above the smallest, documented by
    // `documentation`, and the number of its points, the entry `count`, in
    // [min_points, max_points]; spaced as `defaults` are.
    void sweep(const std::string &quantity, const std::string &count, Sweep &sweep, const Sweep &defaults,
               unsigned int min_points, unsigned int max_points, const Range &range,
               const std::string &documentation);

    // A condition between entries, checked once they are read: throws
    // "Subsection/ENTRY = VALUE is outside the allowed range RANGE" unless `ok`.
    void require(bool ok, const std::string &entry, double value, const std::string &range) const;

    // "Subsection/ENTRY", as messages name it.
    std::string name(const std::string &entry) const { return subsection + "/" + entry; }

    // Whether the values are being read (else declared).
    bool reading() const { return reading_; }

  private:
    // A comma-separated list, documented as KIND ("a list of") numbers in `range`.
    void number_list(const std::string &entry, std::vector<double> &values,
                     const std::vector<double> &defaults, const Range &range, const std::string &kind,
                     const std::string &documentation);
    void ordered_numbers(const std::string &entry, std::vector<double> &values,
                         const std::vector<double> &defaults, std::size_t min_count, const Range &range,
                         bool increasing, const std::string &documentation);
    void integer_entry(const std::string &entry, long long &value, long long default_value, long long lo,
                       long long hi, const std::string &documentation);
    // One of `options`, which the printed documentation lists.
    void selection(const std::string &entry, std::string &value, const std::string &default_value,
                   const std::vector<std::string> &options, const std::string &documentation);
    // An entry read as text that matches `pattern`.
    void text_entry(const std::string &entry, std::string &value, const std::string &default_value,
                    const dealii::Patterns::PatternBase &pattern, const std::string &documentation);

    dealii::ParameterHandler &prm;
    const std::string         subsection;
    const bool                reading_;
    const std::string         folder;
  };

  // The subsections of a parameter file, while they are declared or read.
  class Sections
  {
  public:
    // `folder`: where relative file names start (the parameter file's folder);
    // `checks`: whether check() runs its checks when reading.
    Sections(dealii::ParameterHandler &prm, bool reading, std::string folder = "", bool checks = true);

    // The entries of `subsection`, listed by `list`.
    void subsection(const std::string &subsection, const std::function<void(Entries &)> &list);

    // A condition between entries of different subsections, checked once
    // they are read; `entry` is "Subsection/Entry".
    void require(bool ok, const std::string &entry, double value, const std::string &range) const;

    // Runs `check` once the entries are read (not while they are declared).
    void check(const std::function<void()> &check) const;

    // A file the run reads, named by an entry that was read (a mesh, a
    // spectrum): replacing the output folder must not remove it.
    void                            input_file(const std::string &path);
    const std::vector<std::string> &input_files() const { return files; }

    bool reading() const { return reading_; }

  private:
    dealii::ParameterHandler &prm;
    const bool                reading_;
    const std::string         folder;
    const bool                checks;
    std::vector<std::string>  files;
  };

  // The values a list of subsections holds at the defaults of its entries:
  // `list(sections, values)` declared, then read, with no file in between.
  // Its checks (Sections::check) do not run: some judge the run, not the
  // entries (a model's size against the memory), and the caller checks the
  // values it goes on to use.
  template <typename Values, typename List> Values default_values(List &&list)
  {
    dealii::ParameterHandler prm;
    Values                   values{};
    Sections                 declaring(prm, false);
    list(declaring, values);
    Sections reading(prm, true, "", false);
    list(reading, values);
    return values;
  }
} // namespace penny
