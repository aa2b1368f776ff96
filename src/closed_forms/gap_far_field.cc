#include "closed_forms/gap_far_field.h"

#include <cmath>

namespace penny
{
  using namespace dealii;

  GapFarField::GapFarField(const double volume, const double poissons_ratio)
      : nu(poissons_ratio), amplitude(volume / (8 * M_PI * (1 - nu)))
  {
  }

  Tensor<1, 3> GapFarField::displacement(const Point<3> &x) const
  {
    const double r2 = x.norm_square(), r3 = r2 * std::sqrt(r2), z = x[2];
    Tensor<1, 3> u = ((3 * z * z / r2 - (1 - 2 * nu)) / r3) * x;
    u[2] += 2 * (1 - 2 * nu) * z / r3;
    return amplitude * u;
  }

  // The derivative of (1 - 2 nu) v/r^3 + 3 x z^2/r^5 with v = 2 z e_z - x.
  Tensor<2, 3> GapFarField::displacement_gradient(const Point<3> &x) const
  {
    const double r2 = x.norm_square(), r = std::sqrt(r2), r3 = r2 * r, r5 = r3 * r2, z = x[2];
    Tensor<1, 3> v = -x;
    v[2] += 2 * z;
    Tensor<2, 3> g;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          const double dv = (i == 2 && j == 2 ? 2. : 0.) - (i == j ? 1. : 0.);
          g[i][j] =
              (1 - 2 * nu) * (dv / r3 - 3 * v[i] * x[j] / r5) +
              3 * ((i == j ? z * z : 0.) + (j == 2 ? 2 * x[i] * z : 0.) - 5 * x[i] * x[j] * z * z / r2) / r5;
        }
    return amplitude * g;
  }
} // namespace penny
