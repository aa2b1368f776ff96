// bem-johnson: Johnson's adhesive sinusoid by the adhesive boundary-element
// solver (contact/adhesive_sinusoid.h), in the JKR limit. For each alpha,
// p_bar/p* at the tabulated a/lambda and the jump into contact are computed
// for each cohesive zone l_pz and grid, extrapolated to l_pz -> 0 and
// dx -> 0 (Richardson, contact/extrapolation.h), and set beside Johnson's
// closed form and the project's FE periodic gap (the johnson-curves and
// jump-into-contact computations). PASS when every extrapolated value lies
// within Verification/Tolerance of Johnson's.
#include "closed_forms/periodic_array.h"
#include "contact/adhesive_sinusoid.h"
#include "contact/extrapolation.h"
#include "numerics/relative_error.h"
#include "output/progress.h"
#include "problems/contact_solver.h"
#include "problems/periodic_gap.h"
#include "scenes/scene.h"
#include "searches/periodic_searches.h"

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>

namespace penny
{
  namespace
  {
    // Observed in refinement studies (doc/contact-notes.md, section 6): p_bar(a)
    // converges like l + l^1.5 + l^2 in the cohesive zone, the jump's maximum
    // like l^2 + l^2.5 + l^3, both like dx^2 at a fixed zone.
    const std::vector<double> load_exponents = {1, 1.5, 2}, jump_exponents = {2, 2.5, 3};

    struct BemJohnsonScene : Scene
    {
      void inputs(Sections &sections) override
      {
        periodic.sections(sections);
        contact_solver_section(sections, control, 1e-11);
      }

      void entries(Entries &entries) override
      {
        entries.numbers("Johnson parameters alpha", alphas, {0.05, 0.2, 0.5}, interval("[]", 0.01, 0.56),
                        "alpha = K_Ic/(p* sqrt(lambda)), one curve and one jump each. Units: none.");
        entries.increasing_numbers("Contact half-widths a/lambda", ratios, {0.1, 0.15, 0.2, 0.25, 0.3}, 1,
                                   interval("[]", 0.1, 0.4), "Where p_bar/p* is tabulated. Units: lambda.");
        entries.decreasing_numbers(
            "Cohesive zones l_pz/lambda", zones, {1e-3, 5e-4, 2.5e-4, 1.25e-4}, 2, interval("[]", 1e-6, 0.02),
            "l_pz = E* rho^2/(pi w) of the exponential law, extrapolated to 0 through the finest four "
            "(exponents 1, 1.5, 2; the jump 2, 2.5, 3); at most c_min/8 at every alpha, c_min = "
            "(alpha/4)^(2/5) lambda/pi the gap's half-width at Johnson's jump. Units: lambda.");
        entries.increasing_numbers(
            "Points per cohesive zone", points_per_zone, {16, 32}, 1,
            interval("[]", HalfSpaceContact::min_process_zone_points, 1000),
            "One value, or two for an extrapolation in the grid spacing "
            "(exponent 2); the grid is the next power of two above points/(l_pz/lambda). "
            "Units: none.");
        if (!entries.reading())
          return;
        entries.require(points_per_zone.size() <= 2, "Points per cohesive zone", points_per_zone.back(),
                        "one value, or two increasing");
        // A zone above 1/8 of the gap's half-width at the jump, c_min = (alpha/4)^(2/5)
        // lambda/pi, leaves the JKR regime before the path reaches the jump.
        for (const double alpha : alphas)
          {
            const double largest = std::pow(alpha / 4, 0.4) / M_PI / 8;
            entries.require(zones.front() <= largest, "Cohesive zones l_pz/lambda", zones.front(),
                            "[1e-6, c_min/8 = " + Table::label(largest, 3) +
                                "] at alpha = " + Table::label(alpha) +
                                ", c_min = (alpha/4)^(2/5) lambda/pi the gap's half-width "
                                "at the jump");
          }
        // Beyond 2^22 points a solve outgrows this verifier's memory and time.
        entries.require(grid_points(zones.back(), points_per_zone.back()) <= (1u << 22),
                        "Points per cohesive zone", points_per_zone.back(),
                        "at most 2^22 points per wavelength over the smallest zone");
      }

      static unsigned int grid_points(const double zone, const double points)
      {
        return 1u << static_cast<unsigned int>(std::ceil(std::log2(points / zone)));
      }

