// Runs the scene a parameter file names in its 'Scene' entry.
#pragma once

#include "parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <ostream>

namespace penny
{
  void run_scene(const Parameters &parameters, const dealii::ParameterHandler &prm, std::ostream &log);
} // namespace penny
