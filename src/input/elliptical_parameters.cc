#include "input/elliptical_parameters.h"

#include "input/input_error.h"
#include "input/parameter_parsing.h"

#include <limits>

namespace penny
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;

  void EllipticalModelParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Elliptical model");
    prm.declare_entry("Box width R/a", "40", Double(0),
                      "The quarter model reaches x = R and y = R; free there. At least 2.8. Units: a.");
    prm.declare_entry("Box height H/a", "40", Double(0),
                      "The model reaches z = H; free there (at 20 instead of 40 K_I of the circle moves "
                      "by 1e-4). At least 2.8. Units: a.");
    prm.declare_entry("Cells along front", "16", Integer(2, 256),
                      "Edges of the quarter front 0 <= phi <= pi/2, evenly spaced in the parametric angle "
                      "phi; even. Units: none.");
    prm.declare_entry("Sectors around front", "8", Integer(4, 64),
                      "Sectors of the half-plane around the front in every normal plane; a multiple of 4. "
                      "Units: none.");
    prm.declare_entry("Front cell size", "1e-3", Double(0),
                      "Radius of the innermost ring of cells around the front (a across the front at "
                      "phi = 0, b at pi/2). Range (0, 0.33). Units: b.");
    prm.declare_entry("Ring ratio", "1.6", Double(1),
                      "Nominal ratio of successive ring radii around the front. Range (1, 4]. Units: none.");
    prm.declare_entry("Global refinements", "0", Integer(0, 3),
                      "Uniform refinements of the graded coarse mesh (each multiplies the DoFs by about 8); "
                      "new front points lie on the ellipse. Units: none.");
    prm.declare_entry("Front weight half-width", "2", Double(0),
                      "Half-width of the weight along the front of each domain integral, in front cells of "
                      "the refined mesh; up to Cells along front. Units: front cells.");
    prm.declare_entry("Ring radii", "0.1, 0.2, 0.4", List(Double(0, 1), 1),
                      "Radii rho of the J-integral tubes around the front, q = (1 - (d/rho)^2)^4 across "
                      "it; below the smallest radius of curvature b^2/a of the front. Open range (0, 1). "
                      "Units: b^2/a.");
    prm.leave_subsection();
  }

  void EllipticalModelParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Elliptical model");
    box_width          = prm.get_double("Box width R/a");
    box_height         = prm.get_double("Box height H/a");
    cells_along_front  = prm.get_integer("Cells along front");
    sectors            = prm.get_integer("Sectors around front");
    front_cell_size    = prm.get_double("Front cell size");
    ring_ratio         = prm.get_double("Ring ratio");
    global_refinements = prm.get_integer("Global refinements");
    weight_half_width  = prm.get_double("Front weight half-width");
    ring_radii         = get_doubles(prm, "Ring radii");
    prm.leave_subsection();
    const std::string section = "Elliptical model/";
    require(box_width >= 2.8, section + "Box width R/a", box_width, "[2.8, inf)");
    require(box_height >= 2.8, section + "Box height H/a", box_height, "[2.8, inf)");
    require(cells_along_front % 2 == 0, section + "Cells along front", cells_along_front,
            "{2, 4, 6, ..., 256}");
    require(sectors % 4 == 0, section + "Sectors around front", sectors, "{4, 8, 12, ..., 64}");
    require(front_cell_size > 0 && front_cell_size < 0.33, section + "Front cell size", front_cell_size,
            "(0, 0.33)");
    require(ring_ratio > 1 && ring_ratio <= 4, section + "Ring ratio", ring_ratio, "(1, 4]");
    const double front_cells = cells_along_front << global_refinements;
    require(weight_half_width > 0 && weight_half_width <= front_cells, section + "Front weight half-width",
            weight_half_width, "(0, Cells along front x 2^Global refinements]");
    for (const double rho : ring_radii)
      require(rho > 0 && rho < 1, section + "Ring radii", rho, "(0, 1)");
  }

  void EllipticalGapParameters::declare(ParameterHandler &prm)
  {
    const double max_double = std::numeric_limits<double>::max();
    prm.enter_subsection("Elliptical gap");
    prm.declare_entry("Semi-axis a", "1", Double(0),
                      "The larger semi-axis of the gap x^2/a^2 + y^2/b^2 < 1 on z = 0, along x. Units: m.");
    prm.declare_entry("Aspect ratio b/a", "0.5", Double(0, 1),
                      "The smaller semi-axis b along y over a. Range (0, 1]. Units: none.");
    prm.declare_entry("Pressure p", "1e6", Double(-max_double, max_double),
                      "Uniform normal traction opening the gap faces; not 0. Units: Pa.");
    prm.declare_entry("Front points", "17", Integer(2, 1000),
                      "K_I is reported at phi = i pi/(2 (n - 1)), i = 0 ... n - 1, one domain integral "
                      "each. Units: none.");
    prm.leave_subsection();
  }

  void EllipticalGapParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Elliptical gap");
    semi_axis_a  = prm.get_double("Semi-axis a");
    aspect_ratio = prm.get_double("Aspect ratio b/a");
    pressure     = prm.get_double("Pressure p");
    front_points = prm.get_integer("Front points");
    prm.leave_subsection();
    const std::string section = "Elliptical gap/";
    require(semi_axis_a > 0, section + "Semi-axis a", semi_axis_a, "(0, inf)");
    require(aspect_ratio > 0 && aspect_ratio <= 1, section + "Aspect ratio b/a", aspect_ratio, "(0, 1]");
    require(pressure != 0, section + "Pressure p", pressure, "(-inf, 0) or (0, inf)");
  }

  void EllipticalSummitsParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Elliptical summits");
    prm.declare_entry("Tension aspect ratios Ay/Ax", "1, 0.8, 0.5, 0.25", List(Double(0, 1), 1),
                      "Summits t = P (1 - x^2/Ax^2 - y^2/Ay^2) of principal radii R_1 = Ax^2/(2 P) and "
                      "R_2 = Ay^2/(2 P); for each, the gaps are searched with and without adhesion. "
                      "Slender summits need slender gap models (b/a about 0.14 for Ay/Ax = 0.1, where "
                      "CG with AMG stalls on the default meshes). Range [0.05, 1]. Units: none.");
    prm.declare_entry("Front points", "9", Integer(2, 1000),
                      "K_I along the front of each gap found, at phi = i pi/(2 (n - 1)), i = 0 ... n - 1. "
                      "Units: none.");
    prm.leave_subsection();
  }

  void EllipticalSummitsParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Elliptical summits");
    tension_aspect_ratios = get_doubles(prm, "Tension aspect ratios Ay/Ax");
    front_points          = prm.get_integer("Front points");
    prm.leave_subsection();
    for (const double ratio : tension_aspect_ratios)
      require(ratio >= 0.05 && ratio <= 1, "Elliptical summits/Tension aspect ratios Ay/Ax", ratio,
              "[0.05, 1]");
  }
} // namespace penny
