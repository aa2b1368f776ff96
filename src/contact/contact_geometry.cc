#include "contact/contact_geometry.h"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace penny
{
  // Flood fill with an explicit stack, x the slow index, both directions periodic.
  ContactTopology contact_topology(const PeriodicGrid &grid, const GridField &gap)
  {
    const std::size_t n = grid.n_points();
    if (gap.size() != n)
      throw std::invalid_argument("contact_topology: the gap must hold the whole grid (a flood fill: not "
                                  "on a grid split over ranks)");
    std::vector<unsigned char> seen(n, 0);
    std::vector<std::size_t>   stack;
    ContactTopology            topology{0, 0};
    for (std::size_t seed = 0; seed < n; ++seed)
      {
        if (seen[seed])
          continue;
        const bool open = gap[seed] > 0;
        ++(open ? topology.gaps : topology.contacts);
        seen[seed] = 1;
        stack.push_back(seed);
        while (!stack.empty())
          {
            const std::size_t  k = stack.back();
            const unsigned int i = k / grid.ny, j = k % grid.ny;
            stack.pop_back();
            const std::size_t neighbours[4] = {
                ((i + 1) % grid.nx) * grid.ny + j, ((i + grid.nx - 1) % grid.nx) * grid.ny + j,
                i * grid.ny + (j + 1) % grid.ny, i * grid.ny + (j + grid.ny - 1) % grid.ny};
            for (const std::size_t m : neighbours)
              if (!seen[m] && (gap[m] > 0) == open)
                {
                  seen[m] = 1;
                  stack.push_back(m);
                }
          }
      }
    return topology;
  }

  double level_radius(const PeriodicGrid &grid, const GridField &f, const double level, const unsigned int i,
                      const unsigned int j, const unsigned int rays)
  {
    if (f.size() != grid.n_points())
      throw std::invalid_argument("level_radius: the field must hold the whole grid (not a grid split "
                                  "over ranks)");
    const double dx = grid.lx / grid.nx, dy = grid.ly / grid.ny;
    // f at (x, y) in grid units from (i, j), bilinear and periodic.
    const auto value = [&](const double x, const double y) {
      const double fx = std::floor(x), fy = std::floor(y), tx = x - fx, ty = y - fy;
      const auto   at = [&](const long a, const long b) {
        const long nx = grid.nx, ny = grid.ny;
        return f[((i + a) % nx + nx) % nx * ny + ((j + b) % ny + ny) % ny];
      };
      const long a = fx, b = fy;
      return (1 - tx) * ((1 - ty) * at(a, b) + ty * at(a, b + 1)) +
             tx * ((1 - ty) * at(a + 1, b) + ty * at(a + 1, b + 1));
    };
    const bool         line   = grid.ny == 1;
    const double       centre = f[std::size_t(i) * grid.ny + j] - level;
    const double       reach  = (line ? grid.lx : std::min(grid.lx, grid.ly)) / 2;
    const double       step   = std::min(line ? dx : std::min(dx, dy), reach) / 2;
    const unsigned int n_rays = line ? 2 : rays;
    double             square = 0;
    for (unsigned int k = 0; k < n_rays; ++k)
      {
        const double angle = line ? M_PI * k : 2 * M_PI * (k + 0.5) / n_rays, cx = std::cos(angle),
                     cy  = line ? 0 : std::sin(angle);
        const auto at    = [&](const double r) { return value(r * cx / dx, line ? 0 : r * cy / dy) - level; };
        double     inner = 0, outer = step;
        while (at(outer) * centre > 0)
          {
            inner = outer;
            outer += step;
            if (outer > reach)
              throw std::runtime_error(
                  "level_radius: a ray leaves the half period without crossing the level");
          }
        for (int b = 0; b < 60; ++b)
          {
            const double middle                       = (inner + outer) / 2;
            (at(middle) * centre > 0 ? inner : outer) = middle;
          }
        square += std::pow((inner + outer) / 2, 2);
      }
    return std::sqrt(square / n_rays);
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
