// How far a computed value lies from its reference.
#pragma once

#include <cmath>

namespace penny
{
  // |value/reference - 1|, or |value| against a zero reference.
  inline double relative_error(const double value, const double reference)
  {
    return reference == 0 ? std::abs(value) : std::abs(value / reference - 1);
  }
} // namespace penny
