#include "contact/adhesive_sphere.h"

#include "contact/contact_geometry.h"
#include "contact/contact_path.h"

#include <cmath>
#include <stdexcept>

namespace penny::adhesive_sphere
{
  double jkr_load(const double contact_radius)
  {
    const double a3 = std::pow(contact_radius, 3);
    return 4 * a3 / 3 - std::sqrt(8 * M_PI * work_of_adhesion * a3);
  }

  // The apex at the grid point (n/2, n/2); x, y periodic offsets from it.
  Model::Model(const Discretisation &discretisation)
      : discretisation(checked(discretisation,
                               discretisation.process_zone > 0 && discretisation.period > 4 &&
                                   discretisation.n_points >= 16,
                               "adhesive sphere: needs l_pz > 0, a period above 4 a_pull-off and 16 points")),
        surface(square_grid(discretisation.n_points, discretisation.period),
                [n = discretisation.n_points, L = discretisation.period](unsigned int i, unsigned int j) {
                  const double x = (double(i) - n / 2) * L / n, y = (double(j) - n / 2) * L / n;
                  return -(x * x + y * y) / 2;
                },
                {work_of_adhesion, std::sqrt(M_PI * work_of_adhesion * discretisation.process_zone)})
  {
  }

  State Model::state(const ContactSolution &solution) const
  {
    const double area = std::pow(discretisation.period, 2);
    const double a    = level_radius(surface.grid(), solution.gap, range(), discretisation.n_points / 2,
                                     discretisation.n_points / 2);
    return {a, solution.mean_pressure * area, solution.mean_gap};
  }

  // Hertz's contact of radius 1.2 (load 4 a^3/3), then adhesion switched
  // on at its mean gap: the contact grows, near JKR's at zero load.
  ContactSolution Model::start(const ContactSolverControl &control) const
  {
    const ContactSolution hertz =
        surface.adhesionless().solve(4 * std::pow(1.2, 3) / 3 / std::pow(discretisation.period, 2), control);
    return surface.adhesive().solve_at_mean_gap(hertz.mean_gap, control, hertz.gap);
  }

  std::vector<State> Model::unloading(const ContactSolverControl &control, const unsigned int steps,
                                      const double increment) const
  {
    const ContactSolution from = start(control);
    ContactPath           path(surface.adhesive(), "unloading", control, from.gap);
    std::vector<State>    states;
    double                mean_gap = from.mean_gap;
    const std::size_t     apex     = std::size_t(discretisation.n_points / 2) * (discretisation.n_points + 1);
    for (unsigned int k = 0; k <= steps; ++k)
      {
        const ContactSolution &solution = path.to_mean_gap(mean_gap);
        if (solution.gap[apex] > range())
          break;
        states.push_back(state(solution));
        mean_gap += increment;
      }
    return states;
  }

  State Model::pull_off(const ContactSolverControl &control) const
  {
    const ContactSolution from = start(control);
    // Steps of 0.04 in the approach (about 1.2 from zero load to pull-off).
    const double factor = 1 + 0.04 / from.mean_gap;
    return state(load_extremum(surface.adhesive(), control, from, factor, false));
  }
} // namespace penny::adhesive_sphere
