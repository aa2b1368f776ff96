// bem-bisinusoid: the bi-sinusoid near full contact (full-contact pressure
// p_bar - p* cos(kx) cos(ky)) by the adhesive boundary-element solver
// (contact/adhesive_bisinusoid.h), against the isolated penny gap of each
// tension peak, P = p* - p_bar and R_p = 1/(p* k^2), from its closed forms
// and from the axisymmetric FE model: without adhesion A_nc/A_0 against
// (3/(2 pi))(1 - p_bar/p*) and each gap's radius against the FE gap; with
// adhesion the gap's radius along a loading path and the load at which the
// gaps snap shut, each extrapolated to the JKR limit, against the FE gap and
// the FE p0 and 1 - p_bar/p* = psi (2 pi)^(2/5) alpha^(4/5). PASS when the
// closure load's ratio to that asymptote at the smallest alpha lies within
// Verification/Tolerance of 1.
#include "closed_forms/adhesive_gap.h"
#include "contact/adhesive_bisinusoid.h"
#include "contact/extrapolation.h"
#include "output/progress.h"
#include "parallel/memory_budget.h"
#include "problems/contact_solver.h"
#include "problems/penny_gap.h"
#include "scenes/scene.h"
#include "searches/gap_searches.h"

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>

namespace penny
{
  namespace
  {
    using adhesive_bisinusoid::summit_radius;

    // c_min/lambda: the radius of the isolated gap at closure, 0.195 alpha^(2/5).
    double closing_gap_radius(const double alpha)
    {
      return closed_form::c_min_factor * adhesion_length(summit_radius, alpha);
    }

    // The JKR limit of results at cohesive zones `lengths` (decreasing): at
    // the leading order the last three show, if they show one in (1/4, 4),
    // else at order 1.
    Extrapolated jkr_limit(const std::vector<double> &lengths, const std::vector<double> &values)
    {
      const std::size_t n = values.size();
      double            order =
          n > 2 ? observed_order(values[n - 3], values[n - 2], values[n - 1], lengths[n - 2] / lengths[n - 1])
                           : 1;
      if (!(order > 0.25 && order < 4))
        order = 1;
      return extrapolate(lengths, values, {order});
    }

    struct BemBisinusoidScene : Scene
    {
      void inputs(Sections &sections) override
      {
        gap.sections(sections);
        contact_solver_section(sections, control, 1e-9);
      }

      void entries(Entries &entries) override
      {
        entries.increasing_numbers("Adhesionless load ratios", load_ratios, {0.9, 0.95, 0.98, 0.99}, 1,
                                   interval("()", 0, 1),
                                   "p_bar/p* of the adhesionless loading path. Units: none.");
        entries.integer("Adhesionless grid", adhesionless_points, 1024u, 16u, 8192u,
                        "Points per side of the cell lambda/sqrt(2) without adhesion. Units: none.");
        entries.decreasing_numbers(
            "Johnson parameters alpha", alphas, {0.1, 0.03, 0.01}, 1, interval("[]", 1e-3, 0.2),
            "alpha = K_Ic/(p* sqrt(lambda)): one loading path to closure each. Units: none.");
        entries.decreasing_numbers(
            "Tension ratios P/p0", tension_ratios, {2, 1.5, 1.25}, 1, interval("(]", 1, 100),
            "The adhesive loading path: the peak tensions P = p* - p_bar of its states, in units of the "
            "isolated gap's p0, each below p* (the load presses; the path starts without adhesion); the "
            "gaps' radii are tabulated there, and the path goes on from the last to the closure. Units: "
            "p0.");
        zones.entries(entries, "c_min", {{1. / 8, 1. / 16, 1. / 32}, 6}, 2, interval("[]", 1e-3, 0.125),
                      "the closing gap's radius c_min = 0.195 alpha^(2/5) lambda, extrapolated to 0 at the "
                      "order the last three show; above c_min/8 the gap shrinks to nothing without a jump.");
        if (!entries.reading())
          return;
        for (const double alpha : alphas)
          {
            const double largest = 1 / adhesive_bisinusoid::isolated_closure_margin(alpha);
            entries.require(tension_ratios.front() < largest, "Tension ratios P/p0", tension_ratios.front(),
                            "(1, p*/p0 = " + Table::label(largest, 3) +
                                ") at alpha = " + Table::label(alpha) + ", where the load still presses");
          }
        // Beyond 8192 points a side a solve runs for hours (and run() holds it
        // to the run's memory).
        entries.require(grid_points(alphas.back(), zones.lengths.back()) <= 8192, "Cohesive zones l_pz/c_min",
                        zones.lengths.back(), "a grid of at most 8192 points a side at the smallest alpha");
      }

