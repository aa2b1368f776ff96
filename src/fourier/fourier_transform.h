// Periodic grids and their fast Fourier transforms (FFTW): the discrete setting
// of the random fields (statistics/) and of the boundary-element contact
// solvers (contact/).
//
// Fourier convention (a Fourier series on the periodic rectangle):
//   h(x) = sum_q h^_q exp(i q.x),  q = 2 pi (kx/lx, ky/ly),
// so <h^2> = sum_q |h^_q|^2.
//
// A grid may be split over the ranks of an MPI communicator: each rank then
// holds a slab of consecutive x rows of every field, and its share of the
// spectrum.
#pragma once

#include <mpi.h>

#include <array>
#include <complex>
#include <functional>
#include <utility>
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

  // A field's values at the grid points, or at a slab of rows of a grid
  // split over ranks (FourierTransform::first_row, n_rows).
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

  // The wavevector of the integer wavenumbers (kx, ky) stored at index i in
  // x (0 <= i < nx, kx = i or i - nx) and ky (0 <= ky <= ny/2).
  Wavevector wavevector(const PeriodicGrid &grid, unsigned int i, unsigned int ky);

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

  // How a grid split over several ranks is transformed. `shared_memory`: the
  // ranks' rows lie in one MPI shared-memory window; each rank transforms its
  // rows, then, reading every rank's rows in place, its lines of the spectrum,
  // so no data is copied between ranks. It needs every rank on one node and
  // is `fftw_mpi` otherwise: FFTW's MPI plans, whose global transposes move
  // the data between ranks (and nodes). Both leave the spectrum in the same
  // layout, with the same split.
  enum class SplitTransform
  {
    shared_memory,
    fftw_mpi
  };

  // Real-to-complex FFTs (FFTW, r2c/c2r) on one grid, in double precision
  // (FourierTransform) or single (SingleFourierTransform: half the memory
  // traffic, for an iterative solver's preconditioner, whose rounding at 1e-7
  // of its input only perturbs the search directions). The spectrum holds the
  // half plane ky >= 0, nx x (ny/2 + 1) coefficients; the other half is the
  // complex conjugate (Hermitian symmetry of a real field). On one rank the
  // coefficients are in FFTW's layout (kx the slow index). On a communicator
  // of several ranks the grid is split (SplitTransform): fields hold the
  // rank's rows, the spectrum is transposed (each rank holds whole lines of
  // constant ky, kx the fast index); every Spectrum (forward, tabulate, inverse)
  // is the rank's share in that layout, and wavevector() tells what each
  // coefficient is. Plans and work arrays belong to the object: it is not
  // thread-safe, and on several ranks every member that transforms or sums
  // is collective.
  template <typename Real> class BasicFourierTransform
  {
  public:
    using Spectrum = std::vector<std::complex<Real>>;
    // A real multiplier m(q) = m(-q) (a symmetric operator such as the
    // half-space's stiffness), stored without the imaginary parts.
    using RealMultiplier = std::vector<Real>;

    explicit BasicFourierTransform(const PeriodicGrid &grid, Planning planning = Planning::estimate,
                                   MPI_Comm       communicator = MPI_COMM_SELF,
                                   SplitTransform how          = SplitTransform::shared_memory);
    ~BasicFourierTransform();
    BasicFourierTransform(const BasicFourierTransform &)            = delete;
    BasicFourierTransform &operator=(const BasicFourierTransform &) = delete;

    const PeriodicGrid &grid() const { return grid_; }
    Planning            planning() const { return planning_; }
    MPI_Comm            communicator() const { return communicator_; }
    // Whether the grid is split over more than one rank, and whether its
    // ranks share memory (SplitTransform::shared_memory on one node).
    bool split() const { return !row_starts.empty(); }
    bool shares_memory() const { return window != MPI_WIN_NULL; }

    // This rank's rows, x indices first_row() ... first_row() + n_rows() - 1
    // (all of them on one rank; possibly none on a split grid).
    unsigned int first_row() const { return first_row_; }
    unsigned int n_rows() const { return n_rows_; }
    std::size_t  n_local_points() const { return std::size_t(n_rows_) * grid_.ny; }
    // Split grids: this rank's lines of the spectrum, ky = first_line() ...
    // first_line() + n_lines() - 1, each of nx coefficients (kx at index i as
    // in wavevector(grid, i, ky)).
    unsigned int first_line() const { return first_line_; }
    unsigned int n_lines() const { return n_coefficients_ / grid_.nx; }
    // The ranks of the communicator (1 unless split), this one among them, the
    // rows of each, the rank that holds row i of a field and the rank that
    // holds the spectrum's line ky.
    int                                   n_ranks() const;
    int                                   rank() const { return rank_; }
    std::pair<unsigned int, unsigned int> rows_of(int rank) const;
    int                                   row_owner(unsigned int i) const;
    int                                   line_owner(unsigned int ky) const;

    // This rank's coefficients and what each stands for.
    std::size_t n_coefficients() const { return n_coefficients_; }
    Wavevector  wavevector(std::size_t coefficient) const;

    // h^_q = (1/(nx ny)) sum_x h(x) exp(-i q.x).
    Spectrum forward(const GridField &field) const;
    // h(x) = sum_q h^_q exp(i q.x); the coefficients must be Hermitian on the
    // lines ky = 0 and ky = ny/2 (FFTW reads only one of each conjugate pair).
    GridField inverse(const Spectrum &coefficients) const;

    // A Fourier multiplier m(q) tabulated once for repeated use, e.g. the
    // half-space compliance 2/(E* |q|) inside the contact solver.
    Spectrum       tabulate(const std::function<std::complex<double>(const Wavevector &)> &multiplier) const;
    RealMultiplier tabulate_real(const std::function<double(const Wavevector &)> &multiplier) const;
    // out = F^-1[m(q) F[in]]; `out` may be `in`.
    void apply(const Spectrum &multiplier, const GridField &in, GridField &out) const;

    // The same in place on the transform's own real array, for iterative
    // solvers that fill it, convolve and read it back without the two copies
    // of apply(). Its rows are row_stride() = 2 (ny/2 + 1) values apart (FFTW's
    // in-place layout); for_each_point walks them.
    Real       *work_array() const { return real_buffer; }
    std::size_t row_stride() const { return row_stride_; }
    // f(i, w) for each local point: i its index in a GridField, w in the work array.
    template <typename Function> void for_each_point(Function &&f) const
    {
      for (std::size_t row = 0, i = 0; row < n_rows_; ++row)
        for (std::size_t j = 0, w = row * row_stride_; j < grid_.ny; ++j, ++i, ++w)
          f(i, w);
    }
    void convolve_work_array(const RealMultiplier &multiplier) const;
    // sum_q m(q) |f^_q|^2 over the whole spectrum (both halves) of the field f
    // in the work array, by one r2c transform: the mean <f M f> of the
    // operator M = F^-1 m F (Parseval). The work array is lost.
    double quadratic_form_of_work_array(const RealMultiplier &multiplier) const;

    // Sums and the least value over the ranks of the communicator of values
    // local to each (the value itself on one rank): the same on every rank.
    double sum(double local) const;
    // Several sums in one reduction.
    template <typename... Values> std::array<double, sizeof...(Values)> sums(const Values... local) const
    {
      std::array<double, sizeof...(Values)> values{{double(local)...}};
      sum_in_place(values.data(), values.size());
      return values;
    }
    double minimum(double local) const;
    // Whether this rank holds the first row: it alone adds a term common to
    // all ranks to a sum over ranks.
    bool holds_first_row() const { return first_row_ == 0 && n_rows_ > 0; }

  private:
    void sum_in_place(double *values, int n) const;

    PeriodicGrid grid_;
    Planning     planning_;
    MPI_Comm     communicator_;
    int          rank_;
    unsigned int first_row_, n_rows_;
    // Split grids: where each rank's rows and spectrum lines start (one entry
    // per rank and the end); both empty on one rank.
    std::vector<unsigned int> row_starts, line_starts;
    unsigned int              first_line_ = 0;
    std::size_t               n_coefficients_, row_stride_;
    // The work array of this rank's rows, and the spectrum: transformed in
    // place of the rows on one rank and by FFTW's MPI plans, into an array of
    // its own in shared memory.
    Real               *real_buffer;
    std::complex<Real> *spectrum_buffer;
    // The plans between them; in shared memory those of the rows' transforms
    // along y and of this rank's lines along x, and the window of all ranks'
    // rows, which the lines' transforms read and write in place.
    void   *forward_plan, *inverse_plan;
    void   *forward_lines_plan = nullptr, *inverse_lines_plan = nullptr;
    MPI_Win window = MPI_WIN_NULL;
    void    synchronise() const;
    void    transform_forward() const;
    void    transform_inverse() const;
    // The work array convolved with a complex or a real multiplier.
    template <typename Multiplier> void convolve(const Multiplier &multiplier) const;
  };

  using FourierTransform       = BasicFourierTransform<double>;
  using SingleFourierTransform = BasicFourierTransform<float>;

  // The Fourier factor of d^(ox + oy)/dx^ox dy^oy, (i qx)^ox (i qy)^oy, zero
  // on a Nyquist component of odd order (its sine part is not on the grid).
  std::complex<double> derivative_factor(const Wavevector &q, unsigned int order_x, unsigned int order_y);

  // d^(ox + oy) h / dx^ox dy^oy by multiplying h^_q with derivative_factor.
  // Exact for band-limited fields.
  GridField spectral_derivative(const FourierTransform &transform, const GridField &field,
                                unsigned int order_x, unsigned int order_y);
} // namespace penny
