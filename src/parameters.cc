#include "parameters.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <sstream>

namespace penny
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::FileName;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::Selection;
  using dealii::Patterns::Anything;

  namespace
  {
    constexpr double max_double = std::numeric_limits<double>::max();

    // Throws the one-line error for an entry whose value lies outside `range`.
    void require(const bool         ok,
                 const std::string &entry,
                 const double       value,
                 const std::string &range)
    {
      if (!ok)
        {
          std::ostringstream message;
          message.precision(17);
          message << entry << " = " << value << " is outside the allowed range " << range;
          throw InputError(message.str());
        }
    }

    // deal.II's exception text spans several lines; keep its explanation only.
    std::string one_line(const dealii::ExceptionBase &exception)
    {
      std::ostringstream info;
      exception.print_info(info);
      std::string text = info.str();
      std::replace(text.begin(), text.end(), '\n', ' ');
      text.erase(0, text.find_first_not_of(' '));
      std::string collapsed;
      for (const char ch : text)
        if (!(ch == ' ' && !collapsed.empty() && collapsed.back() == ' '))
          collapsed += ch;
      while (!collapsed.empty() && collapsed.back() == ' ')
        collapsed.pop_back();
      return collapsed;
    }
  } // namespace

  void GeometryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Gap radius c", "1", Double(0), "Radius of the penny-shaped gap (crack). Units: m.");
    prm.declare_entry("Domain radius R", "1000", Double(0),
                      "Radius of the truncated cylinder; must exceed c. Its effect on K_I shrinks "
                      "roughly like (c/R)^3. Units: m.");
    prm.declare_entry("Domain height H", "1000", Double(0),
                      "Height of the half model z >= 0. Units: m.");
    prm.declare_entry("Far boundary", "free", Selection("free|clamped"),
                      "Condition on r = R and z = H: traction free, or clamped (u = 0).");
    prm.leave_subsection();
  }

  void GeometryParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    gap_radius    = prm.get_double("Gap radius c");
    domain_radius = prm.get_double("Domain radius R");
    domain_height = prm.get_double("Domain height H");
    clamped_far_boundary = prm.get("Far boundary") == "clamped";
    prm.leave_subsection();
    require(gap_radius > 0, "Geometry/Gap radius c", gap_radius, "(0, Domain radius R)");
    require(domain_radius > gap_radius, "Geometry/Domain radius R", domain_radius,
            "(Gap radius c = " + dealii::Utilities::to_string(gap_radius) + ", inf)");
    require(domain_height > 0, "Geometry/Domain height H", domain_height, "(0, inf)");
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
    prm.declare_entry("Young's modulus E", "1e9", Double(0), "Isotropic linear elasticity. Units: Pa.");
    prm.declare_entry("Poisson's ratio nu", "0.3", Double(-1, 0.5),
                      "Open range (-1, 0.5). Units: none.");
    prm.leave_subsection();
  }

  void MaterialParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus E");
    poissons_ratio = prm.get_double("Poisson's ratio nu");
    prm.leave_subsection();
    require(youngs_modulus > 0, "Material/Young's modulus E", youngs_modulus, "(0, inf)");
    require(poissons_ratio > -1 && poissons_ratio < 0.5, "Material/Poisson's ratio nu",
            poissons_ratio, "(-1, 0.5)");
  }

  void LoadParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Load");
    prm.declare_entry("Type", "uniform", Selection("uniform|parabolic|expression"),
                      "Face traction p(r) opening the gap: uniform p = P; parabolic (Bueckner) "
                      "p = P (1 - r^2/a^2); expression: any p(r) in 'Expression'.");
    prm.declare_entry("Peak tension P", "1e6", Double(-max_double, max_double),
                      "P: the uniform value, or the peak of the parabola at r = 0. Units: Pa.");
    prm.declare_entry("Parabola given by", "a", Selection("a|R_p"),
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
    const std::string type_name = prm.get("Type");
    type         = type_name == "uniform"   ? Type::uniform :
                   type_name == "parabolic" ? Type::parabolic :
                                              Type::expression;
    peak_tension = prm.get_double("Peak tension P");
    summit_radius = prm.get_double("Summit radius R_p");
    require(summit_radius > 0, "Load/Summit radius R_p", summit_radius, "(0, inf)");
    if (prm.get("Parabola given by") == "a")
      tension_radius = prm.get_double("Tension radius a");
    else
      {
        require(peak_tension > 0, "Load/Peak tension P", peak_tension,
                "(0, inf) when the parabola is given by R_p");
        tension_radius = std::sqrt(2 * summit_radius * peak_tension);
      }
    expression = prm.get("Expression");
    prm.leave_subsection();
    require(tension_radius > 0, "Load/Tension radius a", tension_radius, "(0, inf)");
  }

  void AdhesionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Adhesion");
    prm.declare_entry("Critical stress intensity K_Ic", "1.28e6", Double(0),
                      "Toughness of the interface: an adhesive gap is in equilibrium at K_I = K_Ic "
                      "(K_Ic = sqrt(E' G_c)). The load's summit radius R_p sets the parabola. "
                      "Units: Pa m^1/2.");
    prm.declare_entry("Smallest c_hat", "0.3", Double(0),
                      "Gap-tension curve: smallest c/c_min. Units: none.");
    prm.declare_entry("Largest c_hat", "4", Double(0),
                      "Gap-tension curve: largest c/c_min. Units: none.");
    prm.declare_entry("Number of points", "24", Integer(2, 1000),
                      "Gap-tension curve: points, evenly spaced in c_hat. Units: none.");
    prm.leave_subsection();
  }

  void AdhesionParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Adhesion");
    critical_stress_intensity = prm.get_double("Critical stress intensity K_Ic");
    smallest_c_hat            = prm.get_double("Smallest c_hat");
    largest_c_hat             = prm.get_double("Largest c_hat");
    n_curve_points            = prm.get_integer("Number of points");
    prm.leave_subsection();
    require(critical_stress_intensity > 0, "Adhesion/Critical stress intensity K_Ic", critical_stress_intensity, "(0, inf)");
    require(smallest_c_hat > 0, "Adhesion/Smallest c_hat", smallest_c_hat, "(0, Largest c_hat)");
    require(largest_c_hat > smallest_c_hat, "Adhesion/Largest c_hat", largest_c_hat, "(Smallest c_hat, inf)");
  }

  void MeshParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Generator", "builtin", Selection("builtin|gmsh"),
                      "builtin: quadtree of square cells, the tip at a vertex, graded geometrically "
                      "(ratio 2) towards the tip and growing to R and H. gmsh: read 'Mesh file'.");
    prm.declare_entry("Tip refinement levels", "30", Integer(0, 40),
                      "Cells at the tip are c / 2^levels wide. Units: none.");
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
    generator          = prm.get("Generator") == "gmsh" ? Generator::gmsh : Generator::builtin;
    tip_levels         = prm.get_integer("Tip refinement levels");
    grading_distance   = prm.get_double("Grading distance");
    global_refinements = prm.get_integer("Global refinements");
    cell_aspect_ratio  = prm.get_double("Cell aspect ratio");
    mesh_file          = prm.get("Mesh file");
    prm.leave_subsection();
  }

  void FiniteElementParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    prm.declare_entry("Polynomial degree", "4", Integer(1, 4),
                      "Degree of the continuous Lagrange elements for (u_r, u_z). Units: none.");
    prm.leave_subsection();
  }

  void FiniteElementParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    degree = prm.get_integer("Polynomial degree");
    prm.leave_subsection();
  }

  void LinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type", "direct", Selection("direct|cg-amg"),
                      "direct: sparse LU (UMFPACK). cg-amg: conjugate gradients preconditioned "
                      "with Trilinos' algebraic multigrid, for large meshes.");
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
    type           = prm.get("Type") == "direct" ? Type::direct : Type::cg_amg;
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
    ring_radii = dealii::Utilities::string_to_double(
      dealii::Utilities::split_string_list(prm.get("Ring radii")));
    prm.leave_subsection();
    for (const double rho : ring_radii)
      require(rho > 0 && rho < 1, "J-integral/Ring radii", rho, "(0, 1)");
  }

  void OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", FileName(FileName::output),
                      "Folder for results; created if missing (relative to the working folder).");
    prm.declare_entry("Write fields", "true", Bool(),
                      "Write VTU files with a PVD record for ParaView.");
    prm.leave_subsection();
  }

  void OutputParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory    = prm.get("Directory");
    write_fields = prm.get_bool("Write fields");
    prm.leave_subsection();
  }

  void ConvergenceParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence");
    prm.declare_entry("Strategy", "tip-grading", Selection("uniform-h|tip-grading|degree|domain-size"),
                      "The sequence of the convergence scene: uniform-h, one more global refinement "
                      "per cycle of the scene's mesh; tip-grading, 'Tip levels step' more tip levels per "
                      "cycle from 'First tip levels'; degree, degree 1 to 4 on the scene's mesh; "
                      "domain-size, R/c = H/c from 10 to 1e4 at the scene's near-tip mesh.");
    prm.declare_entry("Cycles", "4", Integer(1, 30), "Number of discretisations. Units: none.");
    prm.declare_entry("First tip levels", "4", Integer(0, 40), "tip-grading: levels of cycle 0. Units: none.");
    prm.declare_entry("Tip levels step", "4", Integer(1, 20), "tip-grading: levels added per cycle. Units: none.");
    prm.leave_subsection();
  }

  void ConvergenceParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence");
    const std::string name = prm.get("Strategy");
    strategy         = name == "uniform-h"   ? Strategy::uniform_h :
                       name == "tip-grading" ? Strategy::tip_grading :
                       name == "degree"      ? Strategy::degree :
                                               Strategy::domain_size;
    cycles           = prm.get_integer("Cycles");
    first_tip_levels = prm.get_integer("First tip levels");
    tip_levels_step  = prm.get_integer("Tip levels step");
    prm.leave_subsection();
    if (strategy == Strategy::degree)
      require(cycles <= 4, "Convergence/Cycles", cycles, "[1, 4] for Strategy = degree");
    if (strategy == Strategy::tip_grading)
      require(first_tip_levels + (cycles - 1) * tip_levels_step <= 40, "Convergence/Cycles", cycles,
              "[1, 1 + (40 - First tip levels)/Tip levels step]");
  }

  void StabilityParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Stability");
    prm.declare_entry("Target accuracy", "1e-5", Double(0, 1),
                      "Relative K_I error a case of the stability scene must reach to pass; a case "
                      "expected to miss it is flagged with the reason. Units: none.");
    prm.leave_subsection();
  }

  void StabilityParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Stability");
    target_accuracy = prm.get_double("Target accuracy");
    prm.leave_subsection();
  }

  void Parameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Scene", "penny-gap",
                      Selection("penny-gap|gap-size-adhesionless|adhesive-minimum|gap-tension-curve|"
                                "adhesive-equilibrium|stability|convergence"),
                      "penny-gap: one FE solve of the load in 'Load', K_I from J-integrals (and signed "
                      "K_I) on every ring beside Sneddon's closed form, face opening and gap volume. "
                      "gap-size-adhesionless: the gap radius c where the FE K_I of the parabola (P, a) "
                      "vanishes. adhesive-minimum: the minimum over c of the FE tension P(c) at "
                      "K_I = K_Ic for the summit radius R_p, giving psi and c_min. gap-tension-curve: "
                      "p_hat(c_hat) from FE. adhesive-equilibrium: the FE gap radius on the stable "
                      "branch for the peak tension P. The c-searches keep R/c and H/c of 'Geometry'. "
                      "stability: stiff and extreme cases around these parameters in one table. "
                      "convergence: this scene over the sequence of discretisations in 'Convergence'.");
    GeometryParameters::declare(prm);
    MaterialParameters::declare(prm);
    LoadParameters::declare(prm);
    AdhesionParameters::declare(prm);
    MeshParameters::declare(prm);
    FiniteElementParameters::declare(prm);
    LinearSolverParameters::declare(prm);
    JIntegralParameters::declare(prm);
    OutputParameters::declare(prm);
    StabilityParameters::declare(prm);
    ConvergenceParameters::declare(prm);
  }

  void Parameters::parse(ParameterHandler &prm)
  {
    scene = prm.get("Scene");
    geometry.parse(prm);
    material.parse(prm);
    load.parse(prm);
    adhesion.parse(prm);
    mesh.parse(prm);
    finite_element.parse(prm);
    linear_solver.parse(prm);
    j_integral.parse(prm);
    output.parse(prm);
    stability.parse(prm);
    convergence.parse(prm);

    const double c          = geometry.gap_radius;
    const double room       = std::min(geometry.domain_height, geometry.domain_radius - c);
    const double max_radius = *std::max_element(j_integral.ring_radii.begin(),
                                                j_integral.ring_radii.end());
    require(max_radius * c < room, "J-integral/Ring radii", max_radius,
            "(0, min(H, R - c)/c = " + dealii::Utilities::to_string(room / c) + ")");
  }

  Parameters Parameters::read(const std::string &filename, ParameterHandler &prm)
  {
    if (!std::filesystem::is_regular_file(filename))
      throw InputError("parameter file '" + filename + "' does not exist or is not a file");
    declare(prm);
    try
      {
        prm.parse_input(filename);
      }
    catch (const dealii::ExceptionBase &exception)
      {
        throw InputError(one_line(exception));
      }
    Parameters parameters;
    parameters.parse(prm);

    // A relative mesh path is read from the parameter file's folder.
    const std::filesystem::path mesh_path(parameters.mesh.mesh_file);
    if (mesh_path.is_relative())
      parameters.mesh.mesh_file =
        (std::filesystem::path(filename).parent_path() / mesh_path).lexically_normal().string();
    if (parameters.mesh.generator == MeshParameters::Generator::gmsh &&
        !std::filesystem::is_regular_file(parameters.mesh.mesh_file))
      throw InputError("Mesh/Mesh file = '" + parameters.mesh.mesh_file +
                       "' does not exist (expected a gmsh .geo or .msh file)");
    return parameters;
  }
} // namespace penny
