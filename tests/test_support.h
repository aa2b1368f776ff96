// Shared set-up for the unit tests: parameters at their declared defaults.
#pragma once

#include "parameters.h"

inline penny::Parameters default_parameters()
{
  dealii::ParameterHandler prm;
  penny::Parameters::declare(prm);
  penny::Parameters parameters;
  parameters.parse(prm);
  return parameters;
}