      // values[zone][grid] extrapolated to the JKR limit with `exponents` in the zone.
      Extrapolated jkr_limit(const std::vector<std::vector<double>> &values,
                             const std::vector<double>              &exponents) const
      {
        const std::vector<double> in_zone(exponents.begin(),
                                          exponents.begin() + std::min(exponents.size(), zones.size() - 1));
        if (points_per_zone.size() == 1)
          {
            std::vector<double> column;
            for (const auto &row : values)
              column.push_back(row.front());
            return extrapolate(zones, column, in_zone);
          }
        return extrapolate_in_both(zones, {1 / points_per_zone[0], 1 / points_per_zone[1]}, values, in_zone,
                                   {2});
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        Progress            progress(log, "discretisations", 0);
        PeriodicGapSearch   search(periodic);
        const double        lambda = periodic.model.wavelength;
        std::vector<double> half_widths;
        for (const double ratio : ratios)
          half_widths.push_back((0.5 - ratio) * lambda);
        const std::vector<SinusoidUnitSifs> sifs = search.gaps.unit_load_sifs(half_widths, MPI_COMM_WORLD);

        std::vector<Table::Column> columns = {{"alpha", Table::Format{4, false}},
                                              {"a/lambda", Table::Format{6, false}},
                                              {"Johnson", Table::digits},
                                              {"FE", Table::digits}};
        for (const double zone : zones)
          columns.push_back({"BEM l_pz/lambda=" + Table::label(zone), Table::digits});
        for (const auto &column :
             std::vector<std::string>{"BEM JKR limit", "error estimate", "|BEM - Johnson|", "|BEM - FE|"})
          columns.push_back({column, column == "BEM JKR limit" ? Table::digits : Table::error_digits});
        Table  table(columns);
        Table  cost({{"alpha", Table::Format{4, false}},
                     "l_pz/lambda",
                     "points per lambda",
                     "iterations",
                     {"wall time (s)", Table::Format{3, false}}});
        double worst = 0;
        for (const double alpha : alphas)
          {
            // values[quantity][zone][grid]: the loads at each a/lambda, then the jump.
            std::vector<std::vector<std::vector<double>>> values(
                ratios.size() + 1, std::vector<std::vector<double>>(zones.size()));
            for (std::size_t z = 0; z < zones.size(); ++z)
              for (const double points : points_per_zone)
                {
                  dealii::Timer                  timer;
                  const unsigned int             n = grid_points(zones[z], points);
                  const adhesive_sinusoid::Model model({alpha, zones[z], n});
                  const auto                     curve      = model.loads_at_half_widths(ratios, control);
                  const auto                     jump       = model.jump_into_contact(control, curve);
                  unsigned int                   iterations = 0;
                  for (std::size_t k = 0; k < ratios.size(); ++k)
                    {
                      values[k][z].push_back(curve[k].load_ratio);
                      iterations += curve[k].iterations;
                    }
                  values.back()[z].push_back(jump.load_ratio);
                  cost.add_row({alpha, zones[z], n, iterations, timer.wall_time()});
                  progress.step("last alpha = " + Table::label(alpha) + ", l_pz/lambda = " +
                                Table::label(zones[z]) + ", " + std::to_string(n) + " points");
                }
            const FeLoadExtremum fe_jump = fe_jump_into_contact(search.gaps, alpha, MPI_COMM_WORLD);
            for (std::size_t k = 0; k <= ratios.size(); ++k)
              {
                const bool   is_jump = k == ratios.size();
                const auto   exact   = periodic_array::jump_into_contact(alpha);
                const double johnson =
                    is_jump ? exact.load_ratio : periodic_array::johnson_load(ratios[k], alpha);
                const double fe = is_jump ? fe_jump.load_ratio : fe_johnson_load(sifs[k], lambda, alpha);
                const Extrapolated limit = jkr_limit(values[k], is_jump ? jump_exponents : load_exponents);
                // The jump's row at the a/lambda of Johnson's maximum.
                std::vector<Table::Cell> row = {alpha, is_jump ? exact.contact_ratio : ratios[k], johnson,
                                                fe};
                for (const auto &at_zone : values[k])
                  row.emplace_back(at_zone.back());
                for (const double cell :
                     {limit.value, limit.error, std::abs(limit.value - johnson), std::abs(limit.value - fe)})
                  row.emplace_back(cell);
                table.add_row(row);
                worst = worse(worst, std::abs(limit.value - johnson));
              }
          }
        publish(table, "bem-johnson.csv", results, log,
                "Johnson's adhesive sinusoid by boundary elements: p_bar/p* at a/lambda (the edge where the "
                "gap reaches rho) and at the jump into contact, on the finest grid at each cohesive zone and "
                "extrapolated to the JKR limit, beside Johnson's closed form and the FE periodic gap");
        publish(
            cost, "bem-johnson-cost.csv", results, log,
            "Solves of each alpha, zone and grid (iterations on the grid, and on the halved grids of nested "
            "iteration weighted by their points; the a/lambda solves only):");
        return verdict(worst);
      }

      PeriodicGapInput     periodic;
      std::vector<double>  alphas, ratios, zones, points_per_zone;
      ContactSolverControl control;
    };
  } // namespace

  PENNY_REGISTER_SCENE(BemJohnsonScene, "bem-johnson", "BEM Johnson",
                       "Johnson's adhesive sinusoid by the adhesive boundary-element solver, extrapolated to "
                       "the JKR limit, against Johnson's closed form and the FE periodic gap",
                       "largest |p_bar/p* BEM (JKR limit) - Johnson|")
} // namespace penny
