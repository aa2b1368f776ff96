// The elastic half-space under a periodic surface load, in Fourier space: a
// pressure p^_q (Pa) moves its surface by u^_q = 2 p^_q/(E* |q|) (q != 0; the
// mean displacement is the rigid-body approach), E* the plane-strain modulus.
#pragma once

#include "fourier/fourier_transform.h"

namespace penny
{
  // The pressure that pushes an elastic half-space (plane-strain modulus E*,
  // Pa) into full contact with the rigid periodic surface h, less its mean:
  // p_fc = (E*/2) F^-1[|q| h^] (Pa).
  GridField full_contact_pressure(const FourierTransform &transform, const GridField &heights, double E_star);
} // namespace penny
