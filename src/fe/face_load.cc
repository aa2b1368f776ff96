#include "fe/face_load.h"

#include "input/input_error.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <iostream>
#include <sstream>

namespace penny
{
  FaceLoad::FaceLoad(const LoadParameters &load, const double gap_radius) : load(load)
  {
    if (load.type != Type::expression)
      return;
    expression = std::make_unique<dealii::FunctionParser<1>>(1);
    // FunctionParser prints muparser's diagnostics to std::cerr; the one-line
    // InputError below replaces them.
    struct SilencedCerr
    {
      std::ostringstream    sink;
      std::streambuf *const saved = std::cerr.rdbuf(sink.rdbuf());
      ~SilencedCerr() { std::cerr.rdbuf(saved); }
    } silenced_cerr;
    try
      {
        expression->initialize("r", load.expression,
                               {{"c", gap_radius}, {"P", load.peak_tension}, {"pi", dealii::numbers::PI}});
        (*this)(0.5 * gap_radius); // muparser reports some errors only when evaluated
      }
    catch (const dealii::ExceptionBase &)
      {
        throw InputError("Load/Expression = '" + load.expression +
                         "' is not a valid muparser expression in r (constants c, P, pi)");
      }
  }

  FaceLoad FaceLoad::unit_uniform()
  {
    LoadParameters load;
    load.type           = Type::uniform;
    load.peak_tension   = 1;
    load.tension_radius = 1;
    return FaceLoad(load, 1);
  }

  FaceLoad FaceLoad::unit_quadratic()
  {
    LoadParameters load;
    load.type       = Type::expression;
    load.expression = "r^2";
    return FaceLoad(load, 1);
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
