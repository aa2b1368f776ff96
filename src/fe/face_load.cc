#include "fe/face_load.h"

#include "input/input_error.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <cmath>

#include <iostream>
#include <sstream>

namespace penny
{
  FaceLoad::FaceLoad(const LoadParameters &load, const double gap_radius) : load(load)
  {
    if (load.type == Type::expression)
      parse_expression(gap_radius);
    check_on_face(gap_radius);
  }

  void FaceLoad::parse_expression(const double gap_radius)
  {
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
        throw InputError("Load/Expression = " + in_quotes(load.expression) +
                         " is not a valid muparser expression in r (constants c, P, pi)");
      }
  }

  // On the midpoints of a fine grid of the open face 0 < r < c (an integrable
  // singularity at r = 0 or r = c is allowed): the load must be finite and
  // must not vanish everywhere. Every rank checks the same points, so the
  // error reaches them all.
  void FaceLoad::check_on_face(const double gap_radius) const
  {
    constexpr unsigned int n_points = 1000;
    bool                   vanishes = true;
    for (unsigned int k = 0; k < n_points; ++k)
      {
        const double r = gap_radius * (k + 0.5) / n_points;
        const double p = (*this)(r);
        if (!std::isfinite(p))
          throw InputError(entries() + " gives p(" + shortest(r) + " m) = " + shortest(p) +
                           "; the load must be finite on 0 < r < c");
        vanishes = vanishes && p == 0;
      }
    if (vanishes)
      throw InputError(entries() + " vanishes on the gap face 0 < r < c: a zero load opens nothing");
  }

  std::string FaceLoad::entries() const
  {
    const std::string P = "Load/Peak tension P = " + shortest(load.peak_tension);
    switch (load.type)
      {
      case Type::uniform:
        return P;
      case Type::parabolic:
        return P + " with Load/Tension radius a = " + shortest(load.tension_radius);
      case Type::expression:
        return "Load/Expression = " + in_quotes(load.expression);
      }
    return "";
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
