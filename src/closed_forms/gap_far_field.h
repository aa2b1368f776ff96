// The far field of a flat gap in an infinite isotropic solid (doc/theory.md,
// section 10). Seen from afar, an opening [u_z] over part of the plane z = 0
// is a point source whose strength is the gap's volume D = int [u_z] dA: its
// eigenstrain D e_z e_z makes the moment tensor M = D (lambda I + 2 mu e_z e_z),
// and Kelvin's point-force solution, differentiated once, gives
//   u(x) = D/(8 pi (1 - nu) r^3) [(1 - 2 nu)(2 z e_z - x) + 3 x z^2/r^2],
// r = |x|, the gap centred at the origin. The next term of the expansion is
// smaller by (c/r)^2 (c the gap's size) for a gap symmetric about its centre.
// On the axis it is the tail of Sneddon's penny crack, 4 (1 + nu)(2 - nu)
// p c^3/(3 pi E z^2) for D = 16 (1 - nu^2) p c^3/(3 E).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace penny
{
  class GapFarField
  {
  public:
    // The field of the volume D (m^3) in the solid of Poisson's ratio nu.
    GapFarField(double volume, double poissons_ratio);

    // u(x) (m) and its gradient du_i/dx_j at x != 0.
    dealii::Tensor<1, 3> displacement(const dealii::Point<3> &x) const;
    dealii::Tensor<2, 3> displacement_gradient(const dealii::Point<3> &x) const;

  private:
    const double nu;
    const double amplitude; // D/(8 pi (1 - nu))
  };
} // namespace penny
