// Periodic grids and their fast Fourier transforms (FFTW): the discrete setting
// of the random fields (statistics/) and of the boundary-element contact
// solvers (contact/).
//
// Fourier convention (a Fourier series on the periodic rectangle):
//   h(x) = sum_q h^_q exp(i q.x),  q = 2 pi (kx/lx, ky/ly),
// so <h^2> = sum_q |h^_q|^2.
#pragma once

#include <complex>
#include <functional>
#include <optional>
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

  // How FFTW chooses its algorithm for a grid. `estimate` picks it without
  // timing runs: the same algorithm, so the same rounding, in every run and on
  // every rank of the same hardware. `measure` times candidates when the
  // transform is made (about 1 s at 2048^2) and is about twice as fast at
  // 2048^2 and 4096^2, but may pick another algorithm in another run, so
  // results can differ in the last bits (and iterative solvers' results by up
  // to their tolerance) from run to run.
  enum class Planning
  {
    estimate,
    measure
  };

  // Real-to-complex FFTs (FFTW, r2c/c2r) on one grid. The spectrum holds the
  // half plane ky >= 0, nx x (ny/2 + 1) coefficients in FFTW's layout; the
  // other half is the complex conjugate (Hermitian symmetry of a real field).
  // Plans and work arrays belong to the object: it is not thread-safe.
  class FourierTransform
  {
  public:
    using Spectrum = std::vector<std::complex<double>>;

    explicit FourierTransform(const PeriodicGrid &grid, Planning planning = Planning::estimate);
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

    // The same in place on the transform's own real array (nx ny values in the
    // layout of GridField), for iterative solvers that fill it, convolve and
    // read it back without the two copies of apply().
    double *work_array() const { return real_buffer; }
    void    convolve_work_array(const Spectrum &multiplier) const;
    // sum_q m(q) |f^_q|^2 over the whole spectrum (both halves) of the field f
    // in the work array, by one r2c transform: for a real even m this is the
    // mean <f M f> of the operator M = F^-1 m F (Parseval). The work array is lost.
    double quadratic_form_of_work_array(const Spectrum &multiplier) const;

    // Convolutions (one r2c and one c2r transform each) done so far, by apply
    // and convolve_work_array: the cost measure of iterative solvers.
    std::size_t convolutions() const { return n_convolutions; }

  private:
    PeriodicGrid          grid_;
    double               *real_buffer;
    std::complex<double> *complex_buffer;
    void                 *forward_plan;
    void                 *inverse_plan;
    mutable std::size_t   n_convolutions = 0;
  };

  // The field sampled on another grid of the same rectangle by its Fourier
  // series, the modes the coarser of the two grids cannot hold (their Nyquist
  // modes too) dropped: exact for fields band-limited to the coarser grid.
  GridField resampled(const FourierTransform &from, const FourierTransform &to, const GridField &field);

  // The grid halved in each direction of more than one point, or nothing if
  // a side is odd or its half would have fewer than `smallest` points.
  std::optional<PeriodicGrid> halved(const PeriodicGrid &grid, unsigned int smallest);

  // A field on `fine` (twice `coarse` in each direction of more than one
  // point) by bilinear interpolation, periodic: each value lies between
  // those of neighbouring coarse points, so a field >= 0 stays >= 0.
  GridField interpolated(const PeriodicGrid &coarse, const GridField &field, const PeriodicGrid &fine);

  // The Fourier factor of d^(ox + oy)/dx^ox dy^oy, (i qx)^ox (i qy)^oy, zero
  // on a Nyquist component of odd order (its sine part is not on the grid).
  std::complex<double> derivative_factor(const Wavevector &q, unsigned int order_x, unsigned int order_y);

  // d^(ox + oy) h / dx^ox dy^oy by multiplying h^_q with derivative_factor.
  // Exact for band-limited fields.
  GridField spectral_derivative(const FourierTransform &transform, const GridField &field,
                                unsigned int order_x, unsigned int order_y);
} // namespace penny
