#include "statistics/random_field.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace penny
{
  namespace
  {
    // One step of SplitMix64: the golden-ratio increment and its bijective
    // 64-bit mixing function.
    std::uint64_t splitmix64(std::uint64_t z)
    {
      z += 0x9e3779b97f4a7c15ULL;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      return z ^ (z >> 31);
    }

    // The top 53 bits as a double in [0, 1).
    double unit_interval(const std::uint64_t bits)
    {
      return (bits >> 11) * 0x1.0p-53;
    }

    // Two independent standard normal numbers keyed on (seed, kx, ky): the
    // first two outputs of SplitMix64 started at the key, through Box-Muller.
    std::complex<double> gaussian_pair(const std::uint64_t seed, const int kx, const int ky)
    {
      const std::uint64_t key = splitmix64(splitmix64(splitmix64(seed) ^ std::uint64_t(std::int64_t(kx))) ^
                                           std::uint64_t(std::int64_t(ky)));
      const double        u1  = unit_interval(splitmix64(key));
      const double        u2  = unit_interval(splitmix64(key + 0x9e3779b97f4a7c15ULL));
      const double        r   = std::sqrt(-2 * std::log1p(-u1));
      return std::polar(r, 2 * M_PI * u2);
    }

    // <f^2> over the grid (its local rows on a split grid).
    double mean_square(const FourierTransform &transform, const GridField &field)
    {
      return transform.sum(std::inner_product(field.begin(), field.end(), field.begin(), 0.)) /
             transform.grid().n_points();
    }
  } // namespace

  double spectral_density(const PowerSpectrum &spectrum, double q)
  {
    const std::vector<double> &q_table = spectrum.wavenumbers;
    if (q < q_table.front() * (1 - 1e-12) || q > q_table.back() * (1 + 1e-12))
      return 0;
    q = std::clamp(q, q_table.front(), q_table.back());
    const std::size_t i =
        std::min<std::size_t>(std::upper_bound(q_table.begin(), q_table.end(), q) - q_table.begin(),
                              q_table.size() - 1) -
        1;
    const double slope =
        std::log(spectrum.densities[i + 1] / spectrum.densities[i]) / std::log(q_table[i + 1] / q_table[i]);
    return spectrum.densities[i] * std::pow(q / q_table[i], slope);
  }

  PowerSpectrum pressure_spectrum(const PowerSpectrum &heights, const double E_star)
  {
    PowerSpectrum pressure = heights;
    for (std::size_t i = 0; i < pressure.wavenumbers.size(); ++i)
      pressure.densities[i] *= E_star * E_star / 4 * std::pow(pressure.wavenumbers[i], 2);
    return pressure;
  }

  std::uint64_t realisation_seed(const std::uint64_t seed, const std::uint64_t index)
  {
    return splitmix64(splitmix64(seed) ^ index);
  }

  // Every stored coefficient with ky > 0 stands for one conjugate pair; on the
  // line ky = 0 both members are stored, and the one with kx < 0 is set to the
  // conjugate of its partner's draw, so the spectrum is Hermitian by construction.
  FourierTransform::Spectrum gaussian_spectrum(const FourierTransform &transform,
                                               const PowerSpectrum &spectrum, const std::uint64_t seed)
  {
    const PeriodicGrid        &grid = transform.grid();
    const double               cell = (2 * M_PI / grid.lx) * (2 * M_PI / grid.ly);
    FourierTransform::Spectrum coefficients(transform.n_coefficients());
    for (std::size_t c = 0; c < coefficients.size(); ++c)
      {
        const Wavevector q = transform.wavevector(c);
        if ((q.kx == 0 && q.ky == 0) || q.nyquist_x || q.nyquist_y)
          continue;
        const double C = spectral_density(spectrum, q.norm());
        if (C == 0)
          continue;
        const double amplitude = std::sqrt(C * cell / 2);
        coefficients[c]        = q.ky > 0 || q.kx > 0 ? amplitude * gaussian_pair(seed, q.kx, q.ky)
                                                      : amplitude * std::conj(gaussian_pair(seed, -q.kx, 0));
      }
    return coefficients;
  }

  GridField gaussian_field(const FourierTransform &transform, const PowerSpectrum &spectrum,
                           const std::uint64_t seed)
  {
    return transform.inverse(gaussian_spectrum(transform, spectrum, seed));
  }

  FieldMoments isotropic_moments(const double m0, const double m2, const double m4)
  {
    return {m0, m2, m4, m4 / 3};
  }

  FieldMoments sampled_moments(const FourierTransform &transform, const GridField &field)
  {
    const double mean =
        transform.sum(std::accumulate(field.begin(), field.end(), 0.)) / transform.grid().n_points();
    const auto derivative_square = [&](const unsigned int order_x, const unsigned int order_y) {
      return mean_square(transform, spectral_derivative(transform, field, order_x, order_y));
    };
    return {mean_square(transform, field) - mean * mean, derivative_square(1, 0), derivative_square(2, 0),
            derivative_square(1, 1)};
  }

  LatticeMoments lattice_moments(const PeriodicGrid &grid, const PowerSpectrum &spectrum)
  {
    // The modes in FFTW's serial order, kx the slow index; no grid is held.
    const double cell   = (2 * M_PI / grid.lx) * (2 * M_PI / grid.ly);
    double       sum[4] = {0, 0, 0, 0}, sum_of_squares[4] = {0, 0, 0, 0};
    for (std::size_t c = 0; c < std::size_t(grid.nx) * (grid.ny / 2 + 1); ++c)
      {
        const Wavevector q = wavevector(grid, c / (grid.ny / 2 + 1), c % (grid.ny / 2 + 1));
        if ((q.kx == 0 && q.ky == 0) || q.nyquist_x || q.nyquist_y)
          continue;
        // A stored coefficient with ky > 0 stands for itself and its conjugate.
        const double multiplicity = q.ky > 0 ? 2 : 1;
        const double term         = spectral_density(spectrum, q.norm()) * cell;
        const double qx2 = q.qx * q.qx, qy2 = q.qy * q.qy;
        const double terms[4] = {term, term * qx2, term * qx2 * qx2, term * qx2 * qy2};
        for (int n = 0; n < 4; ++n)
          {
            sum[n] += multiplicity * terms[n];
            sum_of_squares[n] += multiplicity * terms[n] * terms[n];
          }
      }
    const auto deviation = [&](const int n) { return std::sqrt(2 * sum_of_squares[n]); };
    return {{sum[0], sum[1], sum[2], sum[3]}, {deviation(0), deviation(1), deviation(2), deviation(3)}};
  }
} // namespace penny
