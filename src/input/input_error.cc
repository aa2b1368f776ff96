#include "input/input_error.h"

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <cstdlib>
#include <regex>
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

  std::string choices_in(const std::string &message)
  {
    std::smatch match;
    if (!std::regex_search(message, match, std::regex("\\[(Selection (.*) |Bool)\\]>?\\.?$")))
      return "";
    return match[1] == "Bool" ? "true, false" : std::regex_replace(match[2].str(), std::regex("\\|"), ", ");
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
    // The length of the UTF-8 sequence of a printable character at text[i],
    // 0 if it is not one (a binary file's bytes).
    const auto utf8_length = [&](const std::size_t i) -> std::size_t {
      const unsigned char lead   = text[i];
      const std::size_t   length = lead >= 0xc2 && lead <= 0xdf   ? 2
                                   : lead >= 0xe0 && lead <= 0xef ? 3
                                   : lead >= 0xf0 && lead <= 0xf4 ? 4
                                                                  : 0;
      for (std::size_t k = 1; k < length; ++k)
        if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80)
          return 0;
      // U+0080 ... U+009F are control characters too.
      if (lead == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0)
        return 0;
      return length;
    };
    std::string collapsed;
    for (std::size_t i = 0; i < text.size(); ++i)
      {
        char ch = text[i];
        if (static_cast<unsigned char>(ch) >= 0x80)
          {
            if (const std::size_t length = utf8_length(i))
              {
                collapsed += text.substr(i, length);
                i += length - 1;
                continue;
              }
            ch = '?';
          }
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
