// A rigid periodic surface pressed on an elastic half-space of E* = 1: its
// grid's transform and the contact solvers with and without adhesion built
// for it. The verification models (adhesive_sinusoid.h, adhesive_sphere.h,
// adhesive_bisinusoid.h) each hold one; the adhesionless solver gives their
// paths a start.
#pragma once

#include "contact/half_space_contact.h"

#include <functional>
#include <stdexcept>

namespace penny
{
  // `value` if `ok`, else std::invalid_argument(`requirement`): a model's
  // discretisation checked before its members are built from it.
  template <typename T> const T &checked(const T &value, const bool ok, const char *requirement)
  {
    if (!ok)
      throw std::invalid_argument(requirement);
    return value;
  }

  class RigidSurface
  {
  public:
    // Heights h(i, j) at the grid points (i, j) of `grid`.
    RigidSurface(const PeriodicGrid &grid, const std::function<double(unsigned int, unsigned int)> &height,
                 const Adhesion &adhesion);

    const PeriodicGrid     &grid() const { return transform.grid(); }
    const Adhesion         &adhesion() const { return adhesive_.adhesion(); }
    const HalfSpaceContact &adhesive() const { return adhesive_; }
    const HalfSpaceContact &adhesionless() const { return adhesionless_; }

  private:
    FourierTransform transform;
    HalfSpaceContact adhesive_, adhesionless_;
  };
} // namespace penny
