// The adhesive boundary-element solver against problems with exact answers,
// at full size (the unit tests run the same models small): Johnson's
// sinusoid, the JKR sphere and the bi-sinusoid near full contact. Each
// adhesive number is computed on a table of cohesive-zone lengths l_pz and
// grid spacings and extrapolated to the JKR limit by Richardson (both
// parameters), with the error estimate of contact/extrapolation.h.
//
// Usage: verify_contact sinusoid|sphere|bisinusoid [quick]
// ("quick": the two coarsest levels fewer, for a look in minutes).
#include "contact/adhesive_bisinusoid.h"
#include "contact/adhesive_sinusoid.h"
#include "contact/adhesive_sphere.h"
#include "contact/extrapolation.h"

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
    std::snprintf(text, sizeof text, "%.2f", observed_order(values[k - 3], values[k - 2], values[k - 1], ratio));
    return text;
  }

  // Johnson's sinusoid: p_bar/p* at a/lambda = 0.1 ... 0.3 and the jump into
  // contact for alpha = 0.05, 0.2, 0.5; l_pz/lambda halving from 1e-3, the
  // grid 16 and 32 points per cohesive zone (n a power of two).
  void sinusoid(const bool quick)
  {
    const std::vector<double> alphas = {0.05, 0.2, 0.5}, ratios = {0.1, 0.15, 0.2, 0.25, 0.3};
    std::vector<double>       zones  = {1e-3, 5e-4, 2.5e-4, 1.25e-4};
    if (quick)
      zones = {4e-3, 2e-3, 1e-3, 5e-4};
    const std::vector<unsigned int> points = {16, 32}; // per zone, about
    const std::vector<double>       spacing = {1. / 16, 1. / 32};
    const ContactSolverControl      control{1000000, 1e-11};
    // Observed in refinement studies (doc/contact-notes.md): p_bar(a) ~ l + l^1.5 + l^2, the jump's
    // maximum ~ l^2 + l^2.5 + l^3, both ~ dx^2.
    const std::vector<double> load_exponents = {1, 1.5, 2}, jump_exponents = {2, 2.5, 3}, grid_exponents = {2};
    std::printf("# Johnson's adhesive sinusoid: p_bar/p* at a/lambda (the edge where the gap reaches rho)\n");
    for (const double alpha : alphas)
      {
        // values[quantity][zone][grid]: the five loads, then the jump.
        std::vector<std::vector<std::vector<double>>> values(ratios.size() + 1,
                                                               std::vector<std::vector<double>>(zones.size()));
        for (std::size_t z = 0; z < zones.size(); ++z)
          for (std::size_t m = 0; m < points.size(); ++m)
            {
              const unsigned int n = 1u << static_cast<unsigned int>(std::ceil(std::log2(points[m] / zones[z])));
              const auto         start = std::chrono::steady_clock::now();
              const adhesive_sinusoid::Model model({alpha, zones[z], n});
              const auto         curve = model.loads_at_half_widths(ratios, control);
              const auto         jump  = model.jump_into_contact(control);
              unsigned int       iterations = 0;
              for (std::size_t k = 0; k < ratios.size(); ++k)
                {
                  values[k][z].push_back(curve[k].load_ratio);
                  iterations += curve[k].iterations;
                }
              values[ratios.size()][z].push_back(jump.load_ratio);
              std::printf("#   alpha %g l_pz/lambda %g n %u (%.1f points per zone): %u iterations, %.1f s\n", alpha,
                          zones[z], n, zones[z] * n, iterations, seconds_since(start));
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
            const bool   is_jump = k == ratios.size();
            double       exact, ratio;
            if (is_jump)
              {
                const adhesive_sinusoid::Extremum jump = adhesive_sinusoid::johnson_jump(alpha);
                ratio                                  = jump.contact_ratio;
                exact                                  = jump.load_ratio;
              }
            else
              {
                ratio = ratios[k];
                exact = adhesive_sinusoid::johnson_load(ratio, alpha);
              }
            const Extrapolated limit = extrapolate_in_both(zones, relative_spacing, values[k],
                                                           is_jump ? jump_exponents : load_exponents, grid_exponents);
            std::vector<double> finest;
            for (const auto &row : values[k])
              finest.push_back(row.back());
            std::printf("%6g %6s %12.8f | %13.8f %13.8f %13.8f %13.8f | %13.8f %10.2e %10.2e %6s\n", alpha,
                        is_jump ? "jump" : std::to_string(ratio).substr(0, 4).c_str(), exact, finest[0], finest[1],
                        finest[2], finest[3], limit.value, limit.error, std::abs(limit.value - exact),
                        order_text(finest, 2).c_str());
          }
        std::fflush(stdout);
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
