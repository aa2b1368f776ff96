#include "input/fe_parameters.h"

#include "input/input_error.h"
#include "input/parameter_parsing.h"

#include <deal.II/base/utilities.h>

#include <cmath>
#include <limits>

namespace penny
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Anything;
  using dealii::Patterns::Double;
  using dealii::Patterns::FileName;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;

  namespace
  {
    constexpr double max_double = std::numeric_limits<double>::max();

    // Magnitudes of moduli, tractions and lengths: far inside the range of
    // double, so that no product the solver forms (stiffness E R, load P c^2,
    // energy P^2 c^3/E', and their squares in norms) overflows or underflows.
    constexpr double smallest_magnitude = 1e-30, largest_magnitude = 1e30;
    // R/c and H/c.
    constexpr double largest_aspect = 1e12;

    std::string magnitude_range(const std::string &unit)
    {
      return "[1e-30, 1e30] " + unit;
    }

    // prm.get_double of `entry` in `section`, where a value that no double
    // holds (a denormal, an overflow) is outside `range`.
    double get_double_in(const ParameterHandler &prm, const std::string &section, const std::string &entry,
                         const std::string &range)
    {
      try
        {
          return prm.get_double(entry);
        }
      catch (const dealii::ExceptionBase &)
        {
          throw InputError(section + "/" + entry + " = " + in_quotes(prm.get(entry)) +
                           " is outside the allowed range " + range);
        }
    }

    const EnumNames<LoadParameters::Type>      load_types     = {{"uniform", LoadParameters::Type::uniform},
                                                                 {"parabolic", LoadParameters::Type::parabolic},
                                                                 {"expression", LoadParameters::Type::expression}};
    const EnumNames<bool>                      far_boundaries = {{"free", false}, {"clamped", true}};
    const EnumNames<bool>                      parabola_forms = {{"a", false}, {"R_p", true}};
    const EnumNames<MeshParameters::Generator> generators = {{"builtin", MeshParameters::Generator::builtin},
                                                             {"gmsh", MeshParameters::Generator::gmsh}};
    const EnumNames<LinearSolverParameters::Type> solvers = {
        {"direct", LinearSolverParameters::Type::direct}, {"cg-amg", LinearSolverParameters::Type::cg_amg}};
  } // namespace

  void GeometryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Gap radius c", "1", Double(0),
                      "Radius of the penny-shaped gap (crack), from 1e-30 to 1e30. Units: m.");
    prm.declare_entry("Domain radius R", "1000", Double(0),
                      "Radius of the truncated cylinder, from c to 1e12 c. Its effect on K_I shrinks "
                      "roughly like (c/R)^3. Units: m.");
    prm.declare_entry("Domain height H", "1000", Double(0),
                      "Height of the half model z >= 0, at most 1e12 c. Units: m.");
    prm.declare_entry("Far boundary", "free", selection(far_boundaries),
                      "Condition on r = R and z = H: traction free, or clamped (u = 0).");
    prm.leave_subsection();
  }

  void GeometryParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    gap_radius           = get_double_in(prm, "Geometry", "Gap radius c", magnitude_range("m"));
    domain_radius        = get_double_in(prm, "Geometry", "Domain radius R", "(c, 1e12 c]");
    domain_height        = get_double_in(prm, "Geometry", "Domain height H", "(0, 1e12 c]");
    clamped_far_boundary = to_enum(far_boundaries, prm.get("Far boundary"));
    prm.leave_subsection();
    require(gap_radius >= smallest_magnitude && gap_radius <= largest_magnitude, "Geometry/Gap radius c",
            gap_radius, magnitude_range("m"));
    require(domain_radius > gap_radius, "Geometry/Domain radius R", domain_radius,
            "(Gap radius c = " + dealii::Utilities::to_string(gap_radius) + ", inf)");
    const std::string c = dealii::Utilities::to_string(gap_radius);
    require(domain_radius <= largest_aspect * gap_radius, "Geometry/Domain radius R", domain_radius,
            "(c, 1e12 c] with Gap radius c = " + c + " m");
    require(domain_height > 0 && domain_height <= largest_aspect * gap_radius, "Geometry/Domain height H",
            domain_height, "(0, 1e12 c] with Gap radius c = " + c + " m");
  }

  double MaterialParameters::plane_strain_modulus() const
  {
    return youngs_modulus / (1 - poissons_ratio * poissons_ratio);
  }

  double MaterialParameters::lame_lambda() const
  {
    return youngs_modulus * poissons_ratio / ((1 + poissons_ratio) * (1 - 2 * poissons_ratio));
  }

  double MaterialParameters::lame_mu() const
  {
    return youngs_modulus / (2 * (1 + poissons_ratio));
  }

  void MaterialParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus E", "1e9", Double(0),
                      "Isotropic linear elasticity, from 1e-30 to 1e30. Units: Pa.");
    prm.declare_entry("Poisson's ratio nu", "0.3", Double(-1, 0.5), "Open range (-1, 0.5). Units: none.");
    prm.leave_subsection();
  }

  void MaterialParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = get_double_in(prm, "Material", "Young's modulus E", magnitude_range("Pa"));
    poissons_ratio = prm.get_double("Poisson's ratio nu");
    prm.leave_subsection();
    require(youngs_modulus >= smallest_magnitude && youngs_modulus <= largest_magnitude,
            "Material/Young's modulus E", youngs_modulus, magnitude_range("Pa"));
    require(poissons_ratio > -1 && poissons_ratio < 0.5, "Material/Poisson's ratio nu", poissons_ratio,
            "(-1, 0.5)");
  }

  void LoadParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Load");
    prm.declare_entry("Type", "uniform", selection(load_types),
                      "Face traction p(r) opening the gap: uniform p = P; parabolic (Bueckner) "
                      "p = P (1 - r^2/a^2); expression: any p(r) in 'Expression'.");
    prm.declare_entry("Peak tension P", "1e6", Double(-max_double, max_double),
                      "P: the uniform value, or the peak of the parabola at r = 0; 0 or |P| from 1e-30 to "
                      "1e30. Units: Pa.");
    prm.declare_entry("Parabola given by", "a", selection(parabola_forms),
                      "Whether the parabola is fixed by its tensile radius a or by the pressure "
                      "summit radius R_p, with a^2 = 2 R_p P.");
    prm.declare_entry("Tension radius a", "1.25", Double(0),
                      "Radius where the parabolic tension vanishes. Units: m.");
    prm.declare_entry("Summit radius R_p", "7.8125e-7", Double(0),
                      "Radius of the pressure summit, p = P - r^2/(2 R_p). Units: m^2/Pa.");
    prm.declare_entry("Expression", "1e6 * (r/c)^4", Anything(),
                      "p(r) for Type = expression, in muparser syntax; variable r (m), "
                      "constants c (gap radius, m), P (peak tension, Pa) and pi. Units: Pa.");
    prm.leave_subsection();
  }

  void LoadParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Load");
    type          = to_enum(load_types, prm.get("Type"));
    peak_tension  = get_double_in(prm, "Load", "Peak tension P", "0 or |P| in " + magnitude_range("Pa"));
    summit_radius = prm.get_double("Summit radius R_p");
    require(summit_radius > 0, "Load/Summit radius R_p", summit_radius, "(0, inf)");
    if (!to_enum(parabola_forms, prm.get("Parabola given by")))
      tension_radius = get_double_in(prm, "Load", "Tension radius a", magnitude_range("m"));
    else
      {
        require(peak_tension > 0, "Load/Peak tension P", peak_tension,
                "(0, inf) when the parabola is given by R_p");
        tension_radius = std::sqrt(2 * summit_radius * peak_tension);
      }
    expression = prm.get("Expression");
    prm.leave_subsection();
    require(tension_radius >= smallest_magnitude && tension_radius <= largest_magnitude,
            "Load/Tension radius a", tension_radius, magnitude_range("m"));
    require(std::abs(peak_tension) <= largest_magnitude &&
                (peak_tension == 0 || std::abs(peak_tension) >= smallest_magnitude),
            "Load/Peak tension P", peak_tension, "0 or |P| in " + magnitude_range("Pa"));
  }

  void MeshParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Generator", "builtin", selection(generators),
                      "builtin: quadtree of square cells, the tip at a vertex, graded geometrically "
                      "(ratio 2) towards the tip and growing to R and H. gmsh: read 'Mesh file'.");
    prm.declare_entry("Tip refinement levels", "30", Integer(0, 40),
                      "Cells at the tip are c / 2^levels wide. Units: none.");
    prm.declare_entry("Gap face levels", "3", Integer(0, 10),
                      "builtin only: cells over the gap face, within c of it, are at most c/2^levels wide; "
                      "they resolve the face opening w(r). Units: none.");
    prm.declare_entry("Grading distance", "2", Double(0.5, 100),
                      "A cell is refined while it lies closer to the tip than this many of its own "
                      "widths; larger values give more cells per ring. Units: cell widths.");
    prm.declare_entry("Cell aspect ratio", "1", Double(1, 1000),
                      "builtin only: cells above z = min(c, H/2) are stretched along z to this many "
                      "times their width; the tip zone keeps square cells. A stress test of the "
                      "mesh and the J rings. Units: none.");
    prm.declare_entry("Global refinements", "0", Integer(0, 10),
                      "Uniform refinements after the grading (h-convergence). Units: none.");
    prm.declare_entry("Mesh file", "../meshes/penny-gap.geo", FileName(),
                      "gmsh .geo or .msh file (relative paths start at the parameter file's folder). "
                      "Physical tags: surface 1 = solid; curves 1 = axis r = 0, 2 = gap face "
                      "z = 0 r < c, 3 = ligament z = 0 r > c, 4 = far boundary.");
    prm.leave_subsection();
  }

  void MeshParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    generator          = to_enum(generators, prm.get("Generator"));
    tip_levels         = prm.get_integer("Tip refinement levels");
    gap_face_levels    = prm.get_integer("Gap face levels");
    grading_distance   = prm.get_double("Grading distance");
    global_refinements = prm.get_integer("Global refinements");
    cell_aspect_ratio  = prm.get_double("Cell aspect ratio");
    mesh_file          = prm.get("Mesh file");
    prm.leave_subsection();
  }

  void FiniteElementParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    prm.declare_entry("Polynomial degree", "4", Integer(1, 8),
                      "Degree of the continuous Lagrange elements for (u_r, u_z). Units: none.");
    prm.declare_entry("Degree grading", "0", Integer(0, 64),
                      "Penny and periodic gaps: tip refinement levels per step down in degree. "
                      "Cells b/2^k wide (b = c, or min(c, lambda/2 - c) for the periodic gap) get "
                      "degree max(1, degree - floor(k / this)), so the small cells near the tip "
                      "carry low degrees (hp); 0 keeps the degree on every cell. Units: levels.");
    prm.leave_subsection();
  }

  void FiniteElementParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    degree            = prm.get_integer("Polynomial degree");
    levels_per_degree = prm.get_integer("Degree grading");
    prm.leave_subsection();
  }

  void LinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry(
        "Type", "direct", selection(solvers),
        "direct: sparse Cholesky (CHOLMOD) on one MPI rank, sparse LU (MUMPS through "
        "Trilinos Amesos) on several. cg-amg: conjugate gradients preconditioned with Trilinos' algebraic "
        "multigrid, for large meshes.");
    prm.declare_entry("Tolerance", "1e-9", Double(0, 1),
                      "Relative residual |A u - b|/|b| the iterative solver must reach; a direct "
                      "solve that misses it is an error too. Units: none.");
    prm.declare_entry("Maximum iterations", "10000", Integer(1),
                      "Iteration limit of the iterative solver. Units: none.");
    prm.leave_subsection();
  }

  void LinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    type           = to_enum(solvers, prm.get("Type"));
    tolerance      = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
    require(tolerance > 0, "Linear solver/Tolerance", tolerance, "(0, 1]");
  }

  void JIntegralParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("J-integral");
    prm.declare_entry("Ring radii", "0.25, 0.5, 0.75", List(Double(0, 1), 1),
                      "Outer radii of the J-integral domains around the tip, weight "
                      "q = (1 - (d/rho)^2)^4. Open range (0, 1). Units: c.");
    prm.leave_subsection();
  }

  void JIntegralParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("J-integral");
    ring_radii = get_doubles(prm, "Ring radii");
    prm.leave_subsection();
    for (const double rho : ring_radii)
      require(rho > 0 && rho < 1, "J-integral/Ring radii", rho, "(0, 1)");
  }
} // namespace penny
