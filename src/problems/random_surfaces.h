// Sampled random surfaces (doc/theory.md, section 7): the subsection of the
// grid and the realisations (Random surfaces), the grid a spectrum needs, and
// the mean over realisations with its standard error.
#pragma once

#include "fe/elasticity.h"
#include "fourier/fourier_transform.h"
#include "input/entries.h"
#include "statistics/roughness.h"
#include "statistics/summit_statistics.h"

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace penny
{
  // Realisations of a spectrum on a periodic square grid.
  struct RandomSurfaceParameters
  {
    unsigned int  n_points; // grid points per side
    double        period;   // side L in units of lambda0 = 2 pi/q0
    unsigned int  n_realisations;
    std::uint64_t seed;
  };

  // What the scenes on sampled surfaces read: the solid (Material), the
  // spectrum (Roughness; only its q0 and h0/lambda0 for a scene that samples
  // power laws of its own H and zeta, `one_spectrum` false) and the grid and
  // realisations (Random surfaces; at least `fewest_realisations`, 2 for a
  // scene whose verdict needs the standard error of a mean).
  struct RandomSurfaceInput
  {
    MaterialParameters      material;
    RoughnessParameters     roughness;
    RandomSurfaceParameters surfaces;

    void sections(Sections &sections, bool one_spectrum = true, unsigned int fewest_realisations = 1);
  };

  // The power laws a scene on sampled surfaces studies: the entries 'Hurst
  // exponents' and 'Magnifications' (each increasing; the magnifications in
  // `magnification_range`) of its own subsection, the q0 and h0/lambda0 of
  // its Roughness.
  struct SampledPowerLaws
  {
    std::vector<double> hurst_exponents, magnifications;

    void entries(Entries &entries, const std::vector<double> &default_magnifications,
                 const Range &magnification_range);
  };

  // The square grid of side L = period 2 pi/q0 for a spectrum on q0 <= q <=
  // zeta q0; throws InputError naming Random surfaces/Grid points per side
  // unless its shortest wavelength spans at least 4 points.
  PeriodicGrid surface_grid(const RandomSurfaceParameters &surfaces, const PowerSpectrum &spectrum);

  // Throws InputError naming Random surfaces/Grid points per side if a
  // rank's grids, `bytes_per_point` for each of the N^2 points (measured per
  // scene: each rank solves whole realisations), would not fit in the memory
  // each rank of the run may take. Collective on `communicator`.
  void check_grid_memory(const RandomSurfaceParameters &surfaces, double bytes_per_point,
                         MPI_Comm communicator);

  // Throws InputError naming `choice` (the entries that chose the spectrum
  // and the grid, as "entry = value ...") unless the sampled lattice's
  // `pressure` moments admit the Kac-Rice summit expectations: a band of
  // wavevectors of one length (or none) has no summit statistics.
  void check_summit_spectrum(const FieldMoments &pressure, const std::string &choice);

  // Mean and standard error of the mean over the rows' `column` (one row a realisation).
  Estimate mean_over(const std::vector<std::vector<double>> &rows, std::size_t column);
} // namespace penny
