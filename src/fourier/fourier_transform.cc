#include "fourier/fourier_transform.h"

#include <fftw3-mpi.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

namespace penny
{
  PeriodicGrid square_grid(const unsigned int n, const double length)
  {
    return {n, n, length, length};
  }

  double Wavevector::norm() const
  {
    return std::hypot(qx, qy);
  }

  Wavevector wavevector(const PeriodicGrid &grid, const unsigned int i, const unsigned int ky)
  {
    const int kx = i <= grid.nx / 2 ? int(i) : int(i) - int(grid.nx);
    return {kx,
            int(ky),
            2 * M_PI * kx / grid.lx,
            2 * M_PI * ky / grid.ly,
            grid.nx % 2 == 0 && i == grid.nx / 2,
            grid.ny % 2 == 0 && ky == grid.ny / 2};
  }

  namespace
  {
    // The start of each rank's block and the end, from the blocks' sizes.
    std::vector<unsigned int> block_starts(const MPI_Comm communicator, const unsigned int size)
    {
      int ranks;
      MPI_Comm_size(communicator, &ranks);
      std::vector<unsigned int> starts(ranks + 1, 0);
      MPI_Allgather(&size, 1, MPI_UNSIGNED, starts.data() + 1, 1, MPI_UNSIGNED, communicator);
      for (int r = 0; r < ranks; ++r)
        starts[r + 1] += starts[r];
      return starts;
    }

    int owner(const std::vector<unsigned int> &starts, const unsigned int index)
    {
      return std::upper_bound(starts.begin(), starts.end(), index) - starts.begin() - 1;
    }

    // Whether every rank of the communicator runs on one node (can share memory).
    bool on_one_node(const MPI_Comm communicator)
    {
      MPI_Comm node;
      MPI_Comm_split_type(communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
      int node_ranks, ranks;
      MPI_Comm_size(node, &node_ranks);
      MPI_Comm_size(communicator, &ranks);
      MPI_Comm_free(&node);
      return node_ranks == ranks;
    }

    // FFTW's functions of each precision (fftw_... and fftwf_...).
    template <typename Real> struct Fftw;

    template <> struct Fftw<double>
    {
      using plan                            = fftw_plan;
      using complex                         = fftw_complex;
      static constexpr auto alloc_real      = fftw_alloc_real;
      static constexpr auto alloc_complex   = fftw_alloc_complex;
      static constexpr auto free            = fftw_free;
      static constexpr auto plan_r2c_2d     = fftw_plan_dft_r2c_2d;
      static constexpr auto plan_c2r_2d     = fftw_plan_dft_c2r_2d;
      static constexpr auto plan_many_r2c   = fftw_plan_many_dft_r2c;
      static constexpr auto plan_many_c2r   = fftw_plan_many_dft_c2r;
      static constexpr auto plan_many_dft   = fftw_plan_many_dft;
      static constexpr auto execute         = fftw_execute;
      static constexpr auto destroy_plan    = fftw_destroy_plan;
      static constexpr auto mpi_init        = fftw_mpi_init;
      static constexpr auto mpi_local_size  = fftw_mpi_local_size_2d_transposed;
      static constexpr auto mpi_plan_r2c_2d = fftw_mpi_plan_dft_r2c_2d;
      static constexpr auto mpi_plan_c2r_2d = fftw_mpi_plan_dft_c2r_2d;
    };

    template <> struct Fftw<float>
    {
      using plan                            = fftwf_plan;
      using complex                         = fftwf_complex;
      static constexpr auto alloc_real      = fftwf_alloc_real;
      static constexpr auto alloc_complex   = fftwf_alloc_complex;
      static constexpr auto free            = fftwf_free;
      static constexpr auto plan_r2c_2d     = fftwf_plan_dft_r2c_2d;
      static constexpr auto plan_c2r_2d     = fftwf_plan_dft_c2r_2d;
      static constexpr auto plan_many_r2c   = fftwf_plan_many_dft_r2c;
      static constexpr auto plan_many_c2r   = fftwf_plan_many_dft_c2r;
      static constexpr auto plan_many_dft   = fftwf_plan_many_dft;
      static constexpr auto execute         = fftwf_execute;
      static constexpr auto destroy_plan    = fftwf_destroy_plan;
      static constexpr auto mpi_init        = fftwf_mpi_init;
      static constexpr auto mpi_local_size  = fftwf_mpi_local_size_2d_transposed;
      static constexpr auto mpi_plan_r2c_2d = fftwf_mpi_plan_dft_r2c_2d;
      static constexpr auto mpi_plan_c2r_2d = fftwf_mpi_plan_dft_c2r_2d;
    };

    // A plan of a rank that has nothing to transform is none.
    template <typename Real> void execute(void *const plan)
    {
      if (plan)
        Fftw<Real>::execute(static_cast<typename Fftw<Real>::plan>(plan));
    }
  } // namespace

