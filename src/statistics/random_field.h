// Gaussian random fields on a periodic grid (doc/theory.md, section 7): a field
// h(x, y) with isotropic power spectral density C(q) (heights in m, C in m^4,
// wavenumbers in 1/m) sampled by FFT, and its sampled mean squares beside
// their expectation for the discrete spectrum and the continuum moments m0,
// m2, m4.
//
// In the Fourier convention of fourier/fourier_transform.h, a field with PSD C has
// <|h^_q|^2> = C(|q|) dq_x dq_y with dq = 2 pi/l: the lattice sum that
// approximates m0 = int C(q) d^2q.
#pragma once

#include "fourier/fourier_transform.h"
#include "statistics/roughness.h"

#include <complex>
#include <cstdint>
#include <vector>

namespace penny
{
  // C(q) of a piecewise power law (roughness.h): log-log linear between the
  // table's points, zero outside [q_first, q_last] (the ends included up to a
  // relative 1e-12, so lattice points on a cut-off shell count).
  double spectral_density(const PowerSpectrum &spectrum, double q);

  // The PSD of the full-contact pressure p_fc = (E*/2) F^-1[|q| h^]:
  // (E*^2/4) q^2 C(q) (Pa^2 m^2), again a piecewise power law.
  PowerSpectrum pressure_spectrum(const PowerSpectrum &heights, double E_star);

  // The generator, fully specified so a seed means the same field on every
  // platform: SplitMix64's mixing function (Steele, Lea and Flood 2014) as a
  // counter-based generator keyed on (seed, kx, ky), and Box-Muller for the
  // Gaussian pair of one mode. A mode's coefficient depends on its wavevector
  // only, never on nx or ny: the same seed on a finer grid of the same
  // rectangle gives the same surface, sampled more finely.
  std::uint64_t realisation_seed(std::uint64_t seed, std::uint64_t index);

  // The spectrum of one realisation: for each conjugate pair {q, -q},
  // h^_q = sqrt(C(|q|) dq_x dq_y / 2) (g1 + i g2) with g1, g2 standard normal and
  // h^_-q its conjugate, so the field is Gaussian, real and has
  // <|h^_q|^2> = C dq_x dq_y. The mean (q = 0) and the Nyquist modes are zero.
  FourierTransform::Spectrum gaussian_spectrum(const FourierTransform &transform,
                                               const PowerSpectrum &spectrum, std::uint64_t seed);

  // The field itself (m): F^-1 of gaussian_spectrum. On a grid split over
  // ranks each rank draws only its own coefficients (each is keyed on its
  // wavevector), so the field is the serial one to rounding.
  GridField gaussian_field(const FourierTransform &transform, const PowerSpectrum &spectrum,
                           std::uint64_t seed);

  // Mean squares over the grid, in the notation of Nayak's profile moments:
  // m0 = <h^2>, m2 = <(dh/dx)^2>, m4 = <(d^2h/dx^2)^2>, and the twist
  // m22 = <(d^2h/dx dy)^2> (m^2, 1, 1/m^2, 1/m^2 for heights). An isotropic
  // spectrum has m22 = m4/3; the lattice of a periodic grid is only square
  // symmetric, and its m22 differs from m4/3 where few shells are sampled.
  struct FieldMoments
  {
    double m0, m2, m4, m22;
  };

  // The moments of an isotropic field from its profile moments: m22 = m4/3.
  FieldMoments isotropic_moments(double m0, double m2, double m4);

  // The sampled mean squares of one field (spectral derivatives); collective
  // on a split grid.
  FieldMoments sampled_moments(const FourierTransform &transform, const GridField &field);

  // Their expectation for a field of gaussian_spectrum, the lattice sums
  // sum_q w(q) C(|q|) dq_x dq_y over the grid's modes with w = 1, qx^2, qx^4,
  // qx^2 qy^2, and the standard deviation of one realisation's mean square
  // about it, [2 sum_q (w C dq_x dq_y)^2]^(1/2) (each conjugate pair carries
  // one exponentially distributed |h^_q|^2).
  struct LatticeMoments
  {
    FieldMoments expected;
    FieldMoments standard_deviation;
  };
  LatticeMoments lattice_moments(const PeriodicGrid &grid, const PowerSpectrum &spectrum);
} // namespace penny
