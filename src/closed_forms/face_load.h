// The traction p(r) on the faces of a penny gap of radius c, z = 0 and r < c:
// the load that Sneddon's closed forms (closed_forms/sneddon_solution.h) and
// the FE model (fe/penny_gap_model.h) both take. It acts along +z on the upper
// face and opens the gap; negative values press the faces together.
#pragma once

#include <deal.II/base/function_parser.h>

#include <memory>
#include <string>

namespace penny
{
  struct LoadParameters
  {
    enum class Type
    {
      uniform,   // p = P
      parabolic, // Bueckner's p = P (1 - r^2/a^2)
      expression // any p(r)
    };
    Type        type;
    double      peak_tension;   // P (Pa)
    double      tension_radius; // a (m); for a parabola given by R_p, a^2 = 2 R_p P
    std::string expression;     // p(r) in Pa, r in m; constants c, P, pi
    double      summit_radius;  // R_p (m^2/Pa), a^2 = 2 R_p P
  };

  class FaceLoad
  {
  public:
    using Type = LoadParameters::Type;

    // Throws InputError "'EXPRESSION' is not a valid muparser expression ..."
    // for an expression muparser cannot read.
    FaceLoad(const LoadParameters &load, double gap_radius);

    // The unit load cases of doc/theory.md, section 1: p = 1 Pa and p = r^2 (Pa/m^2).
    static FaceLoad unit_uniform();
    static FaceLoad unit_quadratic();

    double operator()(double r) const;

    Type   type() const { return load.type; }
    double peak_tension() const { return load.peak_tension; }
    double tension_radius() const { return load.tension_radius; }

  private:
    LoadParameters                             load;
    std::unique_ptr<dealii::FunctionParser<1>> expression;
  };
} // namespace penny
