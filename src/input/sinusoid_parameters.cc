#include "input/sinusoid_parameters.h"

#include "input/input_error.h"
#include "input/parameter_parsing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace penny
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;

  namespace
  {
    constexpr double max_double = std::numeric_limits<double>::max();
  } // namespace

  void PeriodicGapParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Periodic gap");
    prm.declare_entry("Wavelength lambda", "1", Double(0),
                      "Period of the sinusoid and of its array of gaps; the model is the half period "
                      "0 <= x <= lambda/2. Units: m.");
    prm.declare_entry("Depth D", "3", Double(0),
                      "Depth of the solid from the crack plane z = 0 to its far side z = D, "
                      "which is free (the perturbation of the gaps decays like exp(-2 pi z/lambda)); the "
                      "periodic-gap-depth scene replaces it by each of 'Depth study/Depths'. "
                      "Units: lambda.");
    prm.declare_entry("Tip refinement levels", "24", Integer(0, 40),
                      "Cells at the tip are min(c, lambda/2 - c)/2^levels wide. Units: none.");
    prm.declare_entry("Grading distance", "3", Double(0.5, 100),
                      "A cell is refined while it lies closer to the tip than this many of its own "
                      "widths; larger values give more cells per ring. Units: cell widths.");
    prm.declare_entry("Ring radii", "0.25, 0.5, 0.75", List(Double(0, 1), 1),
                      "Outer radii of the J-integral domains around the tip, weight "
                      "q = (1 - (d/rho)^2)^4; inside the domain for every c when below 1 and "
                      "4 D/lambda. The searches use the last. Open range (0, 1). "
                      "Units: min(c, lambda/2 - c).");
    prm.leave_subsection();
  }

  void PeriodicGapParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Periodic gap");
    wavelength       = prm.get_double("Wavelength lambda");
    depth            = prm.get_double("Depth D");
    tip_levels       = prm.get_integer("Tip refinement levels");
    grading_distance = prm.get_double("Grading distance");
    ring_radii       = get_doubles(prm, "Ring radii");
    prm.leave_subsection();
    // Bounded so that no product the solver forms overflows, and the mesh,
    // whose coarse cells are at most lambda/4 wide, stays small.
    require(wavelength >= 1e-30 && wavelength <= 1e30, "Periodic gap/Wavelength lambda", wavelength,
            "[1e-30, 1e30] m");
    require(depth > 0 && depth <= 100, "Periodic gap/Depth D", depth, "(0, 100] lambda");
    require(grading_distance <= 10, "Periodic gap/Grading distance", grading_distance, "[0.5, 10]");
    // min(c, lambda/2 - c) is at most lambda/4: rings below 4 D/lambda stay above z = -D.
    std::ostringstream largest;
    largest << std::min(1., 4 * depth);
    for (const double rho : ring_radii)
      require(rho > 0 && rho < std::min(1., 4 * depth), "Periodic gap/Ring radii", rho,
              "(0, min(1, 4 D/lambda) = " + largest.str() + ")");
  }

  void GapAndLoadParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Gap and load");
    prm.declare_entry("Gap half-width c/lambda", "0.2", Double(0, 0.5),
                      "Half-width of the gap, centred where the tension peaks; the contact "
                      "half-width is a = lambda/2 - c. Open range (0, 1/2). Units: lambda.");
    prm.declare_entry("Peak tension p*", "1e6", Double(0),
                      "Amplitude of the full-contact pressure, p* = pi E' h/lambda for a sinusoid of "
                      "amplitude h. Units: Pa.");
    prm.declare_entry("Mean pressure p_bar/p*", "0", Double(-max_double, max_double),
                      "Mean contact pressure (compressive positive); the gap faces carry "
                      "t = p* cos(2 pi x/lambda) - p_bar. Units: p*.");
    prm.leave_subsection();
  }

  void GapAndLoadParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Gap and load");
    gap_ratio    = prm.get_double("Gap half-width c/lambda");
    peak_tension = prm.get_double("Peak tension p*");
    load_ratio   = prm.get_double("Mean pressure p_bar/p*");
    prm.leave_subsection();
    // The tip cells are min(c, lambda/2 - c)/2^levels wide: a gap or a
    // contact narrower than 1e-6 lambda would need more quadtree levels than a mesh holds.
    require(gap_ratio >= 1e-6 && gap_ratio <= 0.5 - 1e-6, "Gap and load/Gap half-width c/lambda", gap_ratio,
            "[1e-6, 0.5 - 1e-6]");
    require(peak_tension >= 1e-30 && peak_tension <= 1e30, "Gap and load/Peak tension p*", peak_tension,
            "[1e-30, 1e30] Pa");
    require(std::abs(load_ratio) <= 1e3, "Gap and load/Mean pressure p_bar/p*", load_ratio, "[-1e3, 1e3]");
  }

  void DepthStudyParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Depth study");
    prm.declare_entry("Depths", "0.25, 0.5, 0.75, 1, 1.5, 2, 3", List(Double(0), 1),
                      "Depths D of the truncated solid, one solve each, in place of 'Periodic gap/Depth D'. "
                      "Units: lambda.");
    prm.leave_subsection();
  }

  void DepthStudyParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Depth study");
    depths = get_doubles(prm, "Depths");
    prm.leave_subsection();
    for (const double depth : depths)
      require(depth > 0 && depth <= 100, "Depth study/Depths", depth, "(0, 100] lambda");
  }

  void WestergaardCurveParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Westergaard curve");
    prm.declare_entry("Number of points", "8", Integer(1, 1000),
                      "Mean pressures p_bar/p* = i/(n + 1), i = 1 ... n; each is one FE root search "
                      "over the contact half-width. Units: none.");
    prm.leave_subsection();
  }

  void WestergaardCurveParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Westergaard curve");
    n_points = prm.get_integer("Number of points");
    prm.leave_subsection();
  }

  void JohnsonCurvesParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Johnson curves");
    prm.declare_entry("Johnson parameters alpha", "0, 0.2, 0.4, 0.6", List(Double(0), 1),
                      "alpha = K_Ic/(p* sqrt(lambda)), one curve each (Johnson's "
                      "alpha^2 = 2 lambda dgamma/(pi^2 E* h^2)). Units: none.");
    prm.declare_entry("Number of points", "24", Integer(1, 1000),
                      "Contact half-widths a/lambda = i/(2 (n + 1)), i = 1 ... n; each is one FE "
                      "solve of the two unit loads, shared by every alpha. Units: none.");
    prm.leave_subsection();
  }

  void JohnsonCurvesParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Johnson curves");
    alphas   = get_doubles(prm, "Johnson parameters alpha");
    n_points = prm.get_integer("Number of points");
    prm.leave_subsection();
  }

  void JumpIntoContactParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Jump into contact");
    prm.declare_entry("Smallest alpha", "1e-4", Double(0), "Open range (0, Largest alpha). Units: none.");
    prm.declare_entry("Largest alpha", "0.5", Double(0),
                      "Up to 0.56, where the maximum still lies in the search interval. Units: none.");
    prm.declare_entry("Number of alphas", "9", Integer(1, 1000),
                      "alphas evenly spaced in log(alpha) from the smallest to the largest; each is "
                      "one FE maximisation over the contact half-width. Units: none.");
    prm.leave_subsection();
  }

  void JumpIntoContactParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Jump into contact");
    smallest_alpha = prm.get_double("Smallest alpha");
    largest_alpha  = prm.get_double("Largest alpha");
    n_alphas       = prm.get_integer("Number of alphas");
    prm.leave_subsection();
    require(smallest_alpha >= 1e-8, "Jump into contact/Smallest alpha", smallest_alpha,
            "[1e-8, Largest alpha)");
    require(largest_alpha > smallest_alpha && largest_alpha <= 0.56, "Jump into contact/Largest alpha",
            largest_alpha, "(Smallest alpha = " + shortest(smallest_alpha) + ", 0.56]");
  }

  double JumpIntoContactParameters::alpha(const unsigned int i) const
  {
    if (n_alphas == 1)
      return smallest_alpha;
    return smallest_alpha * std::pow(largest_alpha / smallest_alpha, static_cast<double>(i) / (n_alphas - 1));
  }
} // namespace penny