      // Points per side of the cell lambda/sqrt(2), a multiple of 32.
      unsigned int grid_points(const double alpha, const double zone) const
      {
        const double l_pz = zone * closing_gap_radius(alpha);
        return 32 * static_cast<unsigned int>(std::ceil(zones.points_per_zone / l_pz / std::sqrt(2.) / 32));
      }

      // Each gap beside the isolated one: A_nc/A_0 and the radius from the
      // share of the cell not in contact.
      void adhesionless_gaps(PennyGapSearch &search, const ResultFolder &results, std::ostream &log) const
      {
        Table table({{"p_bar/p*", Table::Format{4, false}},
                     {"A_nc/A_0", Table::digits},
                     {"(3/(2 pi))(1 - p_bar/p*)", Table::digits},
                     {"ratio", Table::Format{6, false}},
                     {"c/lambda BEM", Table::digits},
                     {"c/lambda FE", Table::digits},
                     {"BEM/FE - 1", Table::error_digits}});
        for (const auto &state :
             adhesive_bisinusoid::Model({0, 0, adhesionless_points}).loading(load_ratios, control))
          {
            const double isolated = adhesive_bisinusoid::isolated_noncontact_fraction(state.load_ratio);
            const double P = 1 - state.load_ratio, a = std::sqrt(2 * summit_radius * P);
            const double fe = fe_adhesionless_gap_radius(search.gaps, P, a, MPI_COMM_WORLD);
            table.add_row({state.load_ratio, state.noncontact_fraction, isolated,
                           state.noncontact_fraction / isolated, *state.gap_radius, fe,
                           *state.gap_radius / fe - 1});
          }
        publish(table, "bem-bisinusoid-adhesionless.csv", results, log,
                "The bi-sinusoid without adhesion: A_nc/A_0 against the isolated gaps' (3/(2 pi))(1 - "
                "p_bar/p*), and the gap's radius sqrt(area/pi) against the FE penny gap of its summit");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        // Peak resident size, one rank: 214 bytes a point more at 1824^2 than
        // at 928^2 with adhesion, 143 without (every rank solves the whole grid).
        check_grid_memory(std::max(adhesionless_points, grid_points(alphas.back(), zones.lengths.back())),
                          240,
                          "BEM bi-sinusoid/Cohesive zones l_pz/c_min = " + shortest(zones.lengths.back()) +
                              " with Points per cohesive zone = " + shortest(zones.points_per_zone) +
                              ", Johnson parameters alpha down to " + shortest(alphas.back()) +
                              " and Adhesionless grid = " + std::to_string(adhesionless_points),
                          MPI_COMM_WORLD);
        Progress       progress(log, "paths to closure", 0);
        PennyGapSearch search(gap, log);
        adhesionless_gaps(search, results, log);

        std::vector<Table::Column> closure_columns = {
            {"alpha", Table::Format{4, false}},
            {"isolated psi (2 pi)^(2/5) alpha^(4/5)", Table::digits},
            {"FE p0/p*", Table::digits}};
        std::vector<Table::Column> radius_columns = {{"alpha", Table::Format{4, false}},
                                                     {"P/p0", Table::Format{4, false}},
                                                     {"c/lambda closed form", Table::digits},
                                                     {"c/lambda FE", Table::digits}};
        for (const double zone : zones.lengths)
          for (auto *columns : {&closure_columns, &radius_columns})
            columns->push_back({"BEM l_pz/c_min=" + Table::label(zone), Table::digits});
        for (const std::string column : {"JKR limit", "error estimate", "ratio to isolated"})
          closure_columns.push_back(
              {column, column == "error estimate" ? Table::error_digits : Table::digits});
        for (const std::string column : {"JKR limit", "error estimate", "JKR limit/FE - 1"})
          radius_columns.push_back({column, column == "JKR limit" ? Table::digits : Table::error_digits});
        Table  closure(closure_columns), radii(radius_columns);
        Table  cost({{"alpha", Table::Format{4, false}},
                     {"l_pz/c_min", Table::Format{4, false}},
                     "points per side",
                     {"wall time (s)", Table::Format{3, false}}});
        double last_ratio = 0;
        for (const double alpha : alphas)
          {
            const double          isolated = adhesive_bisinusoid::isolated_closure_margin(alpha);
            const AdhesiveMinimum minimum =
                fe_adhesive_minimum(search.gaps, summit_radius, alpha, MPI_COMM_WORLD);
            std::vector<double> path;
            for (const double ratio : tension_ratios)
              path.push_back(1 - ratio * isolated);
            // states[state][zone]: the path's states, then the closure.
            std::vector<std::vector<adhesive_bisinusoid::State>> states(path.size() + 1);
            std::vector<double>                                  lengths;
            for (const double zone : zones.lengths)
              {
                dealii::Timer      timer;
                const double       l_pz = zone * closing_gap_radius(alpha);
                const unsigned int n    = grid_points(alpha, zone);
                const auto         on_path =
                    adhesive_bisinusoid::Model({alpha, l_pz, n}).loading(path, control, true);
                for (std::size_t k = 0; k < on_path.size(); ++k)
                  states[k].push_back(on_path[k]);
                lengths.push_back(l_pz);
                cost.add_row({alpha, zone, n, timer.wall_time()});
                progress.step("last alpha = " + Table::label(alpha) + ", l_pz/c_min = " + Table::label(zone) +
                              ", " + std::to_string(n) + "^2 points");
              }

            std::vector<double> margins;
            for (const auto &state : states.back())
              margins.push_back(1 - state.load_ratio);
            const Extrapolated       margin = jkr_limit(lengths, margins);
            std::vector<Table::Cell> row    = {alpha, isolated, minimum.tension};
            row.insert(row.end(), margins.begin(), margins.end());
            for (const double cell : {margin.value, margin.error, margin.value / isolated})
              row.emplace_back(cell);
            closure.add_row(row);
            last_ratio = margin.value / isolated;

            for (std::size_t k = 0; k < path.size(); ++k)
              {
                const double P = 1 - path[k];
                const auto   fe =
                    fe_stable_gap_radius(search.gaps, P, summit_radius, alpha, minimum, MPI_COMM_WORLD);
                // A gap closed at some zone, or in the FE model, is said to be.
                std::vector<double>      bem;
                std::vector<Table::Cell> radius_row = {alpha, tension_ratios[k],
                                                       *adhesive_bisinusoid::isolated_gap_radius(P, alpha),
                                                       fe ? Table::Cell(*fe) : Table::Cell("closed")};
                for (const auto &state : states[k])
                  {
                    radius_row.push_back(state.gap_radius ? Table::Cell(*state.gap_radius)
                                                          : Table::Cell("closed"));
                    if (state.gap_radius)
                      bem.push_back(*state.gap_radius);
                  }
                if (bem.size() == states[k].size())
                  {
                    const Extrapolated radius = jkr_limit(lengths, bem);
                    radius_row.insert(radius_row.end(), {radius.value, radius.error});
                    radius_row.push_back(fe ? Table::Cell(radius.value / *fe - 1)
                                            : Table::Cell("FE gap closed"));
                  }
                else
                  radius_row.insert(radius_row.end(), {"-", "-", "BEM gap closed"});
                radii.add_row(radius_row);
              }
          }
        publish(
            radii, "bem-bisinusoid-gaps.csv", results, log,
            "The bi-sinusoid with adhesion: the gap's radius sqrt(area/pi) (area where the gap exceeds "
            "the range rho) along the loading path at peak tensions P = p* - p_bar, at each cohesive zone "
            "and extrapolated to the JKR limit, against the closed-form and FE penny gap of its summit "
            "(stable branch, K_I = K_Ic)");
        publish(closure, "bem-bisinusoid-closure.csv", results, log,
                "The bi-sinusoid with adhesion: 1 - p_bar/p* where the gaps snap shut on loading, at each "
                "cohesive zone and extrapolated to the JKR limit, against the isolated penny gaps' "
                "psi (2 pi)^(2/5) alpha^(4/5) and the FE p0 of the summit");
        publish(cost, "bem-bisinusoid-cost.csv", results, log, "Loading paths to closure:");
        Table summary = Table::summary();
        search.add_cost(summary);
        publish(summary, "bem-bisinusoid-fe-cost.csv", results, log, "FE penny gaps of the summits:");
        return verdict(std::abs(last_ratio - 1));
      }

      PennyGapInput        gap;
      ContactSolverControl control;
      std::vector<double>  load_ratios, alphas, tension_ratios;
      CohesiveZones        zones; // l_pz/c_min
      unsigned int         adhesionless_points;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      BemBisinusoidScene, "bem-bisinusoid", "BEM bi-sinusoid",
      "the bi-sinusoid near full contact by the adhesive boundary-element solver: non-contact area, the "
      "gaps' "
      "radii and their closure load against the isolated penny gaps of its summits (closed form and FE)",
      "|closure load margin/(psi (2 pi)^(2/5) alpha^(4/5)) - 1| at the smallest alpha")
} // namespace penny