  template <typename Real>
  BasicFourierTransform<Real>::BasicFourierTransform(const PeriodicGrid &grid, const Planning planning,
                                                     const MPI_Comm communicator, const SplitTransform how)
      : grid_(grid), planning_(planning), communicator_(communicator), rank_(0), first_row_(0),
        n_rows_(grid.nx), n_coefficients_(std::size_t(grid.nx) * (grid.ny / 2 + 1))
  {
    if (grid.nx == 0 || grid.ny == 0 || !(grid.lx > 0) || !(grid.ly > 0))
      throw std::invalid_argument("FourierTransform: the grid needs nx, ny >= 1 points and lx, ly > 0");
    int ranks = 1;
    if (communicator != MPI_COMM_SELF)
      MPI_Comm_size(communicator, &ranks);
    // In place, rows padded to 2 (ny/2 + 1) values (about a tenth faster than
    // out of place at 2048^2). FFTW_MEASURE overwrites the arrays while it
    // plans; they hold nothing yet.
    const unsigned int flags   = planning == Planning::estimate ? FFTW_ESTIMATE : FFTW_MEASURE;
    const ptrdiff_t    n_lines = grid.ny / 2 + 1;
    using F                    = Fftw<Real>;
    using Complex              = typename F::complex;
    row_stride_                = 2 * n_lines;
    if (ranks == 1)
      {
        real_buffer     = F::alloc_real(2 * n_coefficients_);
        spectrum_buffer = reinterpret_cast<std::complex<Real> *>(real_buffer);
        auto *spectrum  = reinterpret_cast<Complex *>(real_buffer);
        forward_plan    = F::plan_r2c_2d(grid.nx, grid.ny, real_buffer, spectrum, flags);
        inverse_plan    = F::plan_c2r_2d(grid.nx, grid.ny, spectrum, real_buffer, flags);
        return;
      }
    MPI_Comm_rank(communicator, &rank_);
    if (how == SplitTransform::shared_memory && on_one_node(communicator))
      {
        // Rows and spectrum lines in blocks as even as they go. Each rank's
        // rows are its segment of the window, the segments contiguous in rank
        // order: the whole grid in FFTW's in-place layout.
        first_row_      = std::size_t(grid.nx) * rank_ / ranks;
        n_rows_         = std::size_t(grid.nx) * (rank_ + 1) / ranks - first_row_;
        first_line_     = std::size_t(n_lines) * rank_ / ranks;
        const int lines = std::size_t(n_lines) * (rank_ + 1) / ranks - first_line_;
        n_coefficients_ = std::size_t(lines) * grid.nx;
        row_starts      = block_starts(communicator, n_rows_);
        line_starts     = block_starts(communicator, lines);
        MPI_Win_allocate_shared(MPI_Aint(n_rows_) * row_stride_ * sizeof(Real), sizeof(Real), MPI_INFO_NULL,
                                communicator, &real_buffer, &window);
        MPI_Win_lock_all(MPI_MODE_NOCHECK, window);
        MPI_Aint size;
        int      unit;
        Real    *whole_grid;
        MPI_Win_shared_query(window, MPI_PROC_NULL, &size, &unit, &whole_grid);
        spectrum_buffer = reinterpret_cast<std::complex<Real> *>(
            F::alloc_complex(std::max<std::size_t>(n_coefficients_, 1)));
        auto     *rows           = reinterpret_cast<Complex *>(real_buffer);
        auto     *spectrum       = reinterpret_cast<Complex *>(spectrum_buffer);
        auto     *lines_in_place = reinterpret_cast<Complex *>(whole_grid) + first_line_;
        const int ny = grid.ny, nx = grid.nx;
        // The rows' transforms along y in place; then each line ky along x,
        // from the rows (n_lines complex values apart) into the spectrum
        // array's line of nx (the transpose done by the transform itself).
        forward_plan = n_rows_ == 0 ? nullptr
                                    : F::plan_many_r2c(1, &ny, n_rows_, real_buffer, nullptr, 1, row_stride_,
                                                       rows, nullptr, 1, n_lines, flags);
        inverse_plan = n_rows_ == 0 ? nullptr
                                    : F::plan_many_c2r(1, &ny, n_rows_, rows, nullptr, 1, n_lines,
                                                       real_buffer, nullptr, 1, row_stride_, flags);
        synchronise();
        if (lines > 0)
          {
            forward_lines_plan = F::plan_many_dft(1, &nx, lines, lines_in_place, nullptr, n_lines, 1,
                                                  spectrum, nullptr, 1, nx, FFTW_FORWARD, flags);
            inverse_lines_plan =
                F::plan_many_dft(1, &nx, lines, spectrum, nullptr, 1, nx, lines_in_place, nullptr, n_lines, 1,
                                 FFTW_BACKWARD, flags | FFTW_DESTROY_INPUT);
          }
        synchronise();
        return;
      }
    // FFTW's MPI plans: a slab of rows per rank; the spectrum's lines ky
    // split over the ranks as the omitted transpose left them (which saves
    // two global transposes a convolution). FFTW's MPI planner times
    // collectively, so FFTW_MEASURE picks one algorithm on every rank.
    static const bool initialised = (F::mpi_init(), true);
    (void)initialised;
    ptrdiff_t       rows, row, lines, line;
    const ptrdiff_t complex_size =
        F::mpi_local_size(grid.nx, n_lines, communicator, &rows, &row, &lines, &line);
    first_row_      = rows > 0 ? row : 0;
    n_rows_         = rows;
    first_line_     = lines > 0 ? line : 0;
    n_coefficients_ = std::size_t(lines) * grid.nx;
    row_starts      = block_starts(communicator, n_rows_);
    line_starts     = block_starts(communicator, lines);
    real_buffer     = F::alloc_real(2 * std::max<ptrdiff_t>(complex_size, 1));
    spectrum_buffer = reinterpret_cast<std::complex<Real> *>(real_buffer);
    auto *spectrum  = reinterpret_cast<Complex *>(real_buffer);
    forward_plan    = F::mpi_plan_r2c_2d(grid.nx, grid.ny, real_buffer, spectrum, communicator,
                                         flags | FFTW_MPI_TRANSPOSED_OUT);
    inverse_plan    = F::mpi_plan_c2r_2d(grid.nx, grid.ny, spectrum, real_buffer, communicator,
                                         flags | FFTW_MPI_TRANSPOSED_IN);
  }

