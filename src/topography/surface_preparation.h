// A measured topography prepared as a user of a contact code prepares it
// (doc/measured.md): points not measured filled, a polynomial trend removed,
// and its roughness summarised: rms height, slope and curvature on stated
// stencils, the isotropic power spectral density and a power law fitted to it.
#pragma once

#include "statistics/roughness.h"
#include "topography/topography.h"

#include <cstddef>
#include <cstdint>

namespace penny
{
  // The points i0 <= i < i1 (along x) and j0 <= j < j1 (along y) of a map, on
  // their own rectangle.
  Topography cropped(const Topography &topography, unsigned int i0, unsigned int i1, unsigned int j0,
                     unsigned int j1);

  // Fills the points not measured (NaN) by harmonic interpolation: Laplace's
  // equation on the five-point stencil over them, the measured points their
  // boundary values, no flux across the map's edges (a sparse Cholesky, Eigen).
  // Returns how many points it filled; throws InputError when none is measured.
  std::size_t fill_missing_points(Topography &topography);

  // The trend removed by least squares over the whole map: the mean, a plane
  // (1, x, y) or a curvature (1, x, y, x^2, x y, y^2). No point may be missing.
  enum class Detrending
  {
    mean,
    plane,
    curvature
  };
  void detrend(Topography &topography, Detrending detrending);

  // Root mean squares of a map that is not periodic, on the stencils of
  // SurfaceTopography's Sq, rms_gradient and rms_curvature_from_area:
  // height over all points; slope sqrt<(dh/dx)^2 + (dh/dy)^2> with forward
  // differences at the (nx - 1)(ny - 1) points where both exist; curvature
  // sqrt<(laplacian h)^2>/2 with the three-point second differences at the
  // (nx - 2)(ny - 2) interior points (a map has 3 x 3 points at least).
  struct SurfaceRoughness
  {
    double rms_height;    // m
    double rms_slope;     // 1
    double rms_curvature; // 1/m
  };
  SurfaceRoughness surface_roughness(const Topography &topography);

  // The isotropic PSD C(q) (m^4, the convention of statistics/roughness.h:
  // m0 = int C d^2q) of the map taken as one period, |h^_q|^2/(dqx dqy)
  // averaged over the modes in bins of |q| evenly spaced in log q (8 per
  // decade), from 2 pi/max(lx, ly) to the Nyquist wavenumber pi/max(dx, dy).
  // With `hann`, the map is multiplied by a separable Hann window first,
  // normalised to keep <h^2> (less leakage from the edges of a map that is not periodic).
  PowerSpectrum isotropic_spectrum(const Topography &topography, bool hann);

  // Where a measured PSD is trusted: wavelengths from half the shorter side
  // of the map (two periods fit; longer ones are few and the trend removal
  // took their power) down to four pixels of the coarser spacing (shorter ones
  // carry the instrument's transfer function and the pixel's aliasing).
  struct WavenumberRange
  {
    double q_low, q_high; // 1/m
  };
  WavenumberRange reliable_range(const Topography &topography);

  // A Gaussian twin of a map taken as one period: its Fourier coefficients
  // with random phases (a phase-randomised surrogate), so the same power at
  // every wavevector, anisotropy included, the same V and moments, and
  // heights that a sum of many independent phases makes Gaussian. On the
  // lines ky = 0 and ky = ny/2 the phases of kx and -kx are opposite (a real
  // field); the coefficients that must be real keep theirs.
  GridField gaussian_twin(const FourierTransform &transform, const GridField &heights, std::uint64_t seed);

  // The least-squares line through log C against log q over the bins inside
  // `range`: C = C0 (q/q_low)^(-2(1 + H)), and how well it fits.
  struct PowerLawFit
  {
    double       hurst;             // H from the slope -2(1 + H)
    double       c0;                // C at range.q_low (m^4)
    double       q_low, q_high;     // the range fitted (1/m)
    double       rms_log_deviation; // rms of log10(C/fit) over the bins
    double       r_squared;         // of log C against log q
    unsigned int n_bins;
  };
  PowerLawFit fit_power_law(const PowerSpectrum &spectrum, const WavenumberRange &range);
} // namespace penny
