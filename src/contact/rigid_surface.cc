#include "contact/rigid_surface.h"

namespace penny
{
  namespace
  {
    GridField sampled(const PeriodicGrid                                      &grid,
                      const std::function<double(unsigned int, unsigned int)> &height)
    {
      GridField h(grid.n_points());
      for (unsigned int i = 0; i < grid.nx; ++i)
        for (unsigned int j = 0; j < grid.ny; ++j)
          h[std::size_t(i) * grid.ny + j] = height(i, j);
      return h;
    }
  } // namespace

  RigidSurface::RigidSurface(const PeriodicGrid                                      &grid,
                             const std::function<double(unsigned int, unsigned int)> &height,
                             const Adhesion                                          &adhesion)
      : transform(grid), adhesive_(transform, sampled(grid, height), 1., adhesion),
        adhesionless_(transform, adhesive_.heights(), 1.)
  {
  }
} // namespace penny
