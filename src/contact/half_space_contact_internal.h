// Helpers shared by the files of HalfSpaceContact (half_space_contact.cc,
// constrained_conjugate_gradients.cc): sums over a grid split over ranks, and
// messages with numbers.
#pragma once

#include "fourier/fourier_transform.h"

#include <cstdio>
#include <numeric>
#include <string>

namespace penny::internal
{
  // The mean over the grid of a field (its local rows on a split grid).
  inline double mean(const FourierTransform &transform, const GridField &field)
  {
    return transform.sum(std::accumulate(field.begin(), field.end(), 0.)) / transform.grid().n_points();
  }

  // Whether `condition` holds on any rank: a check that throws on all ranks or none.
  inline bool on_any_rank(const FourierTransform &transform, const bool condition)
  {
    return transform.sum(condition ? 1 : 0) > 0;
  }

  // A message with up to three numbers (printf's format).
  inline std::string formatted(const char *format, const double a, const double b = 0, const double c = 0)
  {
    char text[240];
    std::snprintf(text, sizeof text, format, a, b, c);
    return text;
  }
} // namespace penny::internal
