#include "contact/adhesive_bisinusoid.h"

#include "closed_forms/adhesive_gap.h"
#include "contact/contact_geometry.h"
#include "contact/contact_path.h"

#include <cmath>
#include <stdexcept>

namespace penny::adhesive_bisinusoid
{
  namespace
  {
    const double cell      = 1 / std::sqrt(2.);          // lambda/sqrt(2)
    const double amplitude = 1 / (std::sqrt(2.) * M_PI); // Delta: p* = sqrt(2) pi E* Delta/lambda = 1
  }                                                      // namespace

  // Two gaps of radius sqrt(3/2) a, a^2 = 2 R_p P, per lambda^2.
  double isolated_noncontact_fraction(const double load_ratio)
  {
    const double a = std::sqrt(2 * summit_radius * (1 - load_ratio));
    return 2 * M_PI * std::pow(closed_form::adhesionless_c_over_a * a, 2);
  }

  double isolated_closure_margin(const double alpha)
  {
    return closed_form::psi * adhesion_tension(summit_radius, alpha);
  }

  std::optional<double> isolated_gap_radius(const double load_margin, const double alpha)
  {
    return closed_form::stable_gap_radius(load_margin, summit_radius, alpha);
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
                                    const ContactSolverControl &control, const bool until_closure) const
  {
    if (until_closure && !(discretisation.alpha > 0))
      throw std::invalid_argument("adhesive bi-sinusoid: without adhesion the gaps close only at p_bar = p*");
    ContactPath        path(surface.adhesive(), "loading", control,
                            surface.adhesionless().solve(load_ratios.front(), control).gap);
    std::vector<State> states;
    for (const double load : load_ratios)
      states.push_back(state(path.to_mean_pressure(load)));
    if (!until_closure)
      return states;
    if (!(path.current().contact_fraction < 1))
      throw std::runtime_error(
          "adhesive bi-sinusoid: the gap is already closed at the last load of the path");
    states.push_back(state(load_extremum(surface.adhesive(), control, path.current(), 0.8, true)));
    return states;
  }
} // namespace penny::adhesive_bisinusoid