  template <typename Real> BasicFourierTransform<Real>::~BasicFourierTransform()
  {
    for (void *plan : {forward_plan, inverse_plan, forward_lines_plan, inverse_lines_plan})
      if (plan)
        Fftw<Real>::destroy_plan(static_cast<typename Fftw<Real>::plan>(plan));
    if (!shares_memory())
      Fftw<Real>::free(real_buffer);
    else
      {
        Fftw<Real>::free(spectrum_buffer);
        // Freeing the window is collective: while an error unwinds, perhaps on
        // this rank alone, it is left to the end of the run.
        if (std::uncaught_exceptions() == 0)
          {
            MPI_Win_unlock_all(window);
            MPI_Win_free(&window);
          }
      }
  }

  // Every rank's writes to the window seen by every rank.
  template <typename Real> void BasicFourierTransform<Real>::synchronise() const
  {
    MPI_Win_sync(window);
    MPI_Barrier(communicator_);
    MPI_Win_sync(window);
  }

  // The rows' transforms, then in shared memory the lines', each rank's own;
  // the lines read every rank's rows, so no rank changes its rows before all
  // have read them, nor reads its rows before all have written them.
  template <typename Real> void BasicFourierTransform<Real>::transform_forward() const
  {
    execute<Real>(forward_plan);
    if (shares_memory())
      {
        synchronise();
        execute<Real>(forward_lines_plan);
        synchronise();
      }
  }

