#include "fourier/fourier_transform.h"

#include <fftw3.h>

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

  FourierTransform::FourierTransform(const PeriodicGrid &grid, const Planning planning) : grid_(grid)
  {
    if (grid.nx == 0 || grid.ny == 0 || !(grid.lx > 0) || !(grid.ly > 0))
      throw std::invalid_argument("FourierTransform: the grid needs nx, ny >= 1 points and lx, ly > 0");
    real_buffer    = fftw_alloc_real(grid.n_points());
    complex_buffer = reinterpret_cast<std::complex<double> *>(fftw_alloc_complex(n_coefficients()));
    // FFTW_MEASURE overwrites the arrays while it plans; they hold nothing yet.
    const unsigned int flags    = planning == Planning::estimate ? FFTW_ESTIMATE : FFTW_MEASURE;
    auto              *spectrum = reinterpret_cast<fftw_complex *>(complex_buffer);
    forward_plan                = fftw_plan_dft_r2c_2d(grid.nx, grid.ny, real_buffer, spectrum, flags);
    inverse_plan                = fftw_plan_dft_c2r_2d(grid.nx, grid.ny, spectrum, real_buffer, flags);
  }

  FourierTransform::~FourierTransform()
  {
    fftw_destroy_plan(static_cast<fftw_plan>(forward_plan));
    fftw_destroy_plan(static_cast<fftw_plan>(inverse_plan));
    fftw_free(real_buffer);
    fftw_free(complex_buffer);
  }

  Wavevector FourierTransform::wavevector(const std::size_t coefficient) const
  {
    const unsigned int n_y = grid_.ny / 2 + 1;
    const unsigned int i = coefficient / n_y, j = coefficient % n_y;
    const int          kx = i <= grid_.nx / 2 ? int(i) : int(i) - int(grid_.nx);
    const int          ky = j;
    return {kx,
            ky,
            2 * M_PI * kx / grid_.lx,
            2 * M_PI * ky / grid_.ly,
            grid_.nx % 2 == 0 && i == grid_.nx / 2,
            grid_.ny % 2 == 0 && j == grid_.ny / 2};
  }

  FourierTransform::Spectrum FourierTransform::forward(const GridField &field) const
  {
    std::copy(field.begin(), field.end(), real_buffer);
    fftw_execute(static_cast<fftw_plan>(forward_plan));
    const double scale = 1. / grid_.n_points();
    Spectrum     coefficients(complex_buffer, complex_buffer + n_coefficients());
    for (auto &c : coefficients)
      c *= scale;
    return coefficients;
  }

  GridField FourierTransform::inverse(const Spectrum &coefficients) const
  {
    std::copy(coefficients.begin(), coefficients.end(), complex_buffer);
    fftw_execute(static_cast<fftw_plan>(inverse_plan));
    return GridField(real_buffer, real_buffer + grid_.n_points());
  }

  FourierTransform::Spectrum
  FourierTransform::tabulate(const std::function<std::complex<double>(const Wavevector &)> &multiplier) const
  {
    Spectrum table(n_coefficients());
    for (std::size_t c = 0; c < table.size(); ++c)
      table[c] = multiplier(wavevector(c));
    return table;
  }

  void FourierTransform::apply(const Spectrum &multiplier, const GridField &in, GridField &out) const
  {
    std::copy(in.begin(), in.end(), real_buffer);
    convolve_work_array(multiplier);
    out.assign(real_buffer, real_buffer + grid_.n_points());
  }

  void FourierTransform::convolve_work_array(const Spectrum &multiplier) const
  {
    fftw_execute(static_cast<fftw_plan>(forward_plan));
    const double scale = 1. / grid_.n_points();
    for (std::size_t c = 0; c < multiplier.size(); ++c)
      complex_buffer[c] *= scale * multiplier[c];
    fftw_execute(static_cast<fftw_plan>(inverse_plan));
    ++n_convolutions;
  }

  double FourierTransform::quadratic_form_of_work_array(const Spectrum &multiplier) const
  {
    fftw_execute(static_cast<fftw_plan>(forward_plan));
    // Each coefficient with 0 < ky < ny/2 stands for itself and its conjugate at -q.
    const unsigned int n_y = grid_.ny / 2 + 1;
    double             sum = 0;
    for (std::size_t c = 0; c < multiplier.size(); ++c)
      {
        const unsigned int j      = c % n_y;
        const double       weight = j == 0 || (grid_.ny % 2 == 0 && j == grid_.ny / 2) ? 1 : 2;
        sum += weight * multiplier[c].real() * std::norm(complex_buffer[c]);
      }
    const double scale = 1. / grid_.n_points();
    return sum * scale * scale;
  }

  GridField resampled(const FourierTransform &from, const FourierTransform &to, const GridField &field)
  {
    const PeriodicGrid &a = from.grid(), &b = to.grid();
    if (a.lx != b.lx || a.ly != b.ly)
      throw std::invalid_argument("resampled: the grids must cover the same rectangle");
    const FourierTransform::Spectrum in = from.forward(field);
    FourierTransform::Spectrum       out(to.n_coefficients(), 0.);
    // Integer wavenumbers |kx| < kx_limit, 0 <= ky < ky_limit on both grids.
    const int          kx_limit = (std::min(a.nx, b.nx) + 1) / 2, ky_limit = (std::min(a.ny, b.ny) + 1) / 2;
    const unsigned int a_ny = a.ny / 2 + 1, b_ny = b.ny / 2 + 1;
    for (int kx = 1 - kx_limit; kx < kx_limit; ++kx)
      for (int ky = 0; ky < ky_limit; ++ky)
        out[((kx + b.nx) % b.nx) * b_ny + ky] = in[((kx + a.nx) % a.nx) * a_ny + ky];
    return to.inverse(out);
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

  std::optional<PeriodicGrid> halved(const PeriodicGrid &grid, const unsigned int smallest)
  {
    const auto halvable = [=](const unsigned int n) { return n == 1 || (n % 2 == 0 && n / 2 >= smallest); };
    if (!halvable(grid.nx) || !halvable(grid.ny) || (grid.nx == 1 && grid.ny == 1))
      return std::nullopt;
    return PeriodicGrid{grid.nx == 1 ? 1 : grid.nx / 2, grid.ny == 1 ? 1 : grid.ny / 2, grid.lx, grid.ly};
  }

  GridField interpolated(const PeriodicGrid &coarse, const GridField &field, const PeriodicGrid &fine)
  {
    const unsigned int sx = fine.nx / coarse.nx, sy = fine.ny / coarse.ny;
    GridField          result(fine.n_points());
    for (unsigned int i = 0; i < fine.nx; ++i)
      for (unsigned int j = 0; j < fine.ny; ++j)
        {
          const unsigned int a = i / sx, b = j / sy, a1 = (a + 1) % coarse.nx, b1 = (b + 1) % coarse.ny;
          const double       tx = double(i % sx) / sx, ty = double(j % sy) / sy;
          const auto         at = [&](const unsigned int x, const unsigned int y) {
            return field[x * coarse.ny + y];
          };
          result[i * fine.ny + j] = (1 - tx) * ((1 - ty) * at(a, b) + ty * at(a, b1)) +
                                    tx * ((1 - ty) * at(a1, b) + ty * at(a1, b1));
        }
    return result;
  }
} // namespace penny
