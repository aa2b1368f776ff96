// Bad input and how it is reported: one line that names the entry and the
// allowed range, meant to be shown to the user as is.
#pragma once

#include <iostream>
#include <sstream>
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

  // Any text on one line: line breaks become spaces, runs of blanks one, and
  // the middle of a text longer than about 500 characters is left out.
  std::string one_line(const std::string &text);

  // deal.II's exception text spans several lines; its explanation on one line.
  std::string one_line(const dealii::ExceptionBase &exception);

  // The choices of the pattern a deal.II message ends with ("[Selection a|b ]"
  // or "[Bool]") as "a, b" or "true, false"; empty if it names neither.
  std::string choices_in(const std::string &message);

  // The shortest text of `value` that reads back as `value`.
  std::string shortest(double value);

  // A value as an error message shows it: 'value', abbreviated when long.
  std::string in_quotes(const std::string &value);

  // What libraries print to std::cerr while this lives (muparser's and
  // Amesos' diagnostics) is kept here instead; penny reports in one line.
  class CapturedCerr
  {
  public:
    CapturedCerr() : saved(std::cerr.rdbuf(sink.rdbuf())) {}
    CapturedCerr(const CapturedCerr &) = delete;
    ~CapturedCerr() { std::cerr.rdbuf(saved); }

    std::string text() const { return sink.str(); }

  private:
    std::ostringstream    sink;
    std::streambuf *const saved;
  };
} // namespace penny
