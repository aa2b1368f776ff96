// The adhesive boundary-element solver against problems with exact answers,
// at full size (the unit tests run the same models small): Johnson's
// sinusoid, the JKR sphere and the bi-sinusoid near full contact. Each
// adhesive number is computed on a table of cohesive-zone lengths l_pz and
// grid spacings and extrapolated to the JKR limit by Richardson (both
// parameters), with the error estimate of contact/extrapolation.h.
//
// Usage: verify_contact sinusoid|sphere|bisinusoid [quick]
// ("quick": the two coarsest levels fewer, for a look in minutes).
#include "closed_forms/periodic_array.h"
#include "contact/adhesive_bisinusoid.h"
#include "contact/adhesive_sinusoid.h"
#include "contact/adhesive_sphere.h"
#include "contact/extrapolation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

using namespace penny;

namespace
{
  double seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  void print_load_average()
  {
    std::ifstream file("/proc/loadavg");
    std::string   one, five, fifteen;
    file >> one >> five >> fifteen;
    std::printf("# load average %s %s %s\n", one.c_str(), five.c_str(), fifteen.c_str());
  }

  std::string order_text(const std::vector<double> &values, const double ratio)
  {
    if (values.size() < 3)
      return "-";
    const std::size_t k = values.size();
    char              text[32];
    std::snprintf(text, sizeof text, "%.2f",
                  observed_order(values[k - 3], values[k - 2], values[k - 1], ratio));
    return text;
  }

  // Johnson's sinusoid: p_bar/p* at a/lambda = 0.1 ... 0.3 and the jump into
  // contact for alpha = 0.05, 0.2, 0.5; l_pz/lambda halving from 1e-3, the
  // grid 16 and 32 points per cohesive zone (n a power of two).
  void sinusoid(const bool quick)
  {
    const std::vector<double> alphas = {0.05, 0.2, 0.5}, ratios = {0.1, 0.15, 0.2, 0.25, 0.3};
    std::vector<double>       zones = {1e-3, 5e-4, 2.5e-4, 1.25e-4};
    if (quick)
      zones = {4e-3, 2e-3, 1e-3, 5e-4};
    const std::vector<unsigned int> points  = {16, 32}; // per zone, about
    const std::vector<double>       spacing = {1. / 16, 1. / 32};
    const ContactSolverControl      control{1000000, 1e-11};
    // Observed in refinement studies (doc/contact-notes.md): p_bar(a) ~ l + l^1.5 + l^2, the jump's
    // maximum ~ l^2 + l^2.5 + l^3, both ~ dx^2.
    const std::vector<double> load_exponents = {1, 1.5, 2}, jump_exponents = {2, 2.5, 3},
                              grid_exponents = {2};
    std::printf("# Johnson's adhesive sinusoid: p_bar/p* at a/lambda (the edge where the gap reaches rho)\n");
    for (const double alpha : alphas)
      {
        // values[quantity][zone][grid]: the five loads, then the jump.
        std::vector<std::vector<std::vector<double>>> values(ratios.size() + 1,
                                                             std::vector<std::vector<double>>(zones.size()));
        for (std::size_t z = 0; z < zones.size(); ++z)
          for (std::size_t m = 0; m < points.size(); ++m)
            {
              const unsigned int n = 1u
                                     << static_cast<unsigned int>(std::ceil(std::log2(points[m] / zones[z])));
              const auto                     start = std::chrono::steady_clock::now();
              const adhesive_sinusoid::Model model({alpha, zones[z], n});
              const auto                     curve      = model.loads_at_half_widths(ratios, control);
              const auto                     jump       = model.jump_into_contact(control);
              unsigned int                   iterations = 0;
              for (std::size_t k = 0; k < ratios.size(); ++k)
                {
                  values[k][z].push_back(curve[k].load_ratio);
                  iterations += curve[k].iterations;
                }
              values[ratios.size()][z].push_back(jump.load_ratio);
              std::printf("#   alpha %g l_pz/lambda %g n %u (%.1f points per zone): %u iterations, %.1f s\n",
                          alpha, zones[z], n, zones[z] * n, iterations, seconds_since(start));
              std::fflush(stdout);
            }
        // The grid spacing relative to l_pz, as the tables were built.
        std::vector<double> relative_spacing;
        for (const unsigned int p : points)
          relative_spacing.push_back(1. / p);
        std::printf("%6s %6s %12s | %13s %13s %13s %13s | %13s %10s %10s %6s\n", "alpha", "a/lam", "Johnson",
                    "BEM l0", "l0/2", "l0/4", "l0/8", "JKR extrap.", "error est", "|BEM-J|", "order");
        for (std::size_t k = 0; k <= ratios.size(); ++k)
          {
            const bool is_jump = k == ratios.size();
            double     exact, ratio;
            if (is_jump)
              {
                const periodic_array::LoadExtremum jump = periodic_array::jump_into_contact(alpha);
                ratio                                   = jump.contact_ratio;
                exact                                   = jump.load_ratio;
              }
            else
              {
                ratio = ratios[k];
                exact = periodic_array::johnson_load(ratio, alpha);
              }
            const Extrapolated limit =
                extrapolate_in_both(zones, relative_spacing, values[k],
                                    is_jump ? jump_exponents : load_exponents, grid_exponents);
            std::vector<double> finest;
            for (const auto &row : values[k])
              finest.push_back(row.back());
            std::printf("%6g %6s %12.8f | %13.8f %13.8f %13.8f %13.8f | %13.8f %10.2e %10.2e %6s\n", alpha,
                        is_jump ? "jump" : std::to_string(ratio).substr(0, 4).c_str(), exact, finest[0],
                        finest[1], finest[2], finest[3], limit.value, limit.error,
                        std::abs(limit.value - exact), order_text(finest, 2).c_str());
          }
        std::fflush(stdout);
      }
  }

