#include "contact/adhesive_bisinusoid.h"

#include "contact/contact_geometry.h"
#include "contact/contact_path.h"

#include <cmath>
#include <stdexcept>

namespace penny::adhesive_bisinusoid
{
  namespace
  {
    const double cell       = 1 / std::sqrt(2.);          // lambda/sqrt(2)
    const double amplitude  = 1 / (std::sqrt(2.) * M_PI); // Delta: p* = sqrt(2) pi E* Delta/lambda = 1
    const double rp         = 1 / (4 * M_PI * M_PI);      // R_p = 1/(p* k^2)
    const double gap_factor = 0.8492635438677062;         // c_min = gap_factor (R_p K_Ic)^(2/5)
  }                                                       // namespace

  double isolated_noncontact_fraction(const double load_ratio)
  {
    return 3 / (2 * M_PI) * (1 - load_ratio);
  }

  double isolated_closure_margin(const double alpha)
  {
    return psi * std::pow(2 * M_PI, 0.4) * std::pow(alpha, 0.8);
  }

  // P(c) = c^2/(3 R_p) + sqrt(pi) K_Ic/(2 sqrt(c)) rises for c > c_min: bisection there.
  std::optional<double> isolated_gap_radius(const double load_margin, const double alpha)
  {
    const auto tension = [&](const double c) {
      return c * c / (3 * rp) + std::sqrt(M_PI) * alpha / (2 * std::sqrt(c));
    };
    double low = gap_factor * std::pow(rp * alpha, 0.4), high = 1;
    if (load_margin < tension(low))
      return std::nullopt;
    for (int k = 0; k < 200; ++k)
      {
        const double middle                          = (low + high) / 2;
        (tension(middle) < load_margin ? low : high) = middle;
      }
    return (low + high) / 2;
  }

  // The valley, where the tension peaks, at the grid point (n/2, n/2).
  Model::Model(const Discretisation &discretisation)
      : discretisation(checked(discretisation,
                               discretisation.alpha >= 0 &&
                                   (discretisation.alpha == 0 || discretisation.process_zone > 0) &&
                                   discretisation.n_points >= 16,
                               "adhesive bi-sinusoid: needs alpha >= 0, l_pz > 0 and at least 16 points")),
        surface(square_grid(discretisation.n_points, cell),
                [n = discretisation.n_points](unsigned int i, unsigned int j) {
                  return amplitude / 2 * (std::cos(2 * M_PI * i / n) + std::cos(2 * M_PI * j / n));
                },
                {discretisation.alpha * discretisation.alpha / 2,
                 discretisation.alpha * std::sqrt(M_PI * discretisation.process_zone / 2)})
  {
  }

  State Model::state(const ContactSolution &solution) const
  {
    State s{solution.mean_pressure, solution.mean_gap, 1 - solution.contact_fraction, std::nullopt};
    const unsigned int centre = discretisation.n_points / 2;
    if (discretisation.alpha > 0)
      {
        const double range = surface.adhesion().range;
        if (solution.gap[centre * discretisation.n_points + centre] > range)
          s.gap_radius = level_radius(surface.grid(), solution.gap, range, centre, centre);
      }
    else if (s.noncontact_fraction > 0)
      s.gap_radius = std::sqrt(s.noncontact_fraction * cell * cell / M_PI);
    return s;
  }

  std::vector<State> Model::loading(const std::vector<double>  &load_ratios,
                                    const ContactSolverControl &control) const
  {
    ContactPath        path(surface.adhesive(), "loading", control,
                            surface.adhesionless().solve(load_ratios.front(), control).gap);
    std::vector<State> states;
    for (const double load : load_ratios)
      states.push_back(state(path.to_mean_pressure(load)));
    return states;
  }

  State Model::closure(const double start_load_ratio, const ContactSolverControl &control) const
  {
    if (!(discretisation.alpha > 0))
      throw std::invalid_argument("adhesive bi-sinusoid: without adhesion the gaps close only at p_bar = p*");
    const ContactSolution from = surface.adhesive().solve(
        start_load_ratio, control, surface.adhesionless().solve(start_load_ratio, control).gap);
    if (!(from.contact_fraction < 1))
      throw std::runtime_error("adhesive bi-sinusoid: the gap is already closed at the start load");
    return state(load_extremum(surface.adhesive(), control, from, 0.8, true));
  }
} // namespace penny::adhesive_bisinusoid
