// Parameters that describe what a scene computes rather than the model it
// solves: adhesion, the sequences of the convergence and stability scenes,
// the gap-tension curve and the output folder. Entries that only one scene
// reads live in that scene's own subsection.
#pragma once

#include "input/fe_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace penny
{
  struct AdhesionParameters
  {
    double critical_stress_intensity; // K_Ic (Pa m^1/2), given or sqrt(E' G_c)

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm, const MaterialParameters &material);
  };

  // The gap-tension curve scene: p_hat against c_hat = c/c_min.
  struct GapTensionCurveParameters
  {
    double       smallest_c_hat, largest_c_hat;
    unsigned int n_points;

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

  // The scenes that compare FE results with closed forms give a verdict.
  struct VerificationParameters
  {
    double tolerance; // largest relative error of a PASS

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct StabilityParameters
  {
    double target_accuracy; // relative K_I error a stability case must reach

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct OutputParameters
  {
    std::string directory;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // Scenes that solve one gap can write its fields for ParaView.
  struct FieldParameters
  {
    bool write_fields;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace penny
