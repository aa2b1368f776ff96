// A table of results: named columns (units in their names), rows of numbers
// or text. The same table is printed aligned to the screen, with the digits
// each column (or cell) asks for, and written as CSV with every digit.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace penny
{
  class Table
  {
  public:
    // How a number is shown on the screen; the CSV keeps every digit.
    struct Format
    {
      int  precision  = 6;
      bool scientific = false;
    };
    // The house formats: every digit of a double, ten significant ones, and
    // three for an error.
    static constexpr Format all_digits{16, false}, digits{10, true}, error_digits{3, true};

    // A column named by its text alone takes the default format:
    // Table({"H", "zeta", {"error", error_digits}}).
    struct Column
    {
      Column(const char *name) : name(name) {}
      Column(std::string name) : name(std::move(name)) {}
      Column(std::string name, const Format format) : name(std::move(name)), format(format) {}

      std::string name;
      Format      format = {};
    };

    struct Cell
    {
      std::variant<double, long long, std::string> value;
      std::optional<Format>                        format; // the column's unless given

      Cell(const double number, const std::optional<Format> own_format = {})
          : value(number), format(own_format)
      {
      }
      template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
      Cell(const Integer number) : value(static_cast<long long>(number))
      {
      }
      Cell(std::string text) : value(std::move(text)) {}
      Cell(const char *text) : value(std::string(text)) {}
    };

    explicit Table(std::vector<Column> columns);

    // A table of named quantities: columns "quantity" and "value".
    static Table summary();

    // One cell per column.
    void add_row(std::vector<Cell> row);

    std::size_t n_rows() const { return rows.size(); }

    // A number as a column name or a note shows it, to `digits` digits:
    // "p_bar/p* alpha=0.2".
    static std::string label(double value, int digits = 6);

    void        print(std::ostream &out) const;
    std::string csv() const;

  private:
    std::vector<Column>            columns;
    std::vector<std::vector<Cell>> rows;
  };
} // namespace penny
