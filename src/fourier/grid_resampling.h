// Fields moved between grids of one periodic rectangle: the coarser grids of
// nested iteration (contact/half_space_contact.h) and back. Both grids may be
// split over the ranks of one communicator (fourier_transform.h); each
// function is then collective and exchanges only what the rows of each rank need.
#pragma once

#include "fourier/fourier_transform.h"

#include <optional>

namespace penny
{
  // The field sampled on another grid of the same rectangle by its Fourier
  // series, the modes the coarser of the two grids cannot hold (their Nyquist
  // modes too) dropped: exact for fields band-limited to the coarser grid.
  // Split grids: each line ky of the kept modes goes from its rank on `from`
  // to its rank on `to` (one MPI_Alltoallv).
  GridField resampled(const FourierTransform &from, const FourierTransform &to, const GridField &field);

  // The grid halved in each direction of more than one point, or nothing if
  // a side is odd or its half would have fewer than `smallest` points.
  std::optional<PeriodicGrid> halved(const PeriodicGrid &grid, unsigned int smallest);

  // A field on the grid of `fine` (twice that of `coarse` in each direction
  // of more than one point) by bilinear interpolation, periodic: each value
  // lies between those of neighbouring coarse points, so a field >= 0 stays
  // >= 0. Split grids: each rank receives the coarse rows its fine rows lie
  // between, one beyond its own block included (one MPI_Alltoallv).
  GridField interpolated(const FourierTransform &coarse, const GridField &field,
                         const FourierTransform &fine);
} // namespace penny
