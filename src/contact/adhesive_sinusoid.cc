#include "contact/adhesive_sinusoid.h"

#include "contact/contact_geometry.h"
#include "contact/contact_path.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace penny::adhesive_sinusoid
{
  namespace
  {
    // The amplitude for which p* = pi E* h0/lambda = 1.
    const double h0 = 1 / M_PI;
  } // namespace

  Model::Model(const Discretisation &discretisation)
      : discretisation(checked(discretisation,
                               discretisation.alpha > 0 && discretisation.process_zone > 0 &&
                                   discretisation.n_points >= 16,
                               "adhesive sinusoid: needs alpha > 0, l_pz > 0 and at least 16 points")),
        surface({discretisation.n_points, 1, 1., 1. / discretisation.n_points},
                [n = discretisation.n_points](unsigned int i, unsigned int) {
                  return 2 * h0 * std::pow(std::sin(M_PI * i / n), 2);
                },
                {discretisation.alpha * discretisation.alpha / 2,
                 discretisation.alpha * std::sqrt(M_PI * discretisation.process_zone / 2)})
  {
  }

  // The strip is centred on the crest x = lambda/2 (i = n/2); its edges are
  // where the gap reaches rho.
  CurvePoint Model::state(const ContactSolution &solution) const
  {
    const double half_width =
        level_radius(surface.grid(), solution.gap, surface.adhesion().range, discretisation.n_points / 2, 0);
    return {half_width, solution.mean_pressure, solution.mean_gap / h0, solution.iterations};
  }

  std::vector<CurvePoint> Model::loads_at_half_widths(const std::vector<double>  &contact_ratios,
                                                      const ContactSolverControl &control) const
  {
    // Start from the adhesionless strip of the first half-width (Westergaard's load).
    ContactSolution current =
        surface.adhesionless().solve(std::pow(std::sin(M_PI * contact_ratios.front()), 2), control);
    current = surface.adhesive().solve_at_mean_gap(current.mean_gap, control, current.gap);
    CurvePoint              point      = state(current);
    CurvePoint              before     = point; // the state of the target before `point`'s
    unsigned int            iterations = current.iterations + std::lround(current.coarse_iterations);
    std::vector<CurvePoint> points;
    for (const double target : contact_ratios)
      {
        const auto at = [&](const double mean_gap) {
          current = surface.adhesive().solve_at_mean_gap(mean_gap * h0, control, current.gap);
          iterations += current.iterations + std::lround(current.coarse_iterations);
          return state(current);
        };
        // a/lambda falls as the mean gap rises. Bracket the target from the
        // last state by steps 1.5 times the secant's through the last two
        // states (the next targets' states lie on a smooth curve: one step
        // mostly), or of 10 % while they share one a/lambda, never more than
        // 20 % of the mean gap.
        const CurvePoint last = point;
        CurvePoint low = point, high = point; // a(low) >= target >= a(high), low.mean_gap <= high.mean_gap
        while (low.contact_ratio < target || high.contact_ratio > target)
          {
            const bool   down   = point.contact_ratio < target;
            const double secant = point.contact_ratio != before.contact_ratio
                                      ? (target - point.contact_ratio) * (point.mean_gap - before.mean_gap) /
                                            (point.contact_ratio - before.contact_ratio)
                                      : 0;
            const double step =
                secant != 0 && (secant < 0) == down ? 1.5 * std::abs(secant) : 0.1 * point.mean_gap;
            before = point;
            point  = at(point.mean_gap + (down ? -1 : 1) * std::min(step, 0.2 * point.mean_gap));
            if (point.contact_ratio >= target &&
                (low.contact_ratio < target || point.mean_gap > low.mean_gap))
              low = point;
            if (point.contact_ratio <= target &&
                (high.contact_ratio > target || point.mean_gap < high.mean_gap))
              high = point;
          }
        before = last;
        // f = a/lambda - target, f(low) > 0 > f(high); the end kept twice running has its f halved.
        double f_low = low.contact_ratio - target, f_high = high.contact_ratio - target;
        int    kept = 0; // +1: low kept last time, -1: high
        point       = std::abs(f_low) < std::abs(f_high) ? low : high;
        for (unsigned int k = 0; std::abs(point.contact_ratio - target) > 1e-9; ++k)
          {
            if (k == 100)
              throw std::runtime_error("adhesive sinusoid: no mean gap found for a/lambda = " +
                                       std::to_string(target));
            // The strip's edge can jump by a fraction of a grid spacing at one
            // mean gap (a grid point near the edge snaps; seen at alpha = 0.5 on
            // 131072 points: 2e-6 lambda). Once the bracket has shrunk to
            // rounding, the load at the target is interpolated across the jump.
            if (high.mean_gap - low.mean_gap <= 1e-13 * high.mean_gap)
              {
                const double w = (low.contact_ratio - target) / (low.contact_ratio - high.contact_ratio);
                point          = {target, low.load_ratio + w * (high.load_ratio - low.load_ratio),
                                  low.mean_gap + w * (high.mean_gap - low.mean_gap), 0};
                break;
              }
            point          = at((low.mean_gap * f_high - high.mean_gap * f_low) / (f_high - f_low));
            const double f = point.contact_ratio - target;
            if (f > 0)
              {
                low   = point;
                f_low = f;
                if (kept == -1)
                  f_high /= 2;
                kept = -1;
              }
            else
              {
                high   = point;
                f_high = f;
                if (kept == 1)
                  f_low /= 2;
                kept = 1;
              }
          }
        point.iterations = iterations;
        points.push_back(point);
        iterations = 0;
      }
    return points;
  }

  CurvePoint Model::jump_into_contact(const ContactSolverControl    &control,
                                      const std::vector<CurvePoint> &curve) const
  {
    // From the strip of a/lambda = 0.3 (before the jump at every alpha up to
    // 0.56), taken from the curve where it has that half-width; from a cold
    // start at its mean gap, the mean gap falls by 10 % a step.
    const double     start_ratio = 0.3;
    const auto       on_curve    = std::find_if(curve.begin(), curve.end(), [&](const CurvePoint &point) {
      return std::abs(point.contact_ratio - start_ratio) <= 1e-8;
    });
    const CurvePoint from =
        on_curve != curve.end() ? *on_curve : loads_at_half_widths({start_ratio}, control).back();
    const ContactSolution start = surface.adhesive().solve_at_mean_gap(from.mean_gap * h0, control);
    CurvePoint            jump  = state(load_extremum(surface.adhesive(), control, start, 0.9, true));
    jump.iterations             = 0;
    return jump;
  }
} // namespace penny::adhesive_sinusoid