  template <typename Real> void BasicFourierTransform<Real>::transform_inverse() const
  {
    if (shares_memory())
      {
        synchronise();
        execute<Real>(inverse_lines_plan);
        synchronise();
      }
    execute<Real>(inverse_plan);
  }

  template <typename Real> int BasicFourierTransform<Real>::n_ranks() const
  {
    return split() ? int(row_starts.size()) - 1 : 1;
  }

  template <typename Real>
  std::pair<unsigned int, unsigned int> BasicFourierTransform<Real>::rows_of(const int rank) const
  {
    if (!split())
      return {0, grid_.nx};
    return {row_starts[rank], row_starts[rank + 1] - row_starts[rank]};
  }

  template <typename Real> int BasicFourierTransform<Real>::row_owner(const unsigned int i) const
  {
    return split() ? owner(row_starts, i) : 0;
  }

  template <typename Real> int BasicFourierTransform<Real>::line_owner(const unsigned int ky) const
  {
    return split() ? owner(line_starts, ky) : 0;
  }

  template <typename Real>
  Wavevector BasicFourierTransform<Real>::wavevector(const std::size_t coefficient) const
  {
    if (split())
      return penny::wavevector(grid_, coefficient % grid_.nx, first_line_ + coefficient / grid_.nx);
    const unsigned int n_y = grid_.ny / 2 + 1;
    return penny::wavevector(grid_, coefficient / n_y, coefficient % n_y);
  }

  template <typename Real>
  typename BasicFourierTransform<Real>::Spectrum
  BasicFourierTransform<Real>::forward(const GridField &field) const
  {
    for_each_point([&](const std::size_t i, const std::size_t w) { real_buffer[w] = field[i]; });
    transform_forward();
    const Real scale = Real(1) / grid_.n_points();
    Spectrum   coefficients(spectrum_buffer, spectrum_buffer + n_coefficients_);
    for (auto &c : coefficients)
      c *= scale;
    return coefficients;
  }

  template <typename Real> GridField BasicFourierTransform<Real>::inverse(const Spectrum &coefficients) const
  {
    std::copy(coefficients.begin(), coefficients.end(), spectrum_buffer);
    transform_inverse();
    GridField field(n_local_points());
    for_each_point([&](const std::size_t i, const std::size_t w) { field[i] = real_buffer[w]; });
    return field;
  }

  template <typename Real>
  typename BasicFourierTransform<Real>::Spectrum BasicFourierTransform<Real>::tabulate(
      const std::function<std::complex<double>(const Wavevector &)> &multiplier) const
  {
    Spectrum table(n_coefficients_);
    for (std::size_t c = 0; c < table.size(); ++c)
      table[c] = std::complex<Real>(multiplier(wavevector(c)));
    return table;
  }

  template <typename Real>
  typename BasicFourierTransform<Real>::RealMultiplier BasicFourierTransform<Real>::tabulate_real(
      const std::function<double(const Wavevector &)> &multiplier) const
  {
    RealMultiplier table(n_coefficients_);
    for (std::size_t c = 0; c < table.size(); ++c)
      table[c] = Real(multiplier(wavevector(c)));
    return table;
  }

