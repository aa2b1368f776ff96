// The traction p(r) on the gap faces, z = 0 and r < c. It acts along +z on the
// upper face and opens the gap; negative values press the faces together.
#pragma once

#include "input/fe_parameters.h"

#include <deal.II/base/function_parser.h>

#include <memory>

namespace penny
{
  class FaceLoad
  {
  public:
    using Type = LoadParameters::Type;

    // Throws InputError for an expression muparser cannot read, and for a
    // load that is NaN or Inf somewhere on the face or zero everywhere.
    FaceLoad(const LoadParameters &load, double gap_radius);

    // The unit load cases of doc/theory.md, section 1: p = 1 Pa and p = r^2 (Pa/m^2).
    static FaceLoad unit_uniform();
    static FaceLoad unit_quadratic();

    double operator()(double r) const;

    // The entries that define the load, with their values, for messages.
    std::string entries() const;

    Type   type() const { return load.type; }
    double peak_tension() const { return load.peak_tension; }
    double tension_radius() const { return load.tension_radius; }

  private:
    void parse_expression(double gap_radius);
    // Throws InputError, naming the load's entries, unless the load is finite
    // and not zero everywhere on the face.
    void check_on_face(double gap_radius) const;

    LoadParameters                             load;
    std::unique_ptr<dealii::FunctionParser<1>> expression;
  };
} // namespace penny
