// Bad input and how it is reported: one line that names the entry and the
// allowed range, meant to be shown to the user as is.
#pragma once

#include <stdexcept>
#include <string>

namespace dealii
{
  class ExceptionBase;
}

namespace penny
{
  struct InputError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  // Throws "ENTRY = VALUE is outside the allowed range RANGE" unless `ok`.
  void require(bool ok, const std::string &entry, double value, const std::string &range);

  // deal.II's exception text spans several lines; its explanation on one line.
  std::string one_line(const dealii::ExceptionBase &exception);
} // namespace penny
