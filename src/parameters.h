// Run-time parameters of a penny-gap scene, one struct per subsection of the
// parameter file (the step-44 pattern). Every entry is declared with a
// pattern, a doc string and its units; parse() also checks the ranges and the
// cross-entry conditions a pattern cannot express, and throws InputError with
// one line that names the entry and the allowed range.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace penny
{
  // Bad input: the message is one line, meant to be shown to the user as is.
  struct InputError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  struct GeometryParameters
  {
    double gap_radius;    // c (m)
    double domain_radius; // R (m)
    double domain_height; // H (m)
    bool   clamped_far_boundary; // u = 0 on r = R and z = H, else traction free

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct MaterialParameters
  {
    double youngs_modulus; // E (Pa)
    double poissons_ratio; // nu

    double plane_strain_modulus() const; // E' = E/(1 - nu^2)
    double lame_lambda() const;
    double lame_mu() const;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct LoadParameters
  {
    enum class Type
    {
      uniform,
      parabolic,
      expression
    };
    Type        type;
    double      peak_tension;   // P (Pa)
    double      tension_radius; // a (m); for a parabola given by R_p, a^2 = 2 R_p P
    std::string expression;     // p(r) in Pa, r in m
    double      summit_radius;  // R_p (m^2/Pa), a^2 = 2 R_p P

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct AdhesionParameters
  {
    double critical_stress_intensity; // K_Ic (Pa m^1/2), given or sqrt(E' G_c)
    double smallest_c_hat, largest_c_hat; // range of the gap-tension curve, c/c_min
    unsigned int n_curve_points;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm, const MaterialParameters &material);
  };

  // The rough surface of the statistical layer: its height PSD.
  struct RoughnessParameters
  {
    enum class Spectrum
    {
      power_law,
      file
    };
    Spectrum    spectrum;
    double      hurst;      // H
    double      q0;         // long-wavelength cut-off (1/m)
    double      zeta;       // magnification q1/q0
    double      amplitude;  // h0 (m) of the power law
    std::string spectrum_file;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // Area-load curves aggregated over the Gaussian field of pressure summits.
  struct AreaLoadParameters
  {
    bool                convention_is_paper;
    double              smallest_mean_pressure, largest_mean_pressure; // p_bar/sqrt(V)
    unsigned int        n_points;
    std::vector<double> hurst_exponents, magnifications;
    double              largest_adhesion_ratio; // zero-load-gap-area: largest p0/sqrt(V)
    double              adhesion_ratio;         // fe-gap-area: p0/sqrt(V)
    unsigned int        n_tabulated_tensions;   // fe-gap-area: FE g at this many P
    double              first_fit_magnification, last_fit_magnification;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct SinusoidParameters
  {
    std::vector<double> alphas; // Johnson's adhesion parameters
    unsigned int        n_points;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct ConvergenceParameters
  {
    enum class Strategy
    {
      uniform_h,
      tip_grading,
      degree,
      domain_size,
      adaptive
    };
    Strategy     strategy;
    unsigned int cycles;
    unsigned int first_tip_levels, tip_levels_step;
    double       refined_fraction; // adaptive: share of cells refined per cycle

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct StabilityParameters
  {
    double target_accuracy; // relative K_I error a stability case must reach

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct MeshParameters
  {
    enum class Generator
    {
      builtin,
      gmsh
    };
    Generator    generator;
    unsigned int tip_levels;        // refinement levels below cell size c at the tip
    double       grading_distance;  // refine a cell closer to the tip than this many cell sizes
    unsigned int global_refinements;
    double       cell_aspect_ratio; // builtin cells are this many times taller than wide
    std::string  mesh_file;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct FiniteElementParameters
  {
    unsigned int degree;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct LinearSolverParameters
  {
    enum class Type
    {
      direct,
      cg_amg
    };
    Type         type;
    double       tolerance;
    unsigned int max_iterations;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // "UMFPACK" (one MPI rank), "MUMPS" (several) or "CG + AMG".
  std::string solver_name(const LinearSolverParameters &solver);

  struct JIntegralParameters
  {
    std::vector<double> ring_radii; // in units of c

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct OutputParameters
  {
    std::string directory;
    bool        write_fields;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct Parameters
  {
    // What the run computes; each scene reads only the subsections it needs.
    std::string scene;

    GeometryParameters      geometry;
    MaterialParameters      material;
    LoadParameters          load;
    AdhesionParameters      adhesion;
    MeshParameters          mesh;
    FiniteElementParameters finite_element;
    LinearSolverParameters  linear_solver;
    JIntegralParameters     j_integral;
    OutputParameters        output;
    StabilityParameters     stability;
    ConvergenceParameters   convergence;
    RoughnessParameters     roughness;
    AreaLoadParameters      area_load;
    SinusoidParameters      sinusoid;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);

    // Reads and checks a parameter file; any problem is an InputError.
    static Parameters read(const std::string &filename, dealii::ParameterHandler &prm);
  };
} // namespace penny
