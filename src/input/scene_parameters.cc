#include "input/scene_parameters.h"

#include "input/input_error.h"
#include "input/parameter_parsing.h"

#include <cmath>

namespace penny
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::FileName;
  using dealii::Patterns::Integer;

  namespace
  {
    const EnumNames<bool> toughness_forms = {{"K_Ic", false}, {"G_c", true}};

    using Strategy                       = ConvergenceParameters::Strategy;
    const EnumNames<Strategy> strategies = {{"uniform-h", Strategy::uniform_h},
                                            {"tip-grading", Strategy::tip_grading},
                                            {"degree", Strategy::degree},
                                            {"domain-size", Strategy::domain_size},
                                            {"adaptive", Strategy::adaptive}};
  } // namespace

  void AdhesionParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Adhesion");
    prm.declare_entry("Toughness given by", "K_Ic", selection(toughness_forms),
                      "K_Ic: 'Critical stress intensity K_Ic' as given; G_c: K_Ic = sqrt(E' G_c) "
                      "from 'Work of adhesion G_c' and the Material section.");
    prm.declare_entry("Critical stress intensity K_Ic", "1.28e6", Double(0),
                      "Toughness of the interface: an adhesive gap is in equilibrium at K_I = K_Ic. "
                      "The load's summit radius R_p sets the parabola. Units: Pa m^1/2.");
    prm.declare_entry("Work of adhesion G_c", "0.1", Double(0),
                      "Interface energy per area, used when the toughness is given by G_c. Units: J/m^2.");
    prm.leave_subsection();
  }

  void AdhesionParameters::parse(ParameterHandler &prm, const MaterialParameters &material)
  {
    prm.enter_subsection("Adhesion");
    if (!to_enum(toughness_forms, prm.get("Toughness given by")))
      critical_stress_intensity = prm.get_double("Critical stress intensity K_Ic");
    else
      {
        const double G_c = prm.get_double("Work of adhesion G_c");
        require(G_c > 0, "Adhesion/Work of adhesion G_c", G_c, "(0, inf)");
        critical_stress_intensity = std::sqrt(material.plane_strain_modulus() * G_c);
      }
    prm.leave_subsection();
    require(critical_stress_intensity > 0, "Adhesion/Critical stress intensity K_Ic",
            critical_stress_intensity, "(0, inf)");
  }

  void GapTensionCurveParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Gap-tension curve");
    prm.declare_entry("Smallest c_hat", "0.3", Double(0), "Smallest c/c_min. Units: none.");
    prm.declare_entry("Largest c_hat", "4", Double(0), "Largest c/c_min. Units: none.");
    prm.declare_entry("Number of points", "24", Integer(2, 1000),
                      "Points, evenly spaced in c_hat. Units: none.");
    prm.leave_subsection();
  }

  void GapTensionCurveParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Gap-tension curve");
    smallest_c_hat = prm.get_double("Smallest c_hat");
    largest_c_hat  = prm.get_double("Largest c_hat");
    n_points       = prm.get_integer("Number of points");
    prm.leave_subsection();
    require(smallest_c_hat > 0, "Gap-tension curve/Smallest c_hat", smallest_c_hat, "(0, Largest c_hat)");
    require(largest_c_hat > smallest_c_hat, "Gap-tension curve/Largest c_hat", largest_c_hat,
            "(Smallest c_hat, inf)");
  }

  void ConvergenceParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence");
    prm.declare_entry(
        "Strategy", "tip-grading", selection(strategies),
        "The sequence of the convergence scene: uniform-h, one more global refinement "
        "per cycle of the scene's mesh; tip-grading, 'Tip levels step' more tip levels per "
        "cycle from 'First tip levels'; degree, degree 1 to 4 on the scene's mesh; "
        "domain-size, R/c = H/c from 10 to 1e4 at the scene's near-tip mesh; adaptive, from the "
        "mesh with 'First tip levels', each cycle refines the 'Refined fraction' of cells with the "
        "largest Kelly error indicators of the displacement.");
    prm.declare_entry("Cycles", "4", Integer(1, 30), "Number of discretisations. Units: none.");
    prm.declare_entry("First tip levels", "4", Integer(0, 40),
                      "tip-grading: levels of cycle 0. Units: none.");
    prm.declare_entry("Tip levels step", "4", Integer(1, 20),
                      "tip-grading: levels added per cycle. Units: none.");
    prm.declare_entry("Refined fraction", "0.1", Double(0, 1),
                      "adaptive: share of the cells, those with the largest Kelly indicators, refined per "
                      "cycle. Open range (0, 1]. Units: none.");
    prm.leave_subsection();
  }

  void ConvergenceParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence");
    strategy         = to_enum(strategies, prm.get("Strategy"));
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

  void VerificationParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    prm.declare_entry(
        "Tolerance", "1e-6", Double(0),
        "The largest relative error against the closed forms that passes: K_I on every ring, w(0) "
        "and the gap volume (penny-gap); c/a, psi, p_hat or c_t (the adhesion scenes); K_I on every "
        "ring (periodic-gap), p_bar/p* (westergaard-curve, johnson-curves), the critical alpha and "
        "the jump into contact (jump-into-contact). A run that "
        "misses it prints FAIL and exits with status 1. Units: none.");
    prm.leave_subsection();
  }

  void VerificationParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    tolerance = prm.get_double("Tolerance");
    prm.leave_subsection();
    require(tolerance > 0, "Verification/Tolerance", tolerance, "(0, inf)");
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

  void OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", FileName(FileName::output),
                      "Folder for results; created if missing (relative to the working folder).");
    prm.leave_subsection();
  }

  void OutputParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    prm.leave_subsection();
  }

  void FieldParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Fields");
    prm.declare_entry("Write fields", "true", Bool(), "Write VTU files with a PVD record for ParaView.");
    prm.leave_subsection();
  }

  void FieldParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Fields");
    write_fields = prm.get_bool("Write fields");
    prm.leave_subsection();
  }
} // namespace penny
