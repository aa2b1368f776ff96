#include "topography/surface_preparation.h"

#include "input/input_error.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <vector>

namespace penny
{
  Topography cropped(const Topography &topography, const unsigned int i0, const unsigned int i1,
                     const unsigned int j0, const unsigned int j1)
  {
    const PeriodicGrid &grid = topography.grid;
    Topography          part = topography;
    part.grid = {i1 - i0, j1 - j0, grid.lx * (i1 - i0) / grid.nx, grid.ly * (j1 - j0) / grid.ny};
    part.heights.clear();
    for (unsigned int i = i0; i < i1; ++i)
      part.heights.insert(part.heights.end(), topography.heights.begin() + std::size_t(i) * grid.ny + j0,
                          topography.heights.begin() + std::size_t(i) * grid.ny + j1);
    return part;
  }

  std::size_t fill_missing_points(Topography &topography)
  {
    const std::size_t nx = topography.grid.nx, ny = topography.grid.ny;
    std::vector<long> unknown(topography.heights.size(), -1);
    long              n_unknowns = 0;
    for (std::size_t k = 0; k < unknown.size(); ++k)
      if (std::isnan(topography.heights[k]))
        unknown[k] = n_unknowns++;
    if (n_unknowns == 0)
      return 0;
    if (static_cast<std::size_t>(n_unknowns) == unknown.size())
      throw InputError("the map holds no measured point to fill the others from");

    // sum over neighbours (h_k - h_n) = 0 at each missing point k, with
    // the spacings' weights 1/dx^2 and 1/dy^2 (pixels need not be square).
    const double wx = 1 / std::pow(topography.grid.lx / nx, 2), wy = 1 / std::pow(topography.grid.ly / ny, 2);
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd                     rhs = Eigen::VectorXd::Zero(n_unknowns);
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
        {
          const long row = unknown[i * ny + j];
          if (row < 0)
            continue;
          double     diagonal = 0;
          const auto couple   = [&](const std::size_t neighbour, const double weight) {
            diagonal += weight;
            if (unknown[neighbour] >= 0)
              entries.emplace_back(row, unknown[neighbour], -weight);
            else
              rhs[row] += weight * topography.heights[neighbour];
          };
          if (i > 0)
            couple((i - 1) * ny + j, wx);
          if (i + 1 < nx)
            couple((i + 1) * ny + j, wx);
          if (j > 0)
            couple(i * ny + j - 1, wy);
          if (j + 1 < ny)
            couple(i * ny + j + 1, wy);
          entries.emplace_back(row, row, diagonal);
        }
    Eigen::SparseMatrix<double> laplacian(n_unknowns, n_unknowns);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    // Every group of missing points touches a measured one (the grid is
    // connected): the matrix is positive definite.
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> cholesky(laplacian);
    const Eigen::VectorXd                                    filled = cholesky.solve(rhs);
    for (std::size_t k = 0; k < unknown.size(); ++k)
      if (unknown[k] >= 0)
        topography.heights[k] = filled[unknown[k]];
    return n_unknowns;
  }

