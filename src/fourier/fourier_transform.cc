#include "fourier/fourier_transform.h"

#include <fftw3-mpi.h>

#include <algorithm>
#include <cmath>
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
  } // namespace

  FourierTransform::FourierTransform(const PeriodicGrid &grid, const Planning planning,
                                     const MPI_Comm communicator)
      : grid_(grid), planning_(planning), communicator_(communicator), rank_(0), first_row_(0),
        n_rows_(grid.nx), n_coefficients_(std::size_t(grid.nx) * (grid.ny / 2 + 1))
  {
    if (grid.nx == 0 || grid.ny == 0 || !(grid.lx > 0) || !(grid.ly > 0))
      throw std::invalid_argument("FourierTransform: the grid needs nx, ny >= 1 points and lx, ly > 0");
    int ranks = 1;
    if (communicator != MPI_COMM_SELF)
      MPI_Comm_size(communicator, &ranks);
    // In place, rows padded to 2 (ny/2 + 1) values (about a tenth faster than
    // out of place at 2048^2). FFTW_MEASURE overwrites the array while it
    // plans; it holds nothing yet.
    const unsigned int flags   = planning == Planning::estimate ? FFTW_ESTIMATE : FFTW_MEASURE;
    const ptrdiff_t    n_lines = grid.ny / 2 + 1;
    row_stride_                = 2 * n_lines;
    if (ranks == 1)
      {
        real_buffer    = fftw_alloc_real(2 * n_coefficients_);
        auto *spectrum = reinterpret_cast<fftw_complex *>(real_buffer);
        forward_plan   = fftw_plan_dft_r2c_2d(grid.nx, grid.ny, real_buffer, spectrum, flags);
        inverse_plan   = fftw_plan_dft_c2r_2d(grid.nx, grid.ny, spectrum, real_buffer, flags);
        return;
      }
    // A slab of rows per rank; the spectrum's lines ky split over the ranks
    // as the omitted transpose left them. FFTW's MPI planner times
    // collectively, so FFTW_MEASURE picks one algorithm on every rank.
    MPI_Comm_rank(communicator, &rank_);
    static const bool initialised = (fftw_mpi_init(), true);
    (void)initialised;
    ptrdiff_t       rows, row, lines, line;
    const ptrdiff_t complex_size =
        fftw_mpi_local_size_2d_transposed(grid.nx, n_lines, communicator, &rows, &row, &lines, &line);
    first_row_      = rows > 0 ? row : 0;
    n_rows_         = rows;
    first_line_     = lines > 0 ? line : 0;
    n_coefficients_ = std::size_t(lines) * grid.nx;
    row_starts      = block_starts(communicator, n_rows_);
    line_starts     = block_starts(communicator, lines);
    real_buffer     = fftw_alloc_real(2 * std::max<ptrdiff_t>(complex_size, 1));
    auto *spectrum  = reinterpret_cast<fftw_complex *>(real_buffer);
    forward_plan    = fftw_mpi_plan_dft_r2c_2d(grid.nx, grid.ny, real_buffer, spectrum, communicator,
                                               flags | FFTW_MPI_TRANSPOSED_OUT);
    inverse_plan    = fftw_mpi_plan_dft_c2r_2d(grid.nx, grid.ny, spectrum, real_buffer, communicator,
                                               flags | FFTW_MPI_TRANSPOSED_IN);
  }

  FourierTransform::~FourierTransform()
  {
    fftw_destroy_plan(static_cast<fftw_plan>(forward_plan));
    fftw_destroy_plan(static_cast<fftw_plan>(inverse_plan));
    fftw_free(real_buffer);
  }

  int FourierTransform::n_ranks() const
  {
    return split() ? int(row_starts.size()) - 1 : 1;
  }

  std::pair<unsigned int, unsigned int> FourierTransform::rows_of(const int rank) const
  {
    if (!split())
      return {0, grid_.nx};
    return {row_starts[rank], row_starts[rank + 1] - row_starts[rank]};
  }

  int FourierTransform::row_owner(const unsigned int i) const
  {
    return split() ? owner(row_starts, i) : 0;
  }

  int FourierTransform::line_owner(const unsigned int ky) const
  {
    return split() ? owner(line_starts, ky) : 0;
  }

  Wavevector FourierTransform::wavevector(const std::size_t coefficient) const
  {
    if (split())
      return penny::wavevector(grid_, coefficient % grid_.nx, first_line_ + coefficient / grid_.nx);
    const unsigned int n_y = grid_.ny / 2 + 1;
    return penny::wavevector(grid_, coefficient / n_y, coefficient % n_y);
  }

  FourierTransform::Spectrum FourierTransform::forward(const GridField &field) const
  {
    for_each_point([&](const std::size_t i, const std::size_t w) { real_buffer[w] = field[i]; });
    fftw_execute(static_cast<fftw_plan>(forward_plan));
    const double scale = 1. / grid_.n_points();
    Spectrum     coefficients(spectrum_buffer(), spectrum_buffer() + n_coefficients_);
    for (auto &c : coefficients)
      c *= scale;
    return coefficients;
  }

  GridField FourierTransform::inverse(const Spectrum &coefficients) const
  {
    std::copy(coefficients.begin(), coefficients.end(), spectrum_buffer());
    fftw_execute(static_cast<fftw_plan>(inverse_plan));
    GridField field(n_local_points());
    for_each_point([&](const std::size_t i, const std::size_t w) { field[i] = real_buffer[w]; });
    return field;
  }

  FourierTransform::Spectrum
  FourierTransform::tabulate(const std::function<std::complex<double>(const Wavevector &)> &multiplier) const
  {
    Spectrum table(n_coefficients_);
    for (std::size_t c = 0; c < table.size(); ++c)
      table[c] = multiplier(wavevector(c));
    return table;
  }

  void FourierTransform::apply(const Spectrum &multiplier, const GridField &in, GridField &out) const
  {
    for_each_point([&](const std::size_t i, const std::size_t w) { real_buffer[w] = in[i]; });
    convolve_work_array(multiplier);
    out.resize(n_local_points());
    for_each_point([&](const std::size_t i, const std::size_t w) { out[i] = real_buffer[w]; });
  }

  void FourierTransform::convolve_work_array(const Spectrum &multiplier) const
  {
    fftw_execute(static_cast<fftw_plan>(forward_plan));
    const double          scale    = 1. / grid_.n_points();
    std::complex<double> *spectrum = spectrum_buffer();
    for (std::size_t c = 0; c < multiplier.size(); ++c)
      spectrum[c] *= scale * multiplier[c];
    fftw_execute(static_cast<fftw_plan>(inverse_plan));
  }

  double FourierTransform::quadratic_form_of_work_array(const Spectrum &multiplier) const
  {
    fftw_execute(static_cast<fftw_plan>(forward_plan));
    const std::complex<double> *spectrum = spectrum_buffer();
    const auto term = [&](const std::size_t c) { return multiplier[c].real() * std::norm(spectrum[c]); };
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

  double FourierTransform::sum(const double local) const
  {
    double value = local;
    sum_in_place(&value, 1);
    return value;
  }

  void FourierTransform::sum_in_place(double *const values, const int n) const
  {
    if (split())
      MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, communicator_);
  }

  double FourierTransform::minimum(const double local) const
  {
    double value = local;
    if (split())
      MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, communicator_);
    return value;
  }

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
