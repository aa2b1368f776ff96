// How far a computed value lies from its reference.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace penny
{
  // |value/reference - 1|, or |value| against a zero reference.
  inline double relative_error(const double value, const double reference)
  {
    return reference == 0 ? std::abs(value) : std::abs(value / reference - 1);
  }

  // The larger of two errors, NaN if either is: an error that could not be
  // measured must fail every tolerance, where std::max would drop it.
  inline double worse(const double a, const double b)
  {
    return std::isnan(a) || std::isnan(b) ? std::nan("") : std::max(a, b);
  }

  // The largest relative_error(values[i], references[i]); 0 for empty lists.
  inline double largest_relative_error(const std::vector<double> &values,
                                       const std::vector<double> &references)
  {
    if (values.size() != references.size())
      throw std::invalid_argument("largest_relative_error: the lists differ in length");
    double worst = 0;
    for (std::size_t i = 0; i < values.size(); ++i)
      worst = worse(worst, relative_error(values[i], references[i]));
    return worst;
  }
} // namespace penny
