// The shape of a contact solution on its periodic grid: how many contact
// regions and gaps it has, and how large a round one is.
#pragma once

#include "fourier/fourier_transform.h"

#include <vector>

namespace penny
{
  // Connected regions of contact (g = 0) and of non-contact (g > 0) on the
  // periodic grid, points joined to their four neighbours. Both functions
  // here need the whole field: on a grid split over ranks they throw
  // std::invalid_argument.
  struct ContactTopology
  {
    unsigned int contacts;
    unsigned int gaps;

    bool operator==(const ContactTopology &other) const
    {
      return contacts == other.contacts && gaps == other.gaps;
    }
  };
  ContactTopology contact_topology(const PeriodicGrid &grid, const GridField &gap);

  // The equivalent radius sqrt(area/pi) of the region around the grid point
  // (i, j) bounded by the level f = `level` (m): along `rays` rays from the
  // point, f interpolated bilinearly (linearly on an n x 1 grid, two rays) is
  // followed until it crosses the level, the crossing is found by bisection,
  // and sqrt(<r^2>) over the rays is the radius of the circle of the same area
  // (the region must be star-shaped about the point). Throws
  // std::runtime_error if a ray meets no crossing within half the period.
  double level_radius(const PeriodicGrid &grid, const GridField &f, double level, unsigned int i,
                      unsigned int j, unsigned int rays = 256);

  // Where a contact edge lies between grid points, from the gaps g_1 ... g_M
  // (M >= 4) of the first non-contact points beside it, g_k at k cells from
  // the last contact point. Beside a smooth edge g ~ (x - a)^(3/2), so g^(2/3)
  // is smooth and vanishes linearly at the edge: fitted by a quadratic (least
  // squares, Eigen) over k = 2 ... M (the first point, nearest the discrete
  // edge, is left out) and returned is its root, in cells from the last
  // contact point.
  double edge_from_gap(const std::vector<double> &gaps);
} // namespace penny