  // The JKR sphere's pull-off under prescribed load, -(3/2) pi w R: the
  // least load along a path of prescribed mean gap. l_pz/a_pull-off halving
  // from 0.1 with the grid tied to it (4 points per zone) in a period of
  // 6 a_pull-off, extrapolated in l_pz; as the grid error at a fixed number of
  // points per zone scales with the zone, that also removes it (8 points per
  // zone at the two coarsest zones show its size). The periodic images shift
  // the load by ~(a/L)^3: the shift from L = 6 to an infinite period,
  // extrapolated from L = 6, 9 and 12 at the coarsest zone, is added.
  void sphere(const bool quick)
  {
    std::vector<double> zones = {0.1, 0.05, 0.025, 0.0125, 0.00625};
    if (quick)
      zones = {0.4, 0.2, 0.1};
    const double               period = 6, points_per_zone = 4;
    const ContactSolverControl control{100000, 1e-9};
    const auto                 pull_off = [&](const double zone, const double L, const double points) {
      const unsigned int           n = static_cast<unsigned int>(std::lround(L * points / zone));
      const auto                   start = std::chrono::steady_clock::now();
      const adhesive_sphere::State state = adhesive_sphere::Model({zone, L, n}).pull_off(control);
      std::printf("#   l_pz %g L %g n %u (%.1f points per zone): F = %.7f at a = %.5f, %.1f s\n", zone, L, n,
                                  zone * n / L, state.load, state.contact_radius, seconds_since(start));
      std::fflush(stdout);
      return state.load;
    };
    std::printf("# The JKR sphere: pull-off load F/(pi w R) (JKR: -1.5) under prescribed load\n");
    const double        unit = M_PI * adhesive_sphere::work_of_adhesion; // pi w R
    std::vector<double> loads, finer;
    for (const double zone : zones)
      loads.push_back(pull_off(zone, period, points_per_zone));
    for (std::size_t k = 0; k < 2; ++k)
      finer.push_back(pull_off(zones[k], period, 2 * points_per_zone));
    // Images: (a/L)^3 and (a/L)^4 through L = 6, 9, 12.
    std::vector<double> by_period = {loads[0]}, inverse_periods = {1 / period};
    for (const double L : {1.5 * period, 2 * period})
      {
        by_period.push_back(pull_off(zones[0], L, points_per_zone));
        inverse_periods.push_back(1 / L);
      }
    const Extrapolated infinite_period = extrapolate(inverse_periods, by_period, {3, 4});
    const Extrapolated in_zone =
        extrapolate(zones, loads, quick ? std::vector<double>{0.5, 1} : std::vector<double>{0.5, 1, 1.5});
    const double shift = infinite_period.value - loads[0];
    const double value = in_zone.value + shift, error = in_zone.error + infinite_period.error;
    std::printf("%10s %14s %14s %8s\n", "l_pz/a_po", "F/(pi w R)", "8 points", "order");
    for (std::size_t k = 0; k < zones.size(); ++k)
      {
        const std::vector<double> upto(loads.begin(), loads.begin() + k + 1);
        std::printf("%10g %14.7f %14s %8s\n", zones[k], loads[k] / unit,
                    k < finer.size() ? std::to_string(finer[k] / unit).c_str() : "",
                    order_text(upto, 2).c_str());
      }
    std::printf("# period L/a_po = 6, 9, 12 at l_pz %g: %.7f %.7f %.7f -> infinite %.7f +- %.1e\n", zones[0],
                by_period[0] / unit, by_period[1] / unit, by_period[2] / unit, infinite_period.value / unit,
                infinite_period.error / unit);
    std::printf(
        "JKR-extrapolated pull-off F/(pi w R) = %.6f +- %.1e (extrapolation in l_pz %.6f, images %+.6f); "
        "relative error against -1.5: %.2e\n",
        value / unit, error / unit, in_zone.value / unit, shift / unit, std::abs(value / unit + 1.5) / 1.5);
    // JKR's F(a) along the unloading path at the finest zone.
    std::printf("# contact radius against load along the unloading path (l_pz %g)\n%10s %12s %12s %10s\n",
                zones.back(), "a/a_po", "F/(pi w R)", "JKR F(a)", "rel. diff");
    const unsigned int n = static_cast<unsigned int>(std::lround(period * points_per_zone / zones.back()));
    for (const adhesive_sphere::State &state :
         adhesive_sphere::Model({zones.back(), period, n}).unloading(control, 6, 0.1))
      std::printf("%10.5f %12.6f %12.6f %10.2e\n", state.contact_radius, state.load / unit,
                  adhesive_sphere::jkr_load(state.contact_radius) / unit,
                  std::abs(state.load / adhesive_sphere::jkr_load(state.contact_radius) - 1));
  }

