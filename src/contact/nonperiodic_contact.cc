#include "contact/nonperiodic_contact.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace penny
{
  namespace
  {
    // A double antiderivative of 1/sqrt(x^2 + y^2): x ln(y + r) + y ln(x + r),
    // with y + r = x^2/(r - y) for y < 0 (no cancellation), and 0 ln 0 = 0.
    double love_corner(const double x, const double y)
    {
      const double r    = std::hypot(x, y);
      const auto   term = [r](const double a, const double b) {
        if (a == 0)
          return 0.;
        const double b_plus_r = b >= 0 ? b + r : a * a / (r - b);
        return a * std::log(b_plus_r);
      };
      return term(x, y) + term(y, x);
    }

    PeriodicGrid doubled(const PeriodicGrid &patch)
    {
      return {2 * patch.nx, 2 * patch.ny, 2 * patch.lx, 2 * patch.ly};
    }
  } // namespace

  double NonperiodicContact::rectangle_influence(const double x, const double y, const double dx,
                                                 const double dy, const double E_star)
  {
    const double a = dx / 2, b = dy / 2;
    return (love_corner(x + a, y + b) - love_corner(x + a, y - b) - love_corner(x - a, y + b) +
            love_corner(x - a, y - b)) /
           (M_PI * E_star);
  }

  NonperiodicContact::NonperiodicContact(const PeriodicGrid &patch, GridField heights, const double E_star)
      : patch(patch), heights(std::move(heights)), E_star(E_star), padded(doubled(patch))
  {
    // The influence of a pixel at every offset (wrapped: index i >= nx stands
    // for the offset i - 2 nx), transformed once; its convolution theorem on
    // the doubled grid is c^ = (number of points) K^ p^.
    const unsigned int nx = 2 * patch.nx, ny = 2 * patch.ny;
    const double       dx = patch.lx / patch.nx, dy = patch.ly / patch.ny;
    GridField          kernel(std::size_t(nx) * ny);
    for (unsigned int i = 0; i < nx; ++i)
      for (unsigned int j = 0; j < ny; ++j)
        {
          const double x                  = (i < patch.nx ? double(i) : double(i) - nx) * dx,
                       y                  = (j < patch.ny ? double(j) : double(j) - ny) * dy;
          kernel[std::size_t(i) * ny + j] = rectangle_influence(x, y, dx, dy, E_star);
        }
    influence = padded.forward(kernel);
    for (auto &coefficient : influence)
      coefficient *= double(nx) * ny;
  }

  GridField NonperiodicContact::displacement(const GridField &pressure) const
  {
    const unsigned int ny = 2 * patch.ny;
    GridField          field(padded.grid().n_points(), 0.);
    for (unsigned int i = 0; i < patch.nx; ++i)
      std::copy_n(&pressure[std::size_t(i) * patch.ny], patch.ny, &field[std::size_t(i) * ny]);
    padded.apply(influence, field, field);
    GridField u(patch.n_points());
    for (unsigned int i = 0; i < patch.nx; ++i)
      std::copy_n(&field[std::size_t(i) * ny], patch.ny, &u[std::size_t(i) * patch.ny]);
    return u;
  }

  NonperiodicSolution NonperiodicContact::solve(const double                mean_pressure,
                                                const ContactSolverControl &control) const
  {
    const std::size_t n    = patch.n_points();
    double            mean = 0, rms = 0;
    for (const double h : heights)
      mean += h / n;
    for (const double h : heights)
      rms += (h - mean) * (h - mean) / n;
    const double length = std::sqrt(rms) > 0 ? std::sqrt(rms) : 1.;

    // Polonsky and Keer: conjugate gradients on the pressures of the contact
    // set, the separation's mean over it the approach, points that overlap
    // brought into contact, and the total load restored after each step.
    GridField    p(n, mean_pressure), direction(n, 0.), separation(n);
    double       previous_norm = 1, approach = 0, residual = 0;
    bool         conjugate = false;
    unsigned int iteration = 0;
    for (; iteration < control.max_iterations; ++iteration)
      {
        const GridField u   = displacement(p);
        double          sum = 0, count = 0;
        for (std::size_t k = 0; k < n; ++k)
          {
            separation[k] = u[k] - heights[k];
            if (p[k] > 0)
              sum += separation[k], ++count;
          }
        approach    = sum / count;
        double norm = 0, overlap = 0;
        for (std::size_t k = 0; k < n; ++k)
          {
            separation[k] -= approach;
            if (p[k] > 0)
              norm += separation[k] * separation[k];
            else if (separation[k] < 0)
              overlap += separation[k] * separation[k];
          }
        residual = std::sqrt((norm + overlap) / n) / length;
        if (residual < control.tolerance)
          break;

        const double beta = conjugate ? norm / previous_norm : 0;
        for (std::size_t k = 0; k < n; ++k)
          direction[k] = p[k] > 0 ? separation[k] + beta * direction[k] : 0;
        previous_norm = norm;

        // The step along the direction that minimises the complementary energy on the contact set.
        GridField response      = displacement(direction);
        double    mean_response = 0;
        for (std::size_t k = 0; k < n; ++k)
          if (p[k] > 0)
            mean_response += response[k] / count;
        double along = 0, curvature = 0;
        for (std::size_t k = 0; k < n; ++k)
          if (p[k] > 0)
            {
              along += separation[k] * direction[k];
              curvature += (response[k] - mean_response) * direction[k];
            }
        const double step = curvature > 0 ? along / curvature : 0;

        conjugate    = true;
        double total = 0;
        for (std::size_t k = 0; k < n; ++k)
          {
            if (p[k] > 0)
              p[k] = std::max(0., p[k] - step * direction[k]);
            else if (separation[k] < 0)
              {
                p[k]      = -step * separation[k];
                conjugate = false; // the contact set grew: restart the directions
              }
            total += p[k];
          }
        if (!(total > 0))
          throw ContactSolverFailure("the non-periodic contact lost every contact point");
        for (double &value : p)
          value *= mean_pressure * n / total;
      }
    if (iteration == control.max_iterations)
      {
        std::ostringstream message;
        message << "the non-periodic contact solver reached " << control.max_iterations
                << " iterations at the residual " << residual << " (tolerance " << control.tolerance << ")";
        throw ContactSolverFailure(message.str());
      }
    // The gap as the solution states it: zero on the contact points, and no
    // overlap (within the tolerance) elsewhere.
    for (std::size_t k = 0; k < n; ++k)
      separation[k] = p[k] > 0 ? 0 : std::max(0., separation[k]);
    const auto contacts = std::count_if(p.begin(), p.end(), [](const double value) { return value > 0; });
    return {p, separation, approach, double(contacts) / n, iteration, residual};
  }
} // namespace penny