  template <typename Real>
  void BasicFourierTransform<Real>::apply(const Spectrum &multiplier, const GridField &in,
                                          GridField &out) const
  {
    for_each_point([&](const std::size_t i, const std::size_t w) { real_buffer[w] = in[i]; });
    convolve(multiplier);
    out.resize(n_local_points());
    for_each_point([&](const std::size_t i, const std::size_t w) { out[i] = real_buffer[w]; });
  }

  template <typename Real>
  void BasicFourierTransform<Real>::convolve_work_array(const RealMultiplier &multiplier) const
  {
    convolve(multiplier);
  }

  template <typename Real>
  template <typename Multiplier>
  void BasicFourierTransform<Real>::convolve(const Multiplier &multiplier) const
  {
    transform_forward();
    const Real          scale    = Real(1) / grid_.n_points();
    std::complex<Real> *spectrum = spectrum_buffer;
    for (std::size_t c = 0; c < multiplier.size(); ++c)
      spectrum[c] *= scale * multiplier[c];
    transform_inverse();
  }

  template <typename Real>
  double BasicFourierTransform<Real>::quadratic_form_of_work_array(const RealMultiplier &multiplier) const
  {
    transform_forward();
    const std::complex<Real> *spectrum = spectrum_buffer;
    const auto term = [&](const std::size_t c) { return double(multiplier[c]) * std::norm(spectrum[c]); };
    double     sum  = 0;
    for (std::size_t c = 0; c < multiplier.size(); ++c)
      sum += term(c);
    // Each coefficient stands for itself and its conjugate at -q, except on
    // the lines ky = 0 and ky = ny/2 (ny even), which hold both.
    std::vector<unsigned int> own_lines{0};
    if (grid_.ny % 2 == 0)
      own_lines.push_back(grid_.ny / 2);
    double on_own_lines = 0;
    for (const unsigned int ky : own_lines)
      if (line_owner(ky) == rank_)
        for (unsigned int i = 0; i < grid_.nx; ++i)
          on_own_lines += term(split() ? std::size_t(ky - first_line_) * grid_.nx + i
                                       : std::size_t(i) * (grid_.ny / 2 + 1) + ky);
    const double scale = 1. / grid_.n_points();
    return this->sum(2 * sum - on_own_lines) * scale * scale;
  }

  template <typename Real> double BasicFourierTransform<Real>::sum(const double local) const
  {
    double value = local;
    sum_in_place(&value, 1);
    return value;
  }

  template <typename Real>
  void BasicFourierTransform<Real>::sum_in_place(double *const values, const int n) const
  {
    if (split())
      MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, communicator_);
  }

  template <typename Real> double BasicFourierTransform<Real>::minimum(const double local) const
  {
    double value = local;
    if (split())
      MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, communicator_);
    return value;
  }

  template class BasicFourierTransform<double>;
  template class BasicFourierTransform<float>;

  std::complex<double> derivative_factor(const Wavevector &q, const unsigned int order_x,
                                         const unsigned int order_y)
  {
    if ((q.nyquist_x && order_x % 2 == 1) || (q.nyquist_y && order_y % 2 == 1))
      return 0;
    std::complex<double> factor = 1;
    for (unsigned int n = 0; n < order_x; ++n)
      factor *= std::complex<double>(0, q.qx);
    for (unsigned int n = 0; n < order_y; ++n)
      factor *= std::complex<double>(0, q.qy);
    return factor;
  }
  GridField spectral_derivative(const FourierTransform &transform, const GridField &field,
                                const unsigned int order_x, const unsigned int order_y)
  {
    const auto multiplier =
        transform.tabulate([=](const Wavevector &q) { return derivative_factor(q, order_x, order_y); });
    GridField derivative;
    transform.apply(multiplier, field, derivative);
    return derivative;
  }
} // namespace penny