  // The bi-sinusoid near full contact: without adhesion A_nc/A_0 against
  // (3/(2 pi))(1 - p_bar/p*); with adhesion the load at which the gap snaps
  // shut on loading against 1 - p_bar/p* = psi (2 pi)^(2/5) alpha^(4/5), l_pz
  // halving from c_min/8 (c_min = 0.195 alpha^(2/5) lambda, the gap's radius
  // there; at c_min/4 the gap closes without a jump), 6 points per zone,
  // extrapolated in l_pz with the order the three levels show; and the gap's
  // equivalent radius against the isolated penny gap of its summit.
  void bisinusoid(const bool quick)
  {
    const ContactSolverControl control{100000, 1e-9};
    std::printf("# The bi-sinusoid without adhesion: A_nc/A_0 against (3/(2 pi))(1 - p_bar/p*)\n");
    std::printf("%8s %8s %12s %12s %8s\n", "points", "p_bar/p*", "A_nc/A_0", "isolated", "ratio");
    for (const unsigned int n :
         quick ? std::vector<unsigned int>{256, 512} : std::vector<unsigned int>{512, 1024, 2048})
      for (const adhesive_bisinusoid::State &state :
           adhesive_bisinusoid::Model({0, 0, n}).loading({0.9, 0.95, 0.98, 0.99}, control))
        {
          const double isolated = adhesive_bisinusoid::isolated_noncontact_fraction(state.load_ratio);
          std::printf("%8u %8.3f %12.6f %12.6f %8.4f\n", n, state.load_ratio, state.noncontact_fraction,
                      isolated, state.noncontact_fraction / isolated);
        }
    std::fflush(stdout);

    std::printf("# The bi-sinusoid with adhesion: 1 - p_bar/p* where the gap closes on loading\n");
    const std::vector<double> alphas =
        quick ? std::vector<double>{0.1, 0.03} : std::vector<double>{0.1, 0.03, 0.01};
    const std::vector<double> fractions =
        quick ? std::vector<double>{1. / 8, 1. / 16} : std::vector<double>{1. / 8, 1. / 16, 1. / 32};
    std::printf("%6s %10s | %10s %10s %10s | %10s %9s %9s %8s\n", "alpha", "isolated", "l0", "l0/2", "l0/4",
                "JKR extr.", "error", "ratio", "order");
    for (const double alpha : alphas)
      {
        const double c_min    = 0.19519 * std::pow(alpha, 0.4),
                     isolated = adhesive_bisinusoid::isolated_closure_margin(alpha);
        std::vector<double> zones, margins;
        for (const double fraction : fractions)
          {
            const double       zone = fraction * c_min;
            const unsigned int n = 32 * static_cast<unsigned int>(std::ceil(6 / zone / std::sqrt(2.) / 32));
            const auto         start = std::chrono::steady_clock::now();
            const adhesive_bisinusoid::State state =
                adhesive_bisinusoid::Model({alpha, zone, n}).closure(1 - 1.3 * isolated, control);
            std::printf(
                "#   alpha %g l_pz/lambda %.3g n %u: 1 - p_bar/p* = %.7f, gap radius %.5f lambda, %.1f s\n",
                alpha, zone, n, 1 - state.load_ratio, state.gap_radius ? *state.gap_radius : 0.,
                seconds_since(start));
            std::fflush(stdout);
            zones.push_back(zone);
            margins.push_back(1 - state.load_ratio);
          }
        // The leading order the levels show (if they show one), else 1.
        double order = margins.size() > 2 ? observed_order(margins[0], margins[1], margins[2], 2) : 1;
        if (!(order > 0.25 && order < 4))
          order = 1;
        const Extrapolated limit = extrapolate(zones, margins, {order});
        std::printf("%6g %10.6f | %10.6f %10.6f %10s | %10.6f %9.1e %9.4f %8s\n", alpha, isolated, margins[0],
                    margins[1], margins.size() > 2 ? std::to_string(margins[2]).c_str() : "", limit.value,
                    limit.error, limit.value / isolated, order_text(margins, 2).c_str());
        std::fflush(stdout);
      }

    // The gap against the penny gap of its summit, c from
    // P = c^2/(3 R_p) + sqrt(pi) K_Ic/(2 sqrt(c)) at P = p* - p_bar, along a
    // loading path to near closure, at each zone and extrapolated (order 1).
    const double                     alpha = 0.03, c_min = 0.19519 * std::pow(alpha, 0.4);
    const double                     isolated  = adhesive_bisinusoid::isolated_closure_margin(alpha);
    const std::vector<double>        multiples = {4, 3, 2, 1.5, 1.25};
    std::vector<double>              zones;
    std::vector<std::vector<double>> radii(multiples.size());
    for (const double fraction : fractions)
      {
        const double        zone = fraction * c_min;
        const unsigned int  n    = 32 * static_cast<unsigned int>(std::ceil(6 / zone / std::sqrt(2.) / 32));
        std::vector<double> loads;
        for (const double multiple : multiples)
          loads.push_back(1 - multiple * isolated);
        const auto states = adhesive_bisinusoid::Model({alpha, zone, n}).loading(loads, control);
        zones.push_back(zone);
        for (std::size_t k = 0; k < multiples.size(); ++k)
          radii[k].push_back(states[k].gap_radius ? *states[k].gap_radius : -1); // -1: closed
      }
    std::printf("# The gap's equivalent radius sqrt(area/pi) (where g > rho) against the isolated penny gap, "
                "alpha = %g\n%10s %10s | %10s %10s %10s | %10s %9s %9s\n",
                alpha, "P/p0", "c penny", "l0", "l0/2", "l0/4", "extrap.", "error", "ratio");
    for (std::size_t k = 0; k < multiples.size(); ++k)
      {
        const double       penny = *adhesive_bisinusoid::isolated_gap_radius(multiples[k] * isolated, alpha);
        const Extrapolated limit = extrapolate(zones, radii[k], {1});
        std::printf("%10g %10.6f | %10.6f %10.6f %10s | %10.6f %9.1e %9.4f\n", multiples[k], penny,
                    radii[k][0], radii[k][1], radii[k].size() > 2 ? std::to_string(radii[k][2]).c_str() : "",
                    limit.value, limit.error, limit.value / penny);
      }
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      if (argc < 2 || argc > 3 || (argc == 3 && std::strcmp(argv[2], "quick") != 0))
        throw std::invalid_argument("usage: verify_contact sinusoid|sphere|bisinusoid [quick]");
      const bool        quick   = argc == 3;
      const std::string problem = argv[1];
      print_load_average();
      const auto start = std::chrono::steady_clock::now();
      if (problem == "sinusoid")
        sinusoid(quick);
      else if (problem == "sphere")
        sphere(quick);
      else if (problem == "bisinusoid")
        bisinusoid(quick);
      else
        throw std::invalid_argument("verify_contact: unknown problem '" + problem + "'");
      print_load_average();
      std::printf("# wall time %.0f s\n", seconds_since(start));
    }
  catch (const std::exception &error)
    {
      std::fprintf(stderr, "%s\n", error.what());
      return 1;
    }
}
