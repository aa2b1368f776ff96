#include "contact/half_space_contact.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

namespace penny
{
  namespace
  {
    double mean(const GridField &field)
    {
      return std::accumulate(field.begin(), field.end(), 0.) / field.size();
    }

    // Clip at zero and scale to the mean pressure.
    void make_admissible(GridField &pressure, const double mean_pressure)
    {
      for (double &p : pressure)
        p = std::max(p, 0.);
      const double current = mean(pressure);
      if (!(current > 0))
        throw std::invalid_argument("contact solver: the initial pressure is nowhere positive");
      for (double &p : pressure)
        p *= mean_pressure / current;
    }

    // Shift f by minus its mean over the contact points (p > 0).
    void centre_on_contact(const GridField &pressure, GridField &f)
    {
      double      sum   = 0;
      std::size_t count = 0;
      for (std::size_t i = 0; i < f.size(); ++i)
        if (pressure[i] > 0)
          {
            sum += f[i];
            ++count;
          }
      const double shift = sum / count;
      for (double &value : f)
        value -= shift;
    }
  } // namespace

  HalfSpaceContact::HalfSpaceContact(const FourierTransform &transform, GridField heights,
                                     const double E_star)
      : transform(transform), heights_(std::move(heights)), E_star(E_star)
  {
    if (heights_.size() != transform.grid().n_points())
      throw std::invalid_argument("contact solver: the heights do not match the grid");
    if (!std::all_of(heights_.begin(), heights_.end(), [](double h) { return std::isfinite(h); }))
      throw std::invalid_argument("contact solver: the heights hold NaN or Inf");
    if (!(E_star > 0))
      throw std::invalid_argument("contact solver: E* must be positive");
    const double h_mean = mean(heights_);
    double       square = 0;
    for (const double h : heights_)
      square += (h - h_mean) * (h - h_mean);
    height_scale = std::sqrt(square / heights_.size());
    if (!(height_scale > 0))
      throw std::invalid_argument("contact solver: a flat surface is in full contact at any load");
    compliance = transform.tabulate([E_star](const Wavevector &q) {
      return std::complex<double>(q.kx == 0 && q.ky == 0 ? 0. : 2 / (E_star * q.norm()));
    });
  }

  void HalfSpaceContact::displacement(const GridField &pressure, GridField &u) const
  {
    transform.apply(compliance, pressure, u);
  }

  // Polonsky and Keer (1999), with g the gap centred on the contact set:
  //   t = g + delta (G/G_old) t on the contact set (conjugate direction),
  //   r = u(t) centred, tau = (g.t)/(r.t), p -= tau t, p = max(p, 0),
  //   points with p = 0 and g < 0 (overlap) get p = -tau g and reset the
  //   conjugacy (delta = 0), and p is scaled to mean p_bar.
  // The residual is checked before each step, on the gap of the current p.
  ContactSolution HalfSpaceContact::solve(const double mean_pressure, const ContactSolverControl &control,
                                          const GridField &initial_pressure) const
  {
    if (!(mean_pressure > 0))
      throw std::invalid_argument("contact solver: the mean pressure must be positive");
    const std::size_t n = heights_.size();

    GridField pressure;
    if (initial_pressure.empty())
      {
        pressure = full_contact_pressure(transform, heights_, E_star);
        for (double &p : pressure)
          p += mean_pressure;
      }
    else if (initial_pressure.size() == n)
      pressure = initial_pressure;
    else
      throw std::invalid_argument("contact solver: the initial pressure does not match the grid");
    make_admissible(pressure, mean_pressure);

    GridField gap(n), direction(n, 0.), response(n);
    double    delta = 0, G_old = 1, residual = 0;
    for (unsigned int iteration = 0; iteration <= control.max_iterations; ++iteration)
      {
        displacement(pressure, gap);
        for (std::size_t i = 0; i < n; ++i)
          gap[i] -= heights_[i];
        centre_on_contact(pressure, gap);

        double G = 0, violation = 0;
        for (std::size_t i = 0; i < n; ++i)
          if (pressure[i] > 0)
            G += gap[i] * gap[i];
          else if (gap[i] < 0)
            violation += gap[i] * gap[i];
        residual = std::sqrt((G + violation) / n) / height_scale;
        if (residual <= control.tolerance)
          {
            const double contact =
                std::count_if(pressure.begin(), pressure.end(), [](double p) { return p > 0; });
            return {std::move(pressure), std::move(gap), contact / n, iteration, residual};
          }

        for (std::size_t i = 0; i < n; ++i)
          direction[i] = pressure[i] > 0 ? gap[i] + delta * G / G_old * direction[i] : 0;
        G_old = G;

        displacement(direction, response);
        centre_on_contact(pressure, response);
        double gap_direction = 0, response_direction = 0;
        for (std::size_t i = 0; i < n; ++i)
          if (pressure[i] > 0)
            {
              gap_direction += gap[i] * direction[i];
              response_direction += response[i] * direction[i];
            }
        if (!(response_direction > 0))
          throw std::runtime_error("contact solver: breakdown at iteration " + std::to_string(iteration) +
                                   " (no descent direction on the contact set)");
        const double tau = gap_direction / response_direction;

        for (std::size_t i = 0; i < n; ++i)
          if (pressure[i] > 0)
            pressure[i] = std::max(pressure[i] - tau * direction[i], 0.);
        delta = 1;
        for (std::size_t i = 0; i < n; ++i)
          if (pressure[i] == 0 && gap[i] < 0)
            {
              pressure[i] = -tau * gap[i];
              delta       = 0;
            }
        make_admissible(pressure, mean_pressure);
      }
    char message[160];
    std::snprintf(message, sizeof message,
                  "contact solver: no convergence in %u iterations (residual %.3g > tolerance %.3g)",
                  control.max_iterations, residual, control.tolerance);
    throw std::runtime_error(message);
  }

  std::vector<LoadStep> load_sweep(const HalfSpaceContact &contact, const std::vector<double> &mean_pressures,
                                   const ContactSolverControl &control)
  {
    std::vector<std::size_t> order(mean_pressures.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return mean_pressures[a] > mean_pressures[b]; });

    std::vector<LoadStep> steps(mean_pressures.size());
    GridField             pressure;
    double                previous_load = 0;
    for (const std::size_t k : order)
      {
        const double p_bar = mean_pressures[k];
        for (double &p : pressure)
          p += p_bar - previous_load;
        ContactSolution solution = contact.solve(p_bar, control, pressure);
        steps[k]      = {p_bar, 1 - solution.contact_fraction, solution.iterations, solution.residual};
        pressure      = std::move(solution.pressure);
        previous_load = p_bar;
      }
    return steps;
  }
  double edge_from_gap(const std::vector<double> &gaps)
  {
    const int n = gaps.size();
    if (n < 4)
      throw std::invalid_argument("edge_from_gap: needs the gaps of at least 4 points beside the edge");
    Eigen::MatrixXd design(n - 1, 3);
    Eigen::VectorXd root_gap(n - 1);
    for (int k = 2; k <= n; ++k)
      {
        design.row(k - 2) << 1, k, k * k;
        root_gap(k - 2) = std::cbrt(gaps[k - 1] * gaps[k - 1]);
      }
    const Eigen::Vector3d c = design.colPivHouseholderQr().solve(root_gap);
    // The root of c0 + c1 k + c2 k^2 nearest the data, by Newton from the linear part's root.
    double k = -c(0) / c(1);
    for (int iteration = 0; iteration < 50; ++iteration)
      k -= (c(0) + c(1) * k + c(2) * k * k) / (c(1) + 2 * c(2) * k);
    return k;
  }
} // namespace penny
