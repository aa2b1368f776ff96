// Parameters of the finite-element model of one penny gap, one struct per
// subsection of the parameter file (the step-44 pattern). Every entry is
// declared with a pattern, a doc string and its units; parse() also checks
// the ranges and cross-entry conditions a pattern cannot express, and throws
// InputError with one line that names the entry and the allowed range.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace penny
{
  struct GeometryParameters
  {
    double gap_radius;           // c (m)
    double domain_radius;        // R (m)
    double domain_height;        // H (m)
    bool   clamped_far_boundary; // u = 0 on r = R and z = H, else traction free

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct MaterialParameters
  {
    double youngs_modulus; // E (Pa)
    double poissons_ratio; // nu

    double plane_strain_modulus() const; // E' = E/(1 - nu^2) (Pa)
    double lame_lambda() const;          // Pa
    double lame_mu() const;              // Pa

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

  struct MeshParameters
  {
    enum class Generator
    {
      builtin,
      gmsh
    };
    Generator    generator;
    unsigned int tip_levels;       // refinement levels below cell size c at the tip
    unsigned int gap_face_levels;  // cells over the gap face are at most c/2^levels wide
    double       grading_distance; // refine a cell closer to the tip than this many cell sizes
    unsigned int global_refinements;
    double       cell_aspect_ratio; // builtin cells are this many times taller than wide
    std::string  mesh_file;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct FiniteElementParameters
  {
    unsigned int degree;
    // Cells c/2^k wide get degree max(1, degree - floor(k / levels_per_degree));
    // 0: the degree on every cell.
    unsigned int levels_per_degree;

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

  struct JIntegralParameters
  {
    std::vector<double> ring_radii; // in units of c

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace penny
