#include "closed_forms/face_load.h"

#include "input/input_error.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

namespace penny
{
  FaceLoad::FaceLoad(const LoadParameters &load, const double gap_radius) : load(load)
  {
    if (load.type != Type::expression)
      return;
    expression = std::make_unique<dealii::FunctionParser<1>>(1);
    // FunctionParser prints muparser's diagnostics to std::cerr; the one-line
    // InputError below replaces them.
    const CapturedCerr muparser_diagnostics;
    try
      {
        expression->initialize("r", load.expression,
                               {{"c", gap_radius}, {"P", load.peak_tension}, {"pi", dealii::numbers::PI}});
        (*this)(0.5 * gap_radius); // muparser reports some errors only when evaluated
      }
    catch (const dealii::ExceptionBase &)
      {
        throw InputError(in_quotes(load.expression) +
                         " is not a valid muparser expression in r (constants c, P, pi)");
      }
  }

  FaceLoad FaceLoad::unit_uniform()
  {
    return FaceLoad({Type::uniform, 1, 1, "", 1}, 1);
  }

  FaceLoad FaceLoad::unit_quadratic()
  {
    return FaceLoad({Type::expression, 1, 1, "r^2", 1}, 1);
  }

  double FaceLoad::operator()(const double r) const
  {
    switch (load.type)
      {
      case Type::uniform:
        return load.peak_tension;
      case Type::parabolic:
        return load.peak_tension * (1 - r * r / (load.tension_radius * load.tension_radius));
      case Type::expression:
        return expression->value(dealii::Point<1>(r));
      }
    return 0;
  }
} // namespace penny
