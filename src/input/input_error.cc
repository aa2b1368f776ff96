#include "input/input_error.h"

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <sstream>

namespace penny
{
  void require(const bool ok, const std::string &entry, const double value, const std::string &range)
  {
    if (ok)
      return;
    std::ostringstream message;
    message.precision(17);
    message << entry << " = " << value << " is outside the allowed range " << range;
    throw InputError(message.str());
  }

  std::string one_line(const dealii::ExceptionBase &exception)
  {
    std::ostringstream info;
    exception.print_info(info);
    std::string text = info.str();
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::string collapsed;
    for (const char ch : text)
      if (!(ch == ' ' && (collapsed.empty() || collapsed.back() == ' ')))
        collapsed += ch;
    while (!collapsed.empty() && collapsed.back() == ' ')
      collapsed.pop_back();
    return collapsed;
  }
} // namespace penny
