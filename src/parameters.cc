#include "parameters.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
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
    prm.declare_entry("Toughness given by", "K_Ic", Selection("K_Ic|G_c"),
                      "K_Ic: 'Critical stress intensity K_Ic' as given; G_c: K_Ic = sqrt(E' G_c) "
                      "from 'Work of adhesion G_c' and the Material section.");
    prm.declare_entry("Critical stress intensity K_Ic", "1.28e6", Double(0),
                      "Toughness of the interface: an adhesive gap is in equilibrium at K_I = K_Ic. "
                      "The load's summit radius R_p sets the parabola. Units: Pa m^1/2.");
    prm.declare_entry("Work of adhesion G_c", "0.1", Double(0),
                      "Interface energy per area, used when the toughness is given by G_c. Units: J/m^2.");
    prm.declare_entry("Smallest c_hat", "0.3", Double(0),
                      "Gap-tension curve: smallest c/c_min. Units: none.");
    prm.declare_entry("Largest c_hat", "4", Double(0),
                      "Gap-tension curve: largest c/c_min. Units: none.");
    prm.declare_entry("Number of points", "24", Integer(2, 1000),
                      "Gap-tension curve: points, evenly spaced in c_hat. Units: none.");
    prm.leave_subsection();
  }

  void AdhesionParameters::parse(ParameterHandler &prm, const MaterialParameters &material)
  {
    prm.enter_subsection("Adhesion");
    if (prm.get("Toughness given by") == "K_Ic")
      critical_stress_intensity = prm.get_double("Critical stress intensity K_Ic");
    else
      {
        const double G_c = prm.get_double("Work of adhesion G_c");
        require(G_c > 0, "Adhesion/Work of adhesion G_c", G_c, "(0, inf)");
        critical_stress_intensity = std::sqrt(material.plane_strain_modulus() * G_c);
      }
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
                      "direct: sparse LU, UMFPACK on one MPI rank and MUMPS (Trilinos Amesos) on "
                      "several. cg-amg: conjugate gradients preconditioned with Trilinos' algebraic "
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
    type           = prm.get("Type") == "direct" ? Type::direct : Type::cg_amg;
    tolerance      = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
    require(tolerance > 0, "Linear solver/Tolerance", tolerance, "(0, 1]");
  }

  std::string solver_name(const LinearSolverParameters &solver)
  {
    if (solver.type == LinearSolverParameters::Type::cg_amg)
      return "CG + AMG";
    return dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1 ? "UMFPACK" : "MUMPS";
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
    prm.declare_entry("Strategy", "tip-grading", Selection("uniform-h|tip-grading|degree|domain-size|adaptive"),
                      "The sequence of the convergence scene: uniform-h, one more global refinement "
                      "per cycle of the scene's mesh; tip-grading, 'Tip levels step' more tip levels per "
                      "cycle from 'First tip levels'; degree, degree 1 to 4 on the scene's mesh; "
                      "domain-size, R/c = H/c from 10 to 1e4 at the scene's near-tip mesh; adaptive, from the "
                      "mesh with 'First tip levels', each cycle refines the 'Refined fraction' of cells with the "
                      "largest Kelly error indicators of the displacement.");
    prm.declare_entry("Cycles", "4", Integer(1, 30), "Number of discretisations. Units: none.");
    prm.declare_entry("First tip levels", "4", Integer(0, 40), "tip-grading: levels of cycle 0. Units: none.");
    prm.declare_entry("Tip levels step", "4", Integer(1, 20), "tip-grading: levels added per cycle. Units: none.");
    prm.declare_entry("Refined fraction", "0.1", Double(0, 1),
                      "adaptive: share of the cells, those with the largest Kelly indicators, refined per "
                      "cycle. Open range (0, 1]. Units: none.");
    prm.leave_subsection();
  }

  void ConvergenceParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence");
    const std::string name = prm.get("Strategy");
    strategy         = name == "uniform-h"   ? Strategy::uniform_h :
                       name == "tip-grading" ? Strategy::tip_grading :
                       name == "degree"      ? Strategy::degree :
                       name == "domain-size" ? Strategy::domain_size :
                                               Strategy::adaptive;
    cycles           = prm.get_integer("Cycles");
    first_tip_levels = prm.get_integer("First tip levels");
    tip_levels_step  = prm.get_integer("Tip levels step");
    refined_fraction = prm.get_double("Refined fraction");
    prm.leave_subsection();
    require(refined_fraction > 0, "Convergence/Refined fraction", refined_fraction, "(0, 1]");
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

  void RoughnessParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Roughness");
    prm.declare_entry("Spectrum", "power-law", Selection("power-law|file"),
                      "Isotropic height PSD C(q): the paper's power law (H/2pi) (h0/q0)^2 (q/q0)^(-2(H+1)) "
                      "on q0 <= q <= zeta q0, or the table in 'Spectrum file'.");
    prm.declare_entry("Hurst exponent H", "0.75", Double(0, 1), "Open range (0, 1). Units: none.");
    prm.declare_entry("Long-wavelength cut-off q0", "6283.185307179586", Double(0),
                      "Smallest wavenumber of the power law, q0 = 2 pi/lambda0. Units: 1/m.");
    prm.declare_entry("Magnification zeta", "1000", Double(1),
                      "q1/q0, the bandwidth of the power law; above 1. Units: none.");
    prm.declare_entry("Amplitude given by", "h0/lambda0", Selection("h0/lambda0|rms height"),
                      "h0/lambda0: h0 = (h0/lambda0) 2 pi/q0; rms height: h0 such that sqrt(m0) is the "
                      "'Rms height'.");
    prm.declare_entry("Amplitude h0/lambda0", "0.01", Double(0), "Units: none.");
    prm.declare_entry("Rms height", "1e-6", Double(0), "sqrt(m0) of the power law. Units: m.");
    prm.declare_entry("Spectrum file", "psd.txt", FileName(),
                      "Two columns q (1/m, increasing) and C(q) (m^4), '#' comments; log-log linear between "
                      "rows (relative paths start at the parameter file's folder).");
    prm.leave_subsection();
  }

  void RoughnessParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Roughness");
    spectrum      = prm.get("Spectrum") == "file" ? Spectrum::file : Spectrum::power_law;
    hurst         = prm.get_double("Hurst exponent H");
    q0            = prm.get_double("Long-wavelength cut-off q0");
    zeta          = prm.get_double("Magnification zeta");
    spectrum_file = prm.get("Spectrum file");
    const bool   from_ratio = prm.get("Amplitude given by") == "h0/lambda0";
    const double ratio = prm.get_double("Amplitude h0/lambda0"), rms = prm.get_double("Rms height");
    prm.leave_subsection();
    require(hurst > 0 && hurst < 1, "Roughness/Hurst exponent H", hurst, "(0, 1)");
    require(q0 > 0, "Roughness/Long-wavelength cut-off q0", q0, "(0, inf)");
    require(zeta > 1, "Roughness/Magnification zeta", zeta, "(1, inf)");
    require(from_ratio ? ratio > 0 : rms > 0, from_ratio ? "Roughness/Amplitude h0/lambda0" : "Roughness/Rms height",
            from_ratio ? ratio : rms, "(0, inf)");
    // m0 = h0^2 (1 - zeta^(-2H))/2 for the power law.
    amplitude = from_ratio ? ratio * 2 * M_PI / q0 : rms * std::sqrt(2 / (1 - std::pow(zeta, -2 * hurst)));
  }

  void AreaLoadParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Area-load");
    prm.declare_entry("Convention", "paper", Selection("paper|consistent"),
                      "paper: the paper's normalisations, prefactor 3 pi R_p eta sqrt(V) = sqrt(2 pi) and "
                      "p0/sqrt(V) = zeta^theta, theta = (2/5)(2H - 1). consistent: V, eta, R_p and p0 from the "
                      "moments of the Roughness spectrum (each H and zeta below replacing its own), the "
                      "Material and the Adhesion sections.");
    prm.declare_entry("Smallest mean pressure", "0", Double(-max_double, max_double),
                      "First p_bar/sqrt(V) of the curves (compression positive). Units: sqrt(V).");
    prm.declare_entry("Largest mean pressure", "3", Double(-max_double, max_double),
                      "Last p_bar/sqrt(V). Units: sqrt(V).");
    prm.declare_entry("Number of points", "61", Integer(2, 100000),
                      "Points of every curve, evenly spaced: mean pressures, or p0/sqrt(V) in "
                      "zero-load-gap-area. Units: none.");
    prm.declare_entry("Hurst exponents", "0.75, 0.5, 0.25", List(Double(0, 1), 1),
                      "area-load: one panel per H, open range (0, 1). Units: none.");
    prm.declare_entry("Magnifications", "1, 10, 100, 1000, 10000", List(Double(1), 1),
                      "area-load: one curve per zeta >= 1 (> 1 in the consistent convention). Units: none.");
    prm.declare_entry("Largest p0/sqrt(V)", "5", Double(0),
                      "zero-load-gap-area: p0/sqrt(V) runs from 0 to this value. Units: none.");
    prm.declare_entry("p0/sqrt(V)", "1", Double(0),
                      "fe-gap-area: adhesion of the gap population; sqrt(V) = p0/this, with p0 from Load/Summit "
                      "radius R_p and the Adhesion section. Units: none.");
    prm.declare_entry("Tabulated tensions", "20", Integer(3, 200),
                      "fe-gap-area: FE gap radii at this many peak tensions P = p0 + t^2 sqrt(V), Chebyshev "
                      "points in t. Units: none.");
    prm.declare_entry("Fit magnifications", "1e12, 1e16", List(Double(1), 2, 2),
                      "magnification-scaling: the zeta range of the least-squares fit of theta. Units: none.");
    prm.leave_subsection();
  }

  void AreaLoadParameters::parse(ParameterHandler &prm)
  {
    const auto doubles = [&](const std::string &entry) {
      return dealii::Utilities::string_to_double(dealii::Utilities::split_string_list(prm.get(entry)));
    };
    prm.enter_subsection("Area-load");
    convention_is_paper    = prm.get("Convention") == "paper";
    smallest_mean_pressure = prm.get_double("Smallest mean pressure");
    largest_mean_pressure  = prm.get_double("Largest mean pressure");
    n_points               = prm.get_integer("Number of points");
    hurst_exponents        = doubles("Hurst exponents");
    magnifications         = doubles("Magnifications");
    largest_adhesion_ratio = prm.get_double("Largest p0/sqrt(V)");
    adhesion_ratio         = prm.get_double("p0/sqrt(V)");
    n_tabulated_tensions   = prm.get_integer("Tabulated tensions");
    const auto fit         = doubles("Fit magnifications");
    first_fit_magnification = fit[0];
    last_fit_magnification  = fit[1];
    prm.leave_subsection();
    require(largest_mean_pressure > smallest_mean_pressure, "Area-load/Largest mean pressure", largest_mean_pressure,
            "(Smallest mean pressure, inf)");
    for (const double H : hurst_exponents)
      require(H > 0 && H < 1, "Area-load/Hurst exponents", H, "(0, 1)");
    for (const double zeta : magnifications)
      require(convention_is_paper ? zeta >= 1 : zeta > 1, "Area-load/Magnifications", zeta,
              convention_is_paper ? "[1, inf)" : "(1, inf) in the consistent convention");
    require(adhesion_ratio > 0, "Area-load/p0/sqrt(V)", adhesion_ratio, "(0, inf)");
    require(last_fit_magnification > first_fit_magnification && first_fit_magnification > 1,
            "Area-load/Fit magnifications", last_fit_magnification, "(first > 1, inf)");
  }

  void SinusoidParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Sinusoid");
    prm.declare_entry("Johnson parameters alpha", "0, 0.2, 0.4, 0.6", List(Double(0), 1),
                      "alpha^2 = 2 lambda dgamma/(pi^2 E* h^2) of Johnson's adhesive 1D sinusoid, one curve "
                      "each. Units: none.");
    prm.declare_entry("Number of points", "199", Integer(2, 100000),
                      "Contact semi-widths a/lambda, evenly spaced inside (0, 1/2). Units: none.");
    prm.leave_subsection();
  }

  void SinusoidParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Sinusoid");
    alphas   = dealii::Utilities::string_to_double(dealii::Utilities::split_string_list(prm.get("Johnson parameters alpha")));
    n_points = prm.get_integer("Number of points");
    prm.leave_subsection();
  }

  void Parameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Scene", "penny-gap",
                      Selection("penny-gap|gap-size-adhesionless|adhesive-minimum|gap-tension-curve|"
                                "adhesive-equilibrium|stability|convergence|sinusoid-contact|zero-load-gap-area|"
                                "area-load|rough-surface|magnification-scaling|fe-gap-area"),
                      "penny-gap: one FE solve of the load in 'Load', K_I from J-integrals (and signed "
                      "K_I) on every ring beside Sneddon's closed form, face opening and gap volume. "
                      "gap-size-adhesionless: the gap radius c where the FE K_I of the parabola (P, a) "
                      "vanishes. adhesive-minimum: the minimum over c of the FE tension P(c) at "
                      "K_I = K_Ic for the summit radius R_p, giving psi and c_min. gap-tension-curve: "
                      "p_hat(c_hat) from FE. adhesive-equilibrium: the FE gap radius on the stable "
                      "branch for the peak tension P. The c-searches keep R/c and H/c of 'Geometry'. "
                      "stability: stiff and extreme cases around these parameters in one table. "
                      "convergence: this scene over the sequence of discretisations in 'Convergence'. "
                      "Statistical layer, no FE: sinusoid-contact: Johnson's 1D sinusoid (paper Fig. 1); "
                      "zero-load-gap-area: A_nc/A_0 at p_bar = 0 against p0/sqrt(V) (Fig. 3); area-load: "
                      "A_nc/A_0 and A_c/A_0 against p_bar/sqrt(V) for each H and zeta (Figs. 4 and 5); "
                      "rough-surface: moments, summit statistics and p0 of the Roughness spectrum in both "
                      "conventions, and its area-load curve; magnification-scaling: theta fitted from the "
                      "moments for each H. fe-gap-area: the area-load curve with the FE g, tabulated from "
                      "FE solves, beside the closed-form g's.");
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
    RoughnessParameters::declare(prm);
    AreaLoadParameters::declare(prm);
    SinusoidParameters::declare(prm);
  }

  void Parameters::parse(ParameterHandler &prm)
  {
    scene = prm.get("Scene");
    geometry.parse(prm);
    material.parse(prm);
    load.parse(prm);
    adhesion.parse(prm, material);
    mesh.parse(prm);
    finite_element.parse(prm);
    linear_solver.parse(prm);
    j_integral.parse(prm);
    output.parse(prm);
    stability.parse(prm);
    convergence.parse(prm);
    roughness.parse(prm);
    area_load.parse(prm);
    sinusoid.parse(prm);

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

    // Relative file paths are read from the parameter file's folder.
    for (std::string *path : {&parameters.mesh.mesh_file, &parameters.roughness.spectrum_file})
      if (std::filesystem::path(*path).is_relative())
        *path = (std::filesystem::path(filename).parent_path() / *path).lexically_normal().string();
    if (parameters.roughness.spectrum == RoughnessParameters::Spectrum::file &&
        !std::filesystem::is_regular_file(parameters.roughness.spectrum_file))
      throw InputError("Roughness/Spectrum file = '" + parameters.roughness.spectrum_file +
                       "' does not exist (expected two columns q (1/m), C(q) (m^4))");
    if (parameters.mesh.generator == MeshParameters::Generator::gmsh &&
        !std::filesystem::is_regular_file(parameters.mesh.mesh_file))
      throw InputError("Mesh/Mesh file = '" + parameters.mesh.mesh_file +
                       "' does not exist (expected a gmsh .geo or .msh file)");
    return parameters;
  }
} // namespace penny