  void detrend(Topography &topography, const Detrending detrending)
  {
    const std::size_t nx = topography.grid.nx, ny = topography.grid.ny;
    const int         n = detrending == Detrending::mean ? 1 : detrending == Detrending::plane ? 3 : 6;
    // The basis in coordinates centred on the map and scaled to [-1/2, 1/2), for conditioning.
    const auto basis = [&](const std::size_t i, const std::size_t j) {
      const double                x = (i + 0.5) / nx - 0.5, y = (j + 0.5) / ny - 0.5;
      Eigen::Matrix<double, 6, 1> b;
      b << 1, x, y, x * x, x * y, y * y;
      return b;
    };
    Eigen::MatrixXd normal  = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd moments = Eigen::VectorXd::Zero(n);
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
        {
          const Eigen::VectorXd b = basis(i, j).head(n);
          normal += b * b.transpose();
          moments += b * topography.heights[i * ny + j];
        }
    const Eigen::VectorXd coefficients = normal.ldlt().solve(moments);
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j)
        topography.heights[i * ny + j] -= basis(i, j).head(n).dot(coefficients);
  }

  SurfaceRoughness surface_roughness(const Topography &topography)
  {
    const std::size_t nx = topography.grid.nx, ny = topography.grid.ny;
    const double      dx = topography.grid.lx / nx, dy = topography.grid.ly / ny;
    const auto h = [&](const std::size_t i, const std::size_t j) { return topography.heights[i * ny + j]; };
    double     mean = 0, squares = 0, slopes = 0, laplacians = 0;
    for (const double value : topography.heights)
      mean += value;
    mean /= topography.heights.size();
    for (const double value : topography.heights)
      squares += (value - mean) * (value - mean);
    for (std::size_t i = 0; i + 1 < nx; ++i)
      for (std::size_t j = 0; j + 1 < ny; ++j)
        slopes += std::pow((h(i + 1, j) - h(i, j)) / dx, 2) + std::pow((h(i, j + 1) - h(i, j)) / dy, 2);
    for (std::size_t i = 1; i + 1 < nx; ++i)
      for (std::size_t j = 1; j + 1 < ny; ++j)
        laplacians += std::pow((h(i + 1, j) - 2 * h(i, j) + h(i - 1, j)) / (dx * dx) +
                                   (h(i, j + 1) - 2 * h(i, j) + h(i, j - 1)) / (dy * dy),
                               2);
    return {std::sqrt(squares / topography.heights.size()), std::sqrt(slopes / ((nx - 1) * (ny - 1))),
            std::sqrt(laplacians / ((nx - 2) * (ny - 2))) / 2};
  }

  PowerSpectrum isotropic_spectrum(const Topography &topography, const bool hann)
  {
    const PeriodicGrid &grid  = topography.grid;
    GridField           field = topography.heights;
    if (hann)
      {
        // w(x) w(y) with w = 1 - cos(2 pi (k + 1/2)/n), whose mean square is 3/2 in each direction.
        const auto window = [](const std::size_t k, const std::size_t n) {
          return (1 - std::cos(2 * M_PI * (k + 0.5) / n)) / std::sqrt(1.5);
        };
        for (std::size_t i = 0; i < grid.nx; ++i)
          for (std::size_t j = 0; j < grid.ny; ++j)
            field[i * grid.ny + j] *= window(i, grid.nx) * window(j, grid.ny);
      }
    const FourierTransform           transform(grid);
    const FourierTransform::Spectrum spectrum = transform.forward(field);
    const double                     q_low    = 2 * M_PI / std::max(grid.lx, grid.ly),
                 q_high                       = M_PI * std::min(grid.nx / grid.lx, grid.ny / grid.ly);
    const double        dq_area               = (2 * M_PI / grid.lx) * (2 * M_PI / grid.ly);
    const unsigned int  per_decade            = 8;
    const unsigned int  n_bins = std::max(1., std::ceil(per_decade * std::log10(q_high / q_low)));
    std::vector<double> sums(n_bins, 0.), counts(n_bins, 0.), q_sums(n_bins, 0.);
    for (std::size_t c = 0; c < transform.n_coefficients(); ++c)
      {
        const Wavevector q    = transform.wavevector(c);
        const double     norm = q.norm();
        if (norm < q_low * (1 - 1e-12) || norm > q_high * (1 + 1e-12))
          continue;
        const auto bin = std::min<std::size_t>(n_bins - 1, std::floor(per_decade * std::log10(norm / q_low)));
        // The half plane ky >= 0 stands for both halves: twice, but once on the lines ky = 0 and ky = ny/2.
        const double multiplicity = q.ky == 0 || q.nyquist_y ? 1 : 2;
        sums[bin] += multiplicity * std::norm(spectrum[c]) / dq_area;
        counts[bin] += multiplicity;
        q_sums[bin] += multiplicity * norm;
      }
    PowerSpectrum psd;
    for (unsigned int b = 0; b < n_bins; ++b)
      if (counts[b] > 0)
        {
          psd.wavenumbers.push_back(q_sums[b] / counts[b]);
          psd.densities.push_back(sums[b] / counts[b]);
        }
    return psd;
  }

  GridField gaussian_twin(const FourierTransform &transform, const GridField &heights,
                          const std::uint64_t seed)
  {
    FourierTransform::Spectrum             spectrum = transform.forward(heights);
    std::mt19937_64                        random(seed);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI);
    const unsigned int                     nx = transform.grid().nx;
    std::vector<double>                    line_phases[2];
    for (auto &phases : line_phases)
      for (unsigned int kx = 0; kx <= nx / 2; ++kx)
        phases.push_back(angle(random));
    for (std::size_t c = 0; c < spectrum.size(); ++c)
      {
        const Wavevector q = transform.wavevector(c);
        double           phase;
        if (q.ky == 0 || q.nyquist_y)
          {
            if (q.kx == 0 || q.nyquist_x)
              continue;
            phase = (q.kx > 0 ? 1 : -1) * line_phases[q.ky == 0 ? 0 : 1][std::abs(q.kx)];
          }
        else
          phase = angle(random);
        spectrum[c] *= std::polar(1., phase);
      }
    return transform.inverse(spectrum);
  }

  WavenumberRange reliable_range(const Topography &topography)
  {
    const PeriodicGrid &grid = topography.grid;
    return {4 * M_PI / std::min(grid.lx, grid.ly),
            2 * M_PI / (4 * std::max(grid.lx / grid.nx, grid.ly / grid.ny))};
  }

  PowerLawFit fit_power_law(const PowerSpectrum &spectrum, const WavenumberRange &range)
  {
    std::vector<double> x, y;
    for (std::size_t k = 0; k < spectrum.wavenumbers.size(); ++k)
      if (spectrum.wavenumbers[k] >= range.q_low && spectrum.wavenumbers[k] <= range.q_high &&
          spectrum.densities[k] > 0)
        {
          x.push_back(std::log10(spectrum.wavenumbers[k] / range.q_low));
          y.push_back(std::log10(spectrum.densities[k]));
        }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (x.size() < 3)
      return {nan, nan, range.q_low, range.q_high, nan, nan, static_cast<unsigned int>(x.size())};
    Eigen::MatrixXd A(x.size(), 2);
    Eigen::VectorXd b(x.size());
    for (std::size_t k = 0; k < x.size(); ++k)
      {
        A(k, 0) = 1;
        A(k, 1) = x[k];
        b[k]    = y[k];
      }
    const Eigen::Vector2d line      = A.colPivHouseholderQr().solve(b);
    const Eigen::VectorXd residuals = b - A * line;
    const double          mean      = b.mean();
    const double          total     = (b.array() - mean).square().sum();
    return {-line[1] / 2 - 1,
            std::pow(10., line[0]),
            range.q_low,
            range.q_high,
            std::sqrt(residuals.squaredNorm() / x.size()),
            total > 0 ? 1 - residuals.squaredNorm() / total : nan,
            static_cast<unsigned int>(x.size())};
  }
} // namespace penny
