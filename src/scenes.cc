#include "scenes.h"

#include "adhesion_scenes.h"
#include "contact_scenes.h"
#include "convergence_scene.h"
#include "output_files.h"
#include "penny_scene.h"
#include "stability_scene.h"

namespace penny
{
  // Checks the output folder first and records the parameters last, so a run
  // that fails writes nothing.
  void run_scene(const Parameters &parameters, const dealii::ParameterHandler &prm, std::ostream &log)
  {
    const std::filesystem::path directory(parameters.output.directory);
    prepare_output_directory(directory);

    if (parameters.scene == "penny-gap")
      run_penny_scene(parameters, log);
    else if (parameters.scene == "gap-size-adhesionless")
      run_gap_size_scene(parameters, log);
    else if (parameters.scene == "adhesive-minimum")
      run_adhesive_minimum_scene(parameters, log);
    else if (parameters.scene == "gap-tension-curve")
      run_gap_tension_curve_scene(parameters, log);
    else if (parameters.scene == "adhesive-equilibrium")
      run_adhesive_equilibrium_scene(parameters, log);
    else if (parameters.scene == "stability")
      run_stability_scene(parameters, log);
    else if (parameters.scene == "convergence")
      run_convergence_scene(parameters, log);
    else if (parameters.scene == "sinusoid-contact")
      run_sinusoid_contact_scene(parameters, log);
    else if (parameters.scene == "zero-load-gap-area")
      run_zero_load_gap_area_scene(parameters, log);
    else if (parameters.scene == "area-load")
      run_area_load_scene(parameters, log);
    else if (parameters.scene == "rough-surface")
      run_rough_surface_scene(parameters, log);
    else if (parameters.scene == "magnification-scaling")
      run_magnification_scaling_scene(parameters, log);
    else if (parameters.scene == "fe-gap-area")
      run_fe_gap_area_scene(parameters, log);
    else
      throw InputError("Scene = '" + parameters.scene + "' has no implementation");

    write_atomically(directory / "parameters.prm",
                     [&](std::ostream &out) { prm.print_parameters(out, dealii::ParameterHandler::PRM); });
  }
} // namespace penny
