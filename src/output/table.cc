#include "output/table.h"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace penny
{
  namespace
  {
    std::string screen_text(const Table::Cell &cell, const Table::Format &column_format)
    {
      std::ostringstream text;
      if (const double *number = std::get_if<double>(&cell.value))
        {
          const Table::Format format = cell.format.value_or(column_format);
          if (format.scientific)
            text << std::scientific;
          text << std::setprecision(format.precision) << *number;
        }
      else if (const long long *integer = std::get_if<long long>(&cell.value))
        text << *integer;
      else
        text << std::get<std::string>(cell.value);
      return text.str();
    }

    // Every digit of a number; text quoted where it holds a comma or a quote.
    std::string csv_text(const Table::Cell &cell)
    {
      std::ostringstream text;
      if (const double *number = std::get_if<double>(&cell.value))
        text << std::setprecision(std::numeric_limits<double>::max_digits10) << *number;
      else if (const long long *integer = std::get_if<long long>(&cell.value))
        text << *integer;
      else
        {
          const std::string &value = std::get<std::string>(cell.value);
          if (value.find_first_of(",\"\n") == std::string::npos)
            return value;
          text << '"';
          for (const char ch : value)
            text << (ch == '"' ? "\"\"" : std::string(1, ch));
          text << '"';
        }
      return text.str();
    }
  } // namespace

  Table::Table(std::vector<Column> columns) : columns(std::move(columns)) {}

  std::string Table::label(const double value, const int digits)
  {
    std::ostringstream text;
    text.precision(digits);
    text << value;
    return text.str();
  }

  Table Table::summary()
  {
    return Table({{"quantity"}, {"value"}});
  }

  void Table::add_row(std::vector<Cell> row)
  {
    if (row.size() != columns.size())
      throw std::logic_error("table row of " + std::to_string(row.size()) + " cells for " +
                             std::to_string(columns.size()) + " columns");
    rows.push_back(std::move(row));
  }

  // Two spaces between columns.
  void Table::print(std::ostream &out) const
  {
    std::vector<std::vector<std::string>> texts(rows.size());
    std::vector<std::size_t>              widths;
    for (const auto &column : columns)
      widths.push_back(column.name.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < columns.size(); ++j)
        {
          texts[i].push_back(screen_text(rows[i][j], columns[j].format));
          widths[j] = std::max(widths[j], texts[i][j].size());
        }
    // Columns of text are aligned left, columns holding numbers right.
    std::vector<bool> left(columns.size(), true);
    for (const auto &row : rows)
      for (std::size_t j = 0; j < columns.size(); ++j)
        left[j] = left[j] && std::holds_alternative<std::string>(row[j].value);
    for (std::size_t i = 0; i <= rows.size(); ++i)
      {
        for (std::size_t j = 0; j < columns.size(); ++j)
          out << (j > 0 ? "  " : "") << (left[j] ? std::left : std::right) << std::setw(widths[j])
              << (i == 0 ? columns[j].name : texts[i - 1][j]);
        out << '\n';
      }
    out << std::right;
  }

  std::string Table::csv() const
  {
    std::ostringstream out;
    for (std::size_t j = 0; j < columns.size(); ++j)
      out << (j > 0 ? "," : "") << csv_text(Table::Cell(columns[j].name));
    out << '\n';
    for (const auto &row : rows)
      {
        for (std::size_t j = 0; j < row.size(); ++j)
          out << (j > 0 ? "," : "") << csv_text(row[j]);
        out << '\n';
      }
    return out.str();
  }
} // namespace penny
