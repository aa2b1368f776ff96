#include "scenes.h"

#include "penny_scene.h"

namespace penny
{
  void run_scene(const Parameters &parameters, const dealii::ParameterHandler &prm, std::ostream &log)
  {
    if (parameters.scene == "penny-gap")
      run_penny_scene(parameters, prm, log);
    else
      throw InputError("Scene = '" + parameters.scene + "' has no implementation");
  }
} // namespace penny
