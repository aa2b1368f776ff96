// bem-bisinusoid: the bi-sinusoid near full contact (full-contact pressure
// p_bar - p* cos(kx) cos(ky)) by the adhesive boundary-element solver
// (contact/adhesive_bisinusoid.h), against the isolated penny gap of each
// tension peak: without adhesion A_nc/A_0 against (3/(2 pi))(1 - p_bar/p*);
// with adhesion the load at which the gaps snap shut on loading, extrapolated
// to the JKR limit, against 1 - p_bar/p* = psi (2 pi)^(2/5) alpha^(4/5), and
// the gap's radius on the way against the penny gap of its summit. PASS when
// the closure load's ratio to that asymptote at the smallest alpha lies
// within Verification/Tolerance of 1.
#include "contact/adhesive_bisinusoid.h"
#include "contact/extrapolation.h"
#include "problems/contact_solver.h"
#include "scenes/scene.h"

#include <deal.II/base/timer.h>

#include <cmath>

namespace penny
{
  namespace
  {
    // c_min/lambda = 0.19519 alpha^(2/5): the radius of the isolated gap at closure.
    double closing_gap_radius(const double alpha)
    {
      return 0.19519 * std::pow(alpha, 0.4);
    }

    struct BemBisinusoidScene : Scene
    {
      void inputs(Sections &sections) override { contact_solver_section(sections, control, 1e-9); }

      void entries(Entries &entries) override
      {
        entries.numbers("Adhesionless load ratios", load_ratios, {0.9, 0.95, 0.98, 0.99},
                        interval("()", 0, 1), "p_bar/p* of the adhesionless loading path. Units: none.");
        entries.integer("Adhesionless grid", adhesionless_points, 1024u, 16u, 8192u,
                        "Points per side of the cell lambda/sqrt(2) without adhesion. Units: none.");
        entries.decreasing_numbers("Johnson parameters alpha", alphas, {0.1, 0.03, 0.01}, 1,
                                   interval("[]", 1e-3, 0.3),
                                   "alpha = K_Ic/(p* sqrt(lambda)): one closure load each. Units: none.");
        entries.decreasing_numbers(
            "Cohesive zones l_pz/c_min", zones, {1. / 8, 1. / 16, 1. / 32}, 2, interval("[]", 1e-3, 0.125),
            "l_pz = E* rho^2/(pi w), in units of the closing gap's radius c_min = 0.195 alpha^(2/5) "
            "lambda; "
            "above c_min/8 the gap shrinks to nothing without a jump. Units: c_min.");
        entries.number("Points per cohesive zone", points_per_zone, 6,
                       interval("[]", HalfSpaceContact::min_process_zone_points, 100),
                       "Grid points over l_pz. Units: none.");
        if (!entries.reading())
          return;
        // Beyond 8192 points a side a solve outgrows this verifier's memory.
        entries.require(grid_points(alphas.back(), zones.back()) <= 8192, "Cohesive zones l_pz/c_min",
                        zones.back(), "a grid of at most 8192 points a side at the smallest alpha");
      }

      // Points per side of the cell lambda/sqrt(2), a multiple of 32.
      unsigned int grid_points(const double alpha, const double zone) const
      {
        const double l_pz = zone * closing_gap_radius(alpha);
        return 32 * static_cast<unsigned int>(std::ceil(points_per_zone / l_pz / std::sqrt(2.) / 32));
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        Table adhesionless({{"p_bar/p*", Table::Format{4, false}},
                            {"A_nc/A_0", Table::digits},
                            {"(3/(2 pi))(1 - p_bar/p*)", Table::digits},
                            {"ratio", Table::Format{6, false}}});
        for (const auto &state :
             adhesive_bisinusoid::Model({0, 0, adhesionless_points}).loading(load_ratios, control))
          {
            const double isolated = adhesive_bisinusoid::isolated_noncontact_fraction(state.load_ratio);
            adhesionless.add_row({state.load_ratio, state.noncontact_fraction, isolated,
                                  state.noncontact_fraction / isolated});
          }
        publish(adhesionless, "bem-bisinusoid-adhesionless.csv", results, log,
                "The bi-sinusoid without adhesion: A_nc/A_0 against the isolated gaps' (3/(2 pi))(1 - "
                "p_bar/p*)");

        std::vector<Table::Column> columns = {{"alpha", Table::Format{4, false}},
                                              {"isolated psi (2 pi)^(2/5) alpha^(4/5)", Table::digits}};
        for (const double zone : zones)
          columns.push_back({"BEM l_pz/c_min=" + Table::label(zone), Table::digits});
        for (const std::string column : {"JKR limit", "error estimate", "ratio to isolated"})
          columns.push_back({column, column == "error estimate" ? Table::error_digits : Table::digits});
        Table  closure(columns);
        Table  cost({{"alpha", Table::Format{4, false}},
                     {"l_pz/c_min", Table::Format{4, false}},
                     "points per side",
                     {"wall time (s)", Table::Format{3, false}}});
        double last_ratio = 0;
        for (const double alpha : alphas)
          {
            const double        isolated = adhesive_bisinusoid::isolated_closure_margin(alpha);
            std::vector<double> lengths, margins;
            for (const double zone : zones)
              {
                dealii::Timer      timer;
                const double       l_pz = zone * closing_gap_radius(alpha);
                const unsigned int n    = grid_points(alpha, zone);
                const auto         state =
                    adhesive_bisinusoid::Model({alpha, l_pz, n}).closure(1 - 1.3 * isolated, control);
                lengths.push_back(l_pz);
                margins.push_back(1 - state.load_ratio);
                cost.add_row({alpha, zone, n, timer.wall_time()});
              }
            // The leading order the levels show (if they show one), else 1.
            double order = margins.size() > 2
                               ? observed_order(margins[margins.size() - 3], margins[margins.size() - 2],
                                                margins.back(), zones[zones.size() - 2] / zones.back())
                               : 1;
            if (!(order > 0.25 && order < 4))
              order = 1;
            const Extrapolated       limit = extrapolate(lengths, margins, {order});
            std::vector<Table::Cell> row   = {alpha, isolated};
            for (const double margin : margins)
              row.emplace_back(margin);
            for (const double cell : {limit.value, limit.error, limit.value / isolated})
              row.emplace_back(cell);
            closure.add_row(row);
            last_ratio = limit.value / isolated;
          }
        publish(closure, "bem-bisinusoid-closure.csv", results, log,
                "The bi-sinusoid with adhesion: 1 - p_bar/p* where the gaps snap shut on loading, at each "
                "cohesive zone and extrapolated to the JKR limit, against the isolated penny gaps' "
                "psi (2 pi)^(2/5) alpha^(4/5)");
        publish(cost, "bem-bisinusoid-cost.csv", results, log, "Closure solves:");
        return verdict(std::abs(last_ratio - 1));
      }

      std::vector<double>  load_ratios, alphas, zones;
      unsigned int         adhesionless_points;
      double               points_per_zone;
      ContactSolverControl control;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      BemBisinusoidScene, "bem-bisinusoid", "BEM bi-sinusoid",
      "the bi-sinusoid near full contact by the adhesive boundary-element solver: non-contact "
      "area and the gaps' closure load against the isolated penny gaps of its summits",
      "|closure load margin/(psi (2 pi)^(2/5) alpha^(4/5)) - 1| at the smallest alpha")
} // namespace penny
