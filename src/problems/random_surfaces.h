// Sampled random surfaces (doc/theory.md, section 7): the subsection of the
// grid and the realisations (Random surfaces), the grid a spectrum needs, and
// the mean over realisations with its standard error.
#pragma once

#include "fe/elasticity.h"
#include "fourier/fourier_transform.h"
#include "input/entries.h"
#include "statistics/roughness.h"
#include "statistics/summit_statistics.h"

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
  // spectrum (Roughness) and the grid and realisations (Random surfaces).
  struct RandomSurfaceInput
  {
    MaterialParameters      material;
    RoughnessParameters     roughness;
    RandomSurfaceParameters surfaces;

    void sections(Sections &sections);
  };

  // The power laws a scene on sampled surfaces studies: the entries 'Hurst
  // exponents' and 'Magnifications' (increasing, in `magnification_range`)
  // of its own subsection, in place of Roughness/Hurst exponent H and
  // Magnification zeta.
  struct SampledPowerLaws
  {
    std::vector<double> hurst_exponents, magnifications;

    void entries(Entries &entries, const std::vector<double> &default_magnifications,
                 const Range &magnification_range);
  };

  // Throws InputError, once read, unless Roughness is the power law: `scene`
  // samples the power laws of its own entries.
  void require_power_law(Sections &sections, const RoughnessParameters &roughness, const std::string &scene);

  // The square grid of side L = period 2 pi/q0 for a spectrum on q0 <= q <=
  // zeta q0; throws InputError naming Random surfaces/Grid points per side
  // unless its shortest wavelength spans at least 4 points.
  PeriodicGrid surface_grid(const RandomSurfaceParameters &surfaces, const PowerSpectrum &spectrum);

  // Mean and standard error of the mean over the rows' `column` (one row a realisation).
  Estimate mean_over(const std::vector<std::vector<double>> &rows, std::size_t column);
} // namespace penny
