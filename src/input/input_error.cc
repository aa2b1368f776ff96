#include "input/input_error.h"

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

namespace penny
{
  void require(const bool ok, const std::string &entry, const double value, const std::string &range)
  {
    if (ok)
      return;
    throw InputError(entry + " = " + shortest(value) + " is outside the allowed range " + range);
  }

  std::string shortest(const double value)
  {
    std::ostringstream text;
    for (int digits = 6; digits <= 17; ++digits)
      {
        text.str("");
        text.precision(digits);
        text << value;
        if (!std::isfinite(value) || std::strtod(text.str().c_str(), nullptr) == value)
          break;
      }
    return text.str();
  }

  namespace
  {
    // Values longer than this are abbreviated in messages.
    constexpr std::size_t longest_value = 80;

    std::string abbreviated(const std::string &value)
    {
      if (value.size() <= longest_value)
        return value;
      return value.substr(0, longest_value - 20) + "... (" + std::to_string(value.size()) + " characters)";
    }
  } // namespace

  std::string in_quotes(const std::string &value)
  {
    return "'" + abbreviated(value) + "'";
  }

  // A message longer than a few lines echoes some value whole; its middle goes.
  std::string one_line(const std::string &text)
  {
    std::string collapsed;
    for (char ch : text)
      {
        if (ch == '\n' || ch == '\r' || ch == '\t')
          ch = ' ';
        // Other control characters (a terminal's escape sequences) are not echoed.
        else if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f)
          ch = '?';
        if (!(ch == ' ' && (collapsed.empty() || collapsed.back() == ' ')))
          collapsed += ch;
      }
    while (!collapsed.empty() && collapsed.back() == ' ')
      collapsed.pop_back();
    constexpr std::size_t head = 250, tail = 200;
    if (collapsed.size() <= head + tail + 50)
      return collapsed;
    return collapsed.substr(0, head) + " ... (" + std::to_string(collapsed.size() - head - tail) +
           " characters left out) ... " + collapsed.substr(collapsed.size() - tail);
  }

  std::string one_line(const dealii::ExceptionBase &exception)
  {
    std::ostringstream info;
    exception.print_info(info);
    return one_line(info.str());
  }
} // namespace penny
