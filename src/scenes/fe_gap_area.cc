// fe-gap-area: the area-load curve with the FE gap function g: the FE gap
// radius on the stable branch at Chebyshev points of t, P = p0 + t^2 sqrt(V),
// interpolated in t and summed over the summits; the closed-form g goes
// through the same table (to show the interpolation error alone) and through
// the exact law. PASS when the area-load curves of the FE and the closed-form
// g agree within Verification/Tolerance.
#include "closed_forms/adhesive_gap.h"
#include "numerics/relative_error.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "problems/penny_gap.h"
#include "problems/rough_surface.h"
#include "problems/solid.h"
#include "scenes/scene.h"
#include "searches/gap_searches.h"
#include "statistics/contact_area.h"

#include <cmath>

namespace penny
{
  namespace
  {
    struct FeGapAreaScene : Scene
    {
      void inputs(Sections &sections) override
      {
        input.sections(sections);
        mean_pressure_entries(sections, mean_pressures);
      }

      void entries(Entries &entries) override
      {
        entries.number(
            "p0/sqrt(V)", adhesion_ratio, 1, above(0),
            "Adhesion of the gap population; sqrt(V) = p0/this, with p0 from Load/Summit radius R_p and "
            "the Adhesion section. Units: none.");
        entries.integer(
            "Tabulated tensions", n_tabulated_tensions, 20u, 3u, 200u,
            "FE gap radii at this many peak tensions P = p0 + t^2 sqrt(V), Chebyshev points in t. Units: "
            "none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PennyGapSearch search(input.gap, log);
        const double   adhesion = adhesion_ratio;
        const double   R_p      = input.summit.summit_radius;
        const double   K_Ic     = input.summit.critical_stress_intensity;
        const double   p0       = closed_form::psi * adhesion_tension(R_p, K_Ic);
        const double   sqrt_V   = p0 / adhesion;
        const auto     minimum  = fe_adhesive_minimum(search.gaps, R_p, K_Ic, MPI_COMM_WORLD);

        const GapPopulation exact_gaps{std::sqrt(2 * M_PI), adhesion};
        const GapPopulation fe_gaps{exact_gaps.prefactor, minimum.tension / sqrt_V};
        const unsigned int  n_tensions = n_tabulated_tensions;
        const double        t_max   = std::max(integration_limit(fe_gaps.adhesion, mean_pressures.smallest),
                                               integration_limit(exact_gaps.adhesion, mean_pressures.smallest));
        const auto          fe_P    = chebyshev_tensions(fe_gaps.adhesion, t_max, n_tensions);
        const auto          exact_P = chebyshev_tensions(exact_gaps.adhesion, t_max, n_tensions);
        const auto          exact   = exact_gap_law(exact_gaps.adhesion);
        std::vector<double> fe_areas, exact_areas;
        Table               gap_table({"P/sqrtV", "c_t FE (m)", "c_t closed form (m)", "relative error"});
        // P = p0 + t^2 sqrt(V): exactly the FE p0 at t = 0, whose gap is the minimum's.
        const auto tension = [&](const unsigned int j) {
          return minimum.tension + (fe_P[j] - fe_gaps.adhesion) * sqrt_V;
        };
        const auto radii = spread_over_ranks<double>(MPI_COMM_WORLD, fe_P.size(), [&](const unsigned int j) {
          return *fe_stable_gap_radius(search.gaps, tension(j), R_p, K_Ic, minimum, MPI_COMM_SELF);
        });
        double     worst_radius = 0;
        for (unsigned int j = 0; j < fe_P.size(); ++j)
          {
            const double P  = tension(j);
            const double c  = radii[j];
            const double c0 = *closed_form::stable_gap_radius(std::max(P, p0), R_p, K_Ic);
            fe_areas.push_back(c * c / (3 * R_p * sqrt_V));
            exact_areas.push_back(exact(exact_P[j]));
            worst_radius = worse(worst_radius, relative_error(c, c0));
            gap_table.add_row({fe_P[j], c, c0, relative_error(c, c0)});
          }
        const auto fe_law      = tabulated_gap_law(fe_gaps.adhesion, t_max, fe_areas);
        const auto exact_table = tabulated_gap_law(exact_gaps.adhesion, t_max, exact_areas);

        double worst = 0, worst_table = 0;
        Table  table({"p_bar/sqrtV", "A_nc FE g", "A_nc closed-form g", "A_nc closed-form g tabulated",
                      "relative difference"});
        for (unsigned int i = 0; i < mean_pressures.n_points; ++i)
          {
            const double p_bar     = mean_pressures.at(i);
            const double fe        = noncontact_area(fe_gaps, fe_law, p_bar);
            const double reference = noncontact_area(exact_gaps, exact, p_bar);
            const double tabulated = noncontact_area(exact_gaps, exact_table, p_bar);
            worst                  = worse(worst, relative_error(fe, reference));
            worst_table            = worse(worst_table, relative_error(tabulated, reference));
            table.add_row({p_bar, fe, reference, tabulated, relative_error(fe, reference)});
          }
        results.write_csv("fe-gap-table.csv", gap_table);
        results.write_csv("fe-gap-area.csv", table);

        const Table::Format error_digits{2, true};
        Table               summary = Table::summary();
        summary.add_row({"p0/sqrt(V)", adhesion});
        summary.add_row({"tabulated peak tensions", n_tensions});
        summary.add_row({"smallest P/sqrt(V)", fe_P.front()});
        summary.add_row({"largest P/sqrt(V)", fe_P.back()});
        summary.add_row({"largest |c_t FE/c_t closed form - 1|", Table::Cell(worst_radius, error_digits)});
        summary.add_row({"largest |A_nc(FE g)/A_nc(closed-form g) - 1|", Table::Cell(worst, error_digits)});
        summary.add_row({"... of the table alone (closed-form g)", Table::Cell(worst_table, error_digits)});
        search.add_cost(summary);
        log << "Area-load curve with the FE gap function g (stable branch of K_I = K_Ic)\n"
            << "convention: paper prefactor sqrt(2 pi) (the comparison is a ratio, free of the prefactor)\n";
        summary.print(log);
        log << "Tables: " << results.directory().string() << "/fe-gap-area.csv, fe-gap-table.csv\n";
        return verdict(worst);
      }

      AdhesiveGapInput input;
      Sweep            mean_pressures; // p_bar/sqrt(V)
      double           adhesion_ratio;
      unsigned int     n_tabulated_tensions;
    };
  } // namespace

  PENNY_REGISTER_SCENE(FeGapAreaScene, "fe-gap-area", "FE gap area",
                       "the area-load curve with the FE gap function g beside the closed-form g's",
                       "largest |A_nc(FE g)/A_nc(closed-form g) - 1|")
} // namespace penny
