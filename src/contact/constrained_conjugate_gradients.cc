#include "contact/half_space_contact.h"
#include "contact/half_space_contact_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace penny
{
  using internal::formatted;
  using internal::mean;
  using internal::on_any_rank;

  namespace
  {
    // A field kept to single precision: the gradient (computed in double
    // precision, as a difference of large tractions, and then rounded: the
    // rounding is relative to the gradient itself), and the step and the
    // search direction made from the single-precision preconditioner's output.
    using SingleField = std::vector<float>;

    // The first minimum of the energy along g + alpha d (alpha > 0) before
    // clipping at the wall: the elastic part is alpha r.d + alpha^2 d.Kd/2, the
    // interaction continues beyond the wall with the slope it has there, so
    //   E'(alpha) = r.d + alpha d.Kd + sum_i [phi'(max(g_i + alpha d_i, 0)) - phi'(g_i)] d_i
    // is continuous (dropping the attraction at the wall instead puts a
    // spurious minimum where a point with a tiny gap reaches it). Without
    // adhesion alpha = -r.d/d.Kd; with it the minimum is bracketed by doubling
    // and found by safeguarded Newton. No bracket within 2^60 times the
    // elastic step: nothing holds the surfaces together along d. On a split
    // grid the sum over points is one over ranks: the rank of the first row
    // adds the elastic part.
    double step_length(const FourierTransform &transform, const Adhesion &adhesion, const double slope_along,
                       const double curvature, const GridField &gap, const SingleField &direction,
                       const GridField &slope)
    {
      if (!adhesion.active())
        {
          if (!(curvature > 0))
            throw std::runtime_error(
                "contact solver: breakdown (no elastic stiffness along the search direction)");
          return -slope_along / curvature;
        }
      const double reach      = adhesion.reach();
      const auto   derivative = [&](const double alpha, double &second) {
        const bool elastic = transform.holds_first_row();
        double     first   = elastic ? slope_along + alpha * curvature : 0;
        second             = elastic ? curvature : 0;
        for (std::size_t i = 0; i < gap.size(); ++i)
          if (direction[i] != 0)
            {
              const double g = gap[i] + alpha * direction[i];
              if (gap[i] >= reach && g >= reach)
                continue;
              const double s = adhesion.slope(std::max(g, 0.));
              first += (s - slope[i]) * direction[i];
              if (g > 0)
                second -= s / adhesion.range * direction[i] * direction[i];
            }
        const auto sums = transform.sums(first, second);
        second          = sums[1];
        return sums[0];
      };
      double alpha = curvature > 0 ? -slope_along / curvature : adhesion.range, low = 0,
             high = std::numeric_limits<double>::infinity();
      for (unsigned int k = 0; k < 200; ++k)
        {
          double       second;
          const double first = derivative(alpha, second);
          if (std::abs(first) <= 1e-12 * std::abs(slope_along))
            return alpha;
          (first < 0 ? low : high) = alpha;
          if (std::isinf(high))
            {
              if (alpha > std::ldexp(curvature > 0 ? -slope_along / curvature : adhesion.range, 60))
                throw std::runtime_error(
                    "contact solver: the surfaces separate (no equilibrium in contact at this "
                    "mean pressure: beyond the pull-off load)");
              alpha = second > 0 && alpha - first / second > alpha ? alpha - first / second : 2 * alpha;
              continue;
            }
          const double newton = second > 0 ? alpha - first / second : low;
          alpha               = newton > low && newton < high ? newton : (low + high) / 2;
          if (high - low <= 1e-14 * high)
            return alpha;
        }
      return alpha;
    }

  } // namespace

  void HalfSpaceContact::check_start(const GridField &gap) const
  {
    if (on_any_rank(transform_, gap.size() != heights_.size()))
      throw std::invalid_argument("contact solver: the initial gap does not match the grid");
    if (on_any_rank(transform_, !std::all_of(gap.begin(), gap.end(),
                                             [](double g) { return g >= 0 && std::isfinite(g); })))
      throw std::invalid_argument("contact solver: the initial gap must be finite and >= 0");
  }

  // Bound-constrained conjugate gradients in the gap (Polonsky and Keer's
  // iteration turned round, with Vollebregt's continuation across changes of
  // the free set and a Fourier preconditioner; doc/contact-notes.md):
  //
  //   r = p_el + phi'(g) + mu                      the gradient (mu = p_bar)
  //   F = {g > 0} or {g = 0, r < 0}                the points free to move
  //   z = P_F C P_F r                              C = 2/(E* |q|): the displacement r would cause
  //   d = -z + beta d,  beta = max(0, z.(r - r_old)/(z_old.r_old))
  //   g = max(g + alpha d, 0),                     alpha the first minimum of Pi along d
  //
  // Preconditioned by the compliance, the stiffness on the free set has a
  // condition number that grows only like the square of the logarithm of the
  // points per gap, so the iterations hardly grow with the grid. At a
  // prescribed mean gap, mu is the unknown p_bar, corrected each step so that
  // z (and d) keep the mean of g.
  ContactSolution HalfSpaceContact::minimise(const Control control, const double value,
                                             const ContactSolverControl &solver, GridField gap) const
  {
    const std::size_t n = heights_.size(), n_points = transform_.grid().n_points();
    check_start(gap);

    // From here on in the units L and T; `target` is the mean pressure or gap.
    const bool      fixed_load = control == Control::mean_pressure;
    const double    target     = value / (fixed_load ? traction_unit : length_unit);
    const Adhesion &adhesion   = scaled_adhesion;
    const bool      adhesive   = adhesion.active();
    for (double &g : gap)
      g /= length_unit;
    double *const work = transform_.work_array(); // the gap and K g, when K g is recomputed
    // The change of the gap and K of it; P_F r and C P_F r; the direction d.
    float *const preconditioned = single.work_array();
    const auto   each_point     = [&](auto &&f) { transform_.for_each_point(f); };

    GridField   elastic_traction(n); // p_fc + K g
    SingleField gradient(n), previous_gradient(n, 0.f), step(n), direction(n, 0.f);
    GridField   slope(adhesive ? n : 0); // phi'(g)
    const auto  attraction = [&](const std::size_t i) { return adhesive ? slope[i] : 0; };
    GridField   mean_response; // P_F C P_F 1, at a prescribed mean gap
    // Each point held at the wall (g = 0, r >= 0), open (g > 0), or leaving
    // the wall (g = 0, r < 0); the free set F is the open and leaving points.
    // An enum, not a char: a store through a char may alias anything, and
    // the compiler would reload every array's address after each one.
    enum class Point : unsigned char
    {
      held,
      open,
      leaving
    };
    const std::unique_ptr<Point[]> point(new Point[n]()); // all held
    const auto                     free = [&](const std::size_t i) { return point[i] != Point::held; };
    double                         mu   = target;

    // At a prescribed mean gap: shift step by a multiple of P_F C P_F 1 so
    // that it keeps the mean of g, and mu and the gradient with it. P_F C P_F 1
    // is convolved again only when the free set has changed (near the
    // solution it rarely does: one convolution of four in an iteration saved).
    double     response_sum  = 0;
    const auto keep_mean_gap = [&](const bool free_set_changed, const double step_sum) {
      if (free_set_changed)
        {
          each_point([&](const std::size_t i, const std::size_t w) { preconditioned[w] = free(i); });
          single.convolve_work_array(compliance);
          mean_response.resize(n);
          response_sum = 0;
          each_point([&](const std::size_t i, const std::size_t w) {
            mean_response[i] = free(i) ? preconditioned[w] : 0;
            response_sum += mean_response[i];
          });
        }
      const auto   sums  = transform_.sums(step_sum, response_sum);
      const double shift = -sums[0] / sums[1];
      for (std::size_t i = 0; i < n; ++i)
        {
          step[i] += shift * mean_response[i];
          gradient[i] += shift;
        }
      mu += shift;
    };

    // At a prescribed mean gap: the direction's mean removed along P_F C P_F 1.
    const auto keep_mean_of_direction = [&]() {
      double direction_sum = 0;
      for (std::size_t i = 0; i < n; ++i)
        direction_sum += direction[i];
      const auto sums = transform_.sums(direction_sum, response_sum);
      for (std::size_t i = 0; i < n; ++i)
        direction[i] -= sums[0] / sums[1] * mean_response[i];
    };

    // The direction d = P_F (-step + beta d), copied to the single-precision array, and
    // r.d over the grid (at a prescribed mean pressure in one pass).
    const auto new_direction = [&](const double beta) {
      double slope_along = 0;
      if (fixed_load)
        each_point([&](const std::size_t i, const std::size_t w) {
          direction[i] = free(i) ? -step[i] + beta * direction[i] : 0;
          slope_along += gradient[i] * direction[i];
          preconditioned[w] = direction[i];
        });
      else
        {
          for (std::size_t i = 0; i < n; ++i)
            direction[i] = free(i) ? -step[i] + beta * direction[i] : 0;
          keep_mean_of_direction();
          each_point([&](const std::size_t i, const std::size_t w) {
            slope_along += gradient[i] * direction[i];
            preconditioned[w] = direction[i];
          });
        }
      return transform_.sum(slope_along);
    };

    double       residual = 0, previous_product = 0;
    unsigned int iteration = 0;
    // The elastic traction p_fc + K g is updated by K of the gap's change,
    // transformed in single precision (its rounding relative to the change,
    // not to K g), and recomputed from the gap in double precision at the
    // start, after a rescaling of the gaps and before a residual below the
    // tolerance is believed: the solution's residual is that of K g in double
    // precision.
    bool recomputed = true;
    each_point([&](const std::size_t i, const std::size_t w) { work[w] = gap[i]; });
    for (;;)
      {
        // The gradient r = p_fc + K g + mu + phi'(g), the free set, and P_F r
        // in the single-precision array.
        if (recomputed)
          transform_.convolve_work_array(stiffness);
        else
          single.convolve_work_array(single_stiffness);
        if (adhesive)
          for (std::size_t i = 0; i < n; ++i)
            slope[i] = gap[i] < adhesion.reach() ? adhesion.slope(gap[i]) : 0;
        if (iteration == 0 && !fixed_load)
          {
            // mu starts as the traction that balances the gap points on average
            // (K g in the work array: the first iteration recomputes it).
            double sum = 0, count = 0;
            each_point([&](const std::size_t i, const std::size_t w) {
              if (gap[i] > 0)
                {
                  sum += full_contact[i] + work[w] + attraction(i);
                  ++count;
                }
            });
            const auto sums = transform_.sums(sum, count);
            mu              = -sums[0] / sums[1];
          }
        bool free_set_changed = mean_response.empty();
        each_point([&](const std::size_t i, const std::size_t w) {
          elastic_traction[i] =
              recomputed ? full_contact[i] + work[w] : elastic_traction[i] + preconditioned[w];
          gradient[i]    = elastic_traction[i] + mu + attraction(i);
          const bool was = free(i);
          point[i]       = gap[i] > 0 ? Point::open : gradient[i] < 0 ? Point::leaving : Point::held;
          free_set_changed |= was != free(i);
          preconditioned[w] = free(i) ? gradient[i] : 0;
        });
        single.convolve_work_array(compliance);
        if (!fixed_load)
          {
            double step_sum = 0;
            each_point([&](const std::size_t i, const std::size_t w) {
              step[i] = free(i) ? preconditioned[w] : 0;
              step_sum += step[i];
            });
            keep_mean_gap(on_any_rank(transform_, free_set_changed), step_sum);
          }

        // In one pass: the step P_F C P_F r (read from the single-precision array at a
        // prescribed mean pressure); the residual; a point at the wall that
        // pulls away (r < 0) but that the preconditioned step would push into
        // it moves by the local compliance instead, -c r (c the diagonal of
        // C), so the step stays a descent direction and the point opens; and
        // the products of Polak-Ribiere.
        double square = 0, product = 0, previous_overlap = 0;
        each_point([&](const std::size_t i, const std::size_t w) {
          double s = fixed_load ? (free(i) ? preconditioned[w] : 0) : step[i];
          square += s * s;
          if (point[i] == Point::leaving && s >= 0)
            s = point_compliance * gradient[i];
          step[i] = s;
          product += gradient[i] * s;
          previous_overlap += previous_gradient[i] * s;
        });
        const auto sums = transform_.sums(square, product, previous_overlap);
        residual        = std::sqrt(sums[0] / n_points);
        if (residual <= solver.tolerance)
          {
            if (recomputed)
              break;
            // Once more at the same gap, from K g in double precision.
            recomputed = true;
            each_point([&](const std::size_t i, const std::size_t w) { work[w] = gap[i]; });
            continue;
          }
        if (iteration == solver.max_iterations)
          throw ContactSolverFailure(
              formatted("contact solver: no convergence in %.0f iterations (residual %.3g > tolerance %.3g)",
                        solver.max_iterations, residual, solver.tolerance));

        // Polak-Ribiere, never negative; a restart where that is no descent.
        const double beta = previous_product > 0 ? std::max(0., (sums[1] - sums[2]) / previous_product) : 0;
        double       slope_along = new_direction(beta);
        if (!(slope_along < 0))
          slope_along = new_direction(0);

        const double curvature = n_points * single.quadratic_form_of_work_array(single_stiffness);
        const double alpha = step_length(transform_, adhesion, slope_along, curvature, gap, direction, slope);

        // The step, clipped at the wall (a clipped point forgets its
        // direction), and the gap's change in the single-precision array.
        bool   clipped      = false;
        double smallest_gap = std::numeric_limits<double>::infinity();
        each_point([&](const std::size_t i, const std::size_t w) {
          const double g = gap[i] + alpha * direction[i];
          if (g <= 0)
            {
              preconditioned[w] = -gap[i];
              gap[i]            = 0;
              direction[i]      = 0;
              clipped           = true;
            }
          else
            {
              preconditioned[w] = g - gap[i];
              gap[i]            = g;
            }
          smallest_gap = std::min(smallest_gap, gap[i]);
        });
        recomputed = !fixed_load && on_any_rank(transform_, clipped);
        if (recomputed)
          {
            const double scale = target / mean(transform_, gap);
            each_point([&](const std::size_t i, const std::size_t w) { work[w] = gap[i] *= scale; });
          }
        if (fixed_load && !(target > 0) && transform_.minimum(smallest_gap) >= adhesion.reach())
          throw std::runtime_error(
              formatted("contact solver: the surfaces separate at p_bar = %g Pa (no equilibrium "
                        "in contact: beyond the pull-off load)",
                        value));
        std::swap(gradient, previous_gradient);
        previous_product = sums[1];
        ++iteration;
      }

    // Back to Pa and m.
    ContactSolution solution;
    solution.coarse_iterations = 0;
    solution.mean_pressure     = mu * traction_unit;
    solution.mean_gap          = mean(transform_, gap) * length_unit;
    solution.iterations        = iteration;
    solution.residual          = residual;
    solution.pressure.resize(n);
    double elastic = 0, interaction = 0, contact = 0;
    for (std::size_t i = 0; i < n; ++i)
      {
        solution.pressure[i] =
            traction_unit *
            ((gap[i] > 0 ? 0 : std::max(elastic_traction[i] + mu + attraction(i), 0.)) - attraction(i));
        elastic += (gap[i] + heights_[i] / length_unit) * elastic_traction[i];
        if (adhesive)
          interaction += adhesion.energy(gap[i]);
        contact += gap[i] == 0;
      }
    const auto sums           = transform_.sums(elastic, interaction, contact);
    solution.energy           = (sums[0] / 2 + sums[1]) / n_points * traction_unit * length_unit;
    solution.contact_fraction = sums[2] / n_points;
    solution.gap              = std::move(gap);
    for (double &g : solution.gap)
      g *= length_unit;
    return solution;
  }
} // namespace penny
