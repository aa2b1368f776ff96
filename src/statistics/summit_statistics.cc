#include "statistics/summit_statistics.h"

#include "closed_forms/adhesive_gap.h"
#include "contact/half_space.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penny
{
  namespace
  {
    double normal_density(const double x, const double variance)
    {
      return std::exp(-x * x / (2 * variance)) / std::sqrt(2 * M_PI * variance);
    }

    // int_0^inf s^k N(s; mu, v) ds for k = 0 ... 3, with t = mu/sqrt(v):
    // the moments of a Gaussian restricted to s > 0.
    double positive_moment(const unsigned int k, const double mu, const double v)
    {
      const double sd = std::sqrt(v), t = mu / sd;
      const double Phi = std::erfc(-t / std::sqrt(2.)) / 2, phi = normal_density(t, 1);
      switch (k)
        {
        case 0:
          return Phi;
        case 1:
          return mu * Phi + sd * phi;
        case 2:
          return (mu * mu + v) * Phi + mu * sd * phi;
        default:
          return (mu * mu * mu + 3 * mu * v) * Phi + sd * (mu * mu + 2 * v) * phi;
        }
    }

    // int_0^inf s^k K(s) N(s; mu, v) ds, k = 0 or 1, with the summit weight
    // K(s) = E[(s^2 - d1^2 - d2^2) 1{d1^2 + d2^2 < s^2}] over the deviator
    // (d1, d2) ~ N(0, diag(v1, v2)). In polar coordinates (rho, theta) of the
    // deviator, with b = cos^2/(2 v1) + sin^2/(2 v2),
    //   K(s) = 1/(2 pi sqrt(v1 v2)) int_0^2pi (b s^2 - 1 + exp(-b s^2))/(2 b^2) dtheta,
    // and exp(-b s^2) N(s; mu, v) = sqrt(pi/b) N(mu; 0, 1/(2b) + v) N(s; mu', v')
    // with 1/v' = 1/v + 2b, mu' = mu v'/v.
    double weighted_moment(const unsigned int k, const double mu, const double v, const double v1,
                           const double v2)
    {
      const unsigned int n_angles = 64;
      double             sum      = 0;
      for (unsigned int i = 0; i < n_angles; ++i)
        {
          const double theta = 2 * M_PI * (i + 0.5) / n_angles;
          const double b = std::pow(std::cos(theta), 2) / (2 * v1) + std::pow(std::sin(theta), 2) / (2 * v2);
          const double v_b       = 1 / (2 * b);
          const double v_product = v * v_b / (v + v_b), mu_product = mu * v_product / v;
          sum += (b * positive_moment(k + 2, mu, v) - positive_moment(k, mu, v) +
                  std::sqrt(M_PI / b) * normal_density(mu, v_b + v) *
                      positive_moment(k, mu_product, v_product)) /
                 (2 * b * b);
        }
      return sum / (n_angles * std::sqrt(v1 * v2));
    }

    // The summit weight K(s) itself, the same angular sum; x + expm1(-x) is
    // b s^2 - 1 + exp(-b s^2) without cancellation down to x ~ 1e-5, below
    // which its series x^2/2 - x^3/6 takes over.
    double summit_weight(const double s, const double v1, const double v2)
    {
      const unsigned int n_angles = 64;
      double             sum      = 0;
      for (unsigned int i = 0; i < n_angles; ++i)
        {
          const double theta = 2 * M_PI * (i + 0.5) / n_angles;
          const double b = std::pow(std::cos(theta), 2) / (2 * v1) + std::pow(std::sin(theta), 2) / (2 * v2);
          const double x = b * s * s;
          sum += (x < 1e-5 ? x * x / 2 - x * x * x / 6 : x + std::expm1(-x)) / (2 * b * b);
        }
      return sum / (n_angles * std::sqrt(v1 * v2));
    }

    // The variances of the mean curvature s (unconditioned) and of the two
    // deviatoric components.
    struct HessianVariances
    {
      double s, d1, d2;
    };

    HessianVariances hessian_variances(const FieldMoments &m)
    {
      if (!summits_have_expectation(m))
        throw std::domain_error("summit statistics need (m4 + m22)/2 > m2^2/m0 and 0 < m22 < m4");
      return {(m.m4 + m.m22) / 2, (m.m4 - m.m22) / 2, m.m22};
    }

    // Mean and standard error of the mean of M numbers.
    Estimate sample_mean(const std::vector<double> &values)
    {
      const double M    = values.size();
      double       mean = 0, spread = 0;
      for (const double v : values)
        mean += v / M;
      for (const double v : values)
        spread += (v - mean) * (v - mean);
      return {mean, M > 1 ? std::sqrt(spread / (M - 1) / M) : NAN};
    }
  } // namespace

  std::vector<Summit> find_summits(const FourierTransform &transform, const GridField &field)
  {
    if (transform.split())
      throw std::invalid_argument("find_summits: summits need their neighbours on the whole grid, and the "
                                  "grid is split over ranks");
    const PeriodicGrid &grid = transform.grid();
    const int           nx = grid.nx, ny = grid.ny;
    const double        dx = grid.lx / nx, dy = grid.ly / ny, cell = std::min(dx, dy);

    // The field's spectrum once; each derivative is one inverse transform.
    const FourierTransform::Spectrum spectrum   = transform.forward(field);
    const auto                       derivative = [&](const unsigned int ox, const unsigned int oy) {
      FourierTransform::Spectrum coefficients = spectrum;
      for (std::size_t c = 0; c < coefficients.size(); ++c)
        coefficients[c] *= derivative_factor(transform.wavevector(c), ox, oy);
      return transform.inverse(coefficients);
    };
    const GridField f_x = derivative(1, 0), f_y = derivative(0, 1);
    const GridField f_xx = derivative(2, 0), f_xy = derivative(1, 1), f_yy = derivative(0, 2);
    const GridField f_xxx = derivative(3, 0), f_xxy = derivative(2, 1), f_xyy = derivative(1, 2),
                    f_yyy = derivative(0, 3);
    const auto index      = [&](const long i, const long j) {
      return std::size_t((i % nx + nx) % nx) * ny + std::size_t((j % ny + ny) % ny);
    };

    // Value, gradient and Hessian at (x, y) from the cubic Taylor model about
    // the grid point (i, j).
    struct Jet
    {
      double value, gx, gy, hxx, hxy, hyy;
    };
    const auto jet = [&](const long i, const long j, const double x, const double y) {
      const std::size_t k  = index(i, j);
      const double      rx = x - i * dx, ry = y - j * dy;
      const double      txxx = f_xxx[k], txxy = f_xxy[k], txyy = f_xyy[k], tyyy = f_yyy[k];
      Jet               J;
      J.hxx = f_xx[k] + txxx * rx + txxy * ry;
      J.hxy = f_xy[k] + txxy * rx + txyy * ry;
      J.hyy = f_yy[k] + txyy * rx + tyyy * ry;
      J.gx  = f_x[k] + (f_xx[k] + J.hxx) / 2 * rx + (f_xy[k] + J.hxy) / 2 * ry;
      J.gy  = f_y[k] + (f_xy[k] + J.hxy) / 2 * rx + (f_yy[k] + J.hyy) / 2 * ry;
      J.value =
          field[k] + f_x[k] * rx + f_y[k] * ry +
          (f_xx[k] * rx * rx + 2 * f_xy[k] * rx * ry + f_yy[k] * ry * ry) / 2 +
          (txxx * rx * rx * rx + 3 * txxy * rx * rx * ry + 3 * txyy * rx * ry * ry + tyyy * ry * ry * ry) / 6;
      return J;
    };

    std::vector<Summit> summits;
    std::vector<int>    owner(grid.n_points(), -1); // a kept summit's index at its nearest grid point
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j)
        {
          const std::size_t p         = index(i, j);
          bool              is_summit = true;
          for (int di = -1; di <= 1 && is_summit; ++di)
            for (int dj = -1; dj <= 1 && is_summit; ++dj)
              {
                const std::size_t n = index(i + di, j + dj);
                if (n != p && !(field[p] > field[n] || (field[p] == field[n] && p < n)))
                  is_summit = false;
              }
          if (!is_summit)
            continue;

          // Newton's method on the Taylor models, steps at most a cell long.
          // The first five steps re-expand about the nearest grid point, the
          // rest keep the last one (near a cell boundary two models could
          // otherwise hand the iterate back and forth). The maximum must be
          // reached within two cells with -H positive definite all the way:
          // a grid maximum on a nearly flat ridge that leads to no maximum is
          // not a summit.
          double x = i * dx, y = j * dy;
          long   ci = i, cj = j;
          Jet    J         = jet(ci, cj, x, y);
          bool   converged = false;
          for (unsigned int iteration = 0; iteration < 25 && !converged; ++iteration)
            {
              const double det = J.hxx * J.hyy - J.hxy * J.hxy;
              if (!(det > 0 && J.hxx < 0))
                break;
              double sx = -(J.hyy * J.gx - J.hxy * J.gy) / det, sy = -(J.hxx * J.gy - J.hxy * J.gx) / det;
              const double length = std::hypot(sx, sy);
              if (length > cell)
                sx *= cell / length, sy *= cell / length;
              x += sx;
              y += sy;
              if (std::hypot(x - i * dx, y - j * dy) > 2 * cell)
                break;
              if (iteration < 5)
                ci = std::lround(x / dx), cj = std::lround(y / dy);
              J         = jet(ci, cj, x, y);
              converged = length < 1e-10 * cell;
            }
          if (!converged || !(J.hxx * J.hyy - J.hxy * J.hxy > 0 && J.hxx < 0))
            continue;

          // Grid maxima on a ridge oblique to the grid can reach the same
          // summit: one summit per half cell.
          Summit summit;
          summit.x       = std::fmod(x + grid.lx, grid.lx);
          summit.y       = std::fmod(y + grid.ly, grid.ly);
          const long k_i = std::lround(summit.x / dx), k_j = std::lround(summit.y / dy);
          bool       duplicate = false;
          for (int di = -1; di <= 1; ++di)
            for (int dj = -1; dj <= 1; ++dj)
              {
                const int other = owner[index(k_i + di, k_j + dj)];
                if (other >= 0)
                  {
                    const double sx = std::abs(summits[other].x - summit.x),
                                 sy = std::abs(summits[other].y - summit.y);
                    duplicate       = duplicate ||
                                std::hypot(std::min(sx, grid.lx - sx), std::min(sy, grid.ly - sy)) < cell / 2;
                  }
              }
          if (duplicate)
            continue;
          const double mean = -(J.hxx + J.hyy) / 2, deviator = std::hypot((J.hxx - J.hyy) / 2, J.hxy);
          summit.height          = J.value;
          summit.curvature_min   = mean - deviator;
          summit.curvature_max   = mean + deviator;
          owner[index(k_i, k_j)] = summits.size();
          summits.push_back(summit);
        }
    return summits;
  }

  std::vector<double> SummitSample::pack() const
  {
    std::vector<double> row = {area, n_summits, curvature_sum};
    row.insert(row.end(), bin_counts.begin(), bin_counts.end());
    row.insert(row.end(), bin_curvature_sums.begin(), bin_curvature_sums.end());
    row.insert(row.end(), bin_curvature_squares.begin(), bin_curvature_squares.end());
    return row;
  }

  SummitSample SummitSample::unpack(const std::vector<double> &row, const unsigned int n_bins)
  {
    if (row.size() != 3 + 3 * std::size_t(n_bins))
      throw std::invalid_argument("SummitSample::unpack: the row does not hold " + std::to_string(n_bins) +
                                  " height bins");
    const auto bins = [&](const unsigned int block) {
      return std::vector<double>(row.begin() + 3 + block * n_bins, row.begin() + 3 + (block + 1) * n_bins);
    };
    return {row[0], row[1], row[2], bins(0), bins(1), bins(2)};
  }

  SummitSample summarise_summits(const std::vector<Summit> &summits, const double area,
                                 const HeightBins &bins)
  {
    SummitSample sample{area,
                        double(summits.size()),
                        0,
                        std::vector<double>(bins.n),
                        std::vector<double>(bins.n),
                        std::vector<double>(bins.n)};
    for (const Summit &summit : summits)
      {
        const double curvature = summit.mean_curvature();
        sample.curvature_sum += curvature;
        const double position = (summit.height - bins.min) / bins.width();
        if (position >= 0 && position < bins.n)
          {
            const unsigned int b = position;
            sample.bin_counts[b] += 1;
            sample.bin_curvature_sums[b] += curvature;
            sample.bin_curvature_squares[b] += curvature * curvature;
          }
      }
    return sample;
  }

  SummitEnsemble summit_ensemble(const std::vector<SummitSample> &samples, const HeightBins &bins)
  {
    SummitEnsemble ensemble{};
    ensemble.n_realisations = samples.size();
    std::vector<double> densities;
    double              curvature_sum = 0;
    for (const SummitSample &sample : samples)
      {
        densities.push_back(sample.n_summits / sample.area);
        ensemble.n_summits += sample.n_summits;
        curvature_sum += sample.curvature_sum;
      }
    ensemble.density = sample_mean(densities);

    // Ratio estimate sum(curvatures)/sum(counts); by the delta method its
    // variance is that of the mean of (n_r/n_mean) (kappa_r - kappa), kappa_r
    // a realisation's own mean curvature.
    const double        kappa  = curvature_sum / ensemble.n_summits;
    const double        n_mean = ensemble.n_summits / samples.size();
    std::vector<double> deviations;
    for (const SummitSample &sample : samples)
      deviations.push_back((sample.curvature_sum - kappa * sample.n_summits) / n_mean);
    ensemble.mean_curvature = {kappa, sample_mean(deviations).standard_error};

    for (unsigned int b = 0; b < bins.n; ++b)
      {
        SummitEnsemble::Bin bin{};
        bin.height_low  = bins.min + b * bins.width();
        bin.height_high = bin.height_low + bins.width();
        std::vector<double> bin_densities;
        double              sum = 0, squares = 0;
        for (const SummitSample &sample : samples)
          {
            bin_densities.push_back(sample.bin_counts[b] / (sample.area * bins.width()));
            bin.n_summits += sample.bin_counts[b];
            sum += sample.bin_curvature_sums[b];
            squares += sample.bin_curvature_squares[b];
          }
        bin.density_per_height = sample_mean(bin_densities);
        const double n = bin.n_summits, mean = sum / n;
        bin.mean_curvature = {n > 0 ? mean : NAN,
                              n > 1 ? std::sqrt(std::max(0., squares - n * mean * mean) / (n - 1) / n) : NAN};
        ensemble.bins.push_back(bin);
      }
    return ensemble;
  }

  bool summits_have_expectation(const FieldMoments &m)
  {
    return (m.m4 + m.m22) / 2 > m.m2 * m.m2 / m.m0 && m.m22 > 0 && m.m22 < m.m4;
  }

  ExpectedSummits expected_summits(const FieldMoments &m)
  {
    const HessianVariances v  = hessian_variances(m);
    const double           w0 = weighted_moment(0, 0, v.s, v.d1, v.d2);
    return {w0 / (2 * M_PI * m.m2), weighted_moment(1, 0, v.s, v.d1, v.d2) / w0};
  }

  double summit_height_density(const FieldMoments &m, const double height)
  {
    const HessianVariances v = hessian_variances(m);
    return normal_density(height, m.m0) / (2 * M_PI * m.m2) *
           weighted_moment(0, m.m2 * height / m.m0, v.s - m.m2 * m.m2 / m.m0, v.d1, v.d2);
  }

  double summit_mean_curvature_at(const FieldMoments &m, const double height)
  {
    const HessianVariances v  = hessian_variances(m);
    const double           mu = m.m2 * height / m.m0, variance = v.s - m.m2 * m.m2 / m.m0;
    return weighted_moment(1, mu, variance, v.d1, v.d2) / weighted_moment(0, mu, variance, v.d1, v.d2);
  }

  // The inner integral int_0^inf (K(s)/s) N(s; mu(z), v) ds runs over
  // [0, mu + 12 sqrt(v)] (K(s)/s ~ s^3 near 0), the outer one over
  // [p_bar, p_bar + 12 sqrt(m0)] beyond the mean pressure.
  double expected_gap_area(const FieldMoments &m, const double mean_pressure)
  {
    using boost::math::quadrature::gauss_kronrod;
    const HessianVariances v                         = hessian_variances(m);
    const double           variance                  = v.s - m.m2 * m.m2 / m.m0;
    const auto             inverse_curvature_density = [&](const double z) {
      const double mu    = m.m2 * z / m.m0;
      const double upper = std::max(mu, 0.) + 12 * std::sqrt(variance);
      const double inner = gauss_kronrod<double, 31>::integrate(
          [&](const double s) {
            return s > 0 ? summit_weight(s, v.d1, v.d2) / s * normal_density(s - mu, variance) : 0.;
          },
          0., upper, 10, 1e-10);
      return normal_density(z, m.m0) / (2 * M_PI * m.m2) * inner;
    };
    const double start = std::max(mean_pressure, -12 * std::sqrt(m.m0));
    return gauss_kronrod<double, 31>::integrate(
        [&](const double z) { return 3 * M_PI * (z - mean_pressure) * inverse_curvature_density(z); }, start,
        std::max(start, 0.) + 12 * std::sqrt(m.m0), 10, 1e-9);
  }

  double sampled_gap_area(const std::vector<Summit> &summits, const double area, const double mean_pressure,
                          const double K_Ic)
  {
    double sum = 0;
    for (const Summit &summit : summits)
      {
        const double P = summit.height - mean_pressure, R_p = 1 / summit.mean_curvature();
        if (!(P > 0))
          continue;
        if (K_Ic == 0)
          sum += 3 * M_PI * R_p * P;
        else if (const auto c = closed_form::stable_gap_radius(P, R_p, K_Ic))
          sum += M_PI * *c * *c;
      }
    return sum / area;
  }

  TensionSummits tension_summits(const FourierTransform &transform, const GridField &heights,
                                 const double E_star)
  {
    GridField tension = full_contact_pressure(transform, heights, E_star);
    for (double &t : tension)
      t = -t;
    TensionSummits result{sampled_moments(transform, tension), find_summits(transform, tension), 0};
    for (const Summit &summit : result.summits)
      result.mean_curvature += summit.mean_curvature() / result.summits.size();
    return result;
  }
} // namespace penny
