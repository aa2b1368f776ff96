// Gaussian random fields on a periodic grid (doc/theory.md, section 7): a field
// h(x, y) with isotropic power spectral density C(q) (heights in m, C in m^4,
// wavenumbers in 1/m) sampled by FFT, its spectral derivatives, its sampled
// mean squares beside their expectation for the discrete spectrum and the
// continuum moments m0, m2, m4, and the full-contact pressure (Pa) it needs.
//
// Fourier convention (a Fourier series on the periodic rectangle):
//   h(x) = sum_q h^_q exp(i q.x),  q = 2 pi (kx/lx, ky/ly),
// so <h^2> = sum_q <|h^_q|^2> and a field with PSD C has
// <|h^_q|^2> = C(|q|) dq_x dq_y with dq = 2 pi/l: the lattice sum that
// approximates m0 = int C(q) d^2q.
#pragma once

#include "statistics/roughness.h"

#include <complex>
#include <cstdint>
#include <functional>
#include <vector>

namespace penny
{
  // nx x ny points on an lx x ly rectangle (m), periodic in both directions.
  // A field is stored row-major with x the slow index: the value at
  // (x, y) = (i lx/nx, j ly/ny) is field[i * ny + j].
  struct PeriodicGrid
  {
    unsigned int nx, ny;
    double       lx, ly;

    std::size_t n_points() const { return std::size_t(nx) * ny; }
    double      area() const { return lx * ly; }
  };

  // A square grid of n x n points on a side `length`.
  PeriodicGrid square_grid(unsigned int n, double length);

  using GridField = std::vector<double>;

  // A wavevector of the grid's spectrum: integer wavenumbers (kx in
  // (-nx/2, nx/2], ky in [0, ny/2]), q = 2 pi (kx/lx, ky/ly) (1/m), and whether
  // the component is the Nyquist one (k = n/2 with n even), whose sine part
  // the grid cannot represent.
  struct Wavevector
  {
    int    kx, ky;
    double qx, qy;
    bool   nyquist_x, nyquist_y;

    double norm() const;
  };

  // Real-to-complex FFTs (FFTW, r2c/c2r) on one grid. The spectrum holds the
  // half plane ky >= 0, nx x (ny/2 + 1) coefficients in FFTW's layout; the
  // other half is the complex conjugate (Hermitian symmetry of a real field).
  // Plans and work arrays belong to the object: it is not thread-safe.
  class FourierTransform
  {
  public:
    using Spectrum = std::vector<std::complex<double>>;

    explicit FourierTransform(const PeriodicGrid &grid);
    ~FourierTransform();
    FourierTransform(const FourierTransform &)            = delete;
    FourierTransform &operator=(const FourierTransform &) = delete;

    const PeriodicGrid &grid() const { return grid_; }
    std::size_t         n_coefficients() const { return std::size_t(grid_.nx) * (grid_.ny / 2 + 1); }
    Wavevector          wavevector(std::size_t coefficient) const;

    // h^_q = (1/(nx ny)) sum_x h(x) exp(-i q.x).
    Spectrum forward(const GridField &field) const;
    // h(x) = sum_q h^_q exp(i q.x); the coefficients must be Hermitian on the
    // lines ky = 0 and ky = ny/2 (FFTW reads only one of each conjugate pair).
    GridField inverse(const Spectrum &coefficients) const;

    // A Fourier multiplier m(q) tabulated once for repeated use, e.g. the
    // half-space compliance 2/(E* |q|) inside the contact solver.
    Spectrum tabulate(const std::function<std::complex<double>(const Wavevector &)> &multiplier) const;
    // out = F^-1[m(q) F[in]]; `out` may be `in`.
    void apply(const Spectrum &multiplier, const GridField &in, GridField &out) const;

  private:
    PeriodicGrid          grid_;
    double               *real_buffer;
    std::complex<double> *complex_buffer;
    void                 *forward_plan;
    void                 *inverse_plan;
  };

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

  // The field itself (m): F^-1 of gaussian_spectrum.
  GridField gaussian_field(const FourierTransform &transform, const PowerSpectrum &spectrum,
                           std::uint64_t seed);

  // The Fourier factor of d^(ox + oy)/dx^ox dy^oy, (i qx)^ox (i qy)^oy, zero
  // on a Nyquist component of odd order (its sine part is not on the grid).
  std::complex<double> derivative_factor(const Wavevector &q, unsigned int order_x, unsigned int order_y);

  // d^(ox + oy) h / dx^ox dy^oy by multiplying h^_q with derivative_factor.
  // Exact for band-limited fields.
  GridField spectral_derivative(const FourierTransform &transform, const GridField &field,
                                unsigned int order_x, unsigned int order_y);

  // The pressure that pushes an elastic half-space (plane-strain modulus E*,
  // Pa) into full contact with the rigid periodic surface h, less its mean:
  // p_fc = (E*/2) F^-1[|q| h^] (Pa).
  GridField full_contact_pressure(const FourierTransform &transform, const GridField &heights, double E_star);

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

  // The sampled mean squares of one field (spectral derivatives).
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
