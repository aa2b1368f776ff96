// westergaard-curve: the adhesionless sinusoid. At each mean pressure
// p_bar/p* = i/(n + 1) the contact half-width a is the FE root over the gap's
// half-width of K_I = 0, beside p_bar/p* = sin^2(pi a/lambda). PASS when
// |p_bar/p* - sin^2(pi a_FE/lambda)| is within Verification/Tolerance.
#include "closed_forms/periodic_array.h"
#include "numerics/relative_error.h"
#include "parallel/spread_over_ranks.h"
#include "problems/periodic_gap.h"
#include "scenes/scene.h"
#include "searches/periodic_searches.h"

#include <algorithm>
#include <cmath>

namespace penny
{
  namespace
  {
    struct WestergaardCurveScene : Scene
    {
      void inputs(Sections &sections) override { periodic.sections(sections); }

      void entries(Entries &entries) override
      {
        entries.integer(
            "Number of points", n_points, 8u, 1u, 1000u,
            "Mean pressures p_bar/p* = i/(n + 1), i = 1 ... n; each is one FE root search over the "
            "contact half-width. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PeriodicGapSearch search(periodic);
        const double      lambda = periodic.model.wavelength;
        Table             table({{"p_bar/p*", Table::digits},
                                 {"a/lambda FE", Table::all_digits},
                                 {"a/lambda exact", Table::all_digits},
                                 {"a/lambda error", Table::error_digits},
                                 {"sin^2(pi a_FE/lambda)", Table::all_digits},
                                 {"p_bar/p* error", Table::error_digits}});
        double            worst_load = 0, worst_contact = 0;
        const auto        load_at = [&](const unsigned int i) { return (i + 1.) / (n_points + 1); };
        const auto contact = spread_over_ranks<double>(MPI_COMM_WORLD, n_points, [&](const unsigned int i) {
          return fe_westergaard_contact_half_width(search.gaps, load_at(i), MPI_COMM_SELF);
        });
        for (unsigned int i = 0; i < n_points; ++i)
          {
            const double load     = load_at(i);
            const double fe_ratio = contact[i] / lambda;
            const double exact    = periodic_array::westergaard_contact_ratio(load);
            const double curve    = periodic_array::johnson_load(fe_ratio, 0);
            worst_load            = worse(worst_load, std::abs(curve - load));
            worst_contact         = worse(worst_contact, std::abs(fe_ratio - exact));
            table.add_row({load, fe_ratio, exact, std::abs(fe_ratio - exact), curve, std::abs(curve - load)});
          }
        publish(table, "westergaard-curve.csv", results, log,
                "Adhesionless sinusoid: contact half-width a from FE roots of K_I = 0, beside p_bar/p* = "
                "sin^2(pi a/lambda)");
        Table summary = Table::summary();
        summary.add_row({"largest |a/lambda FE - exact|", Table::Cell(worst_contact, Table::error_digits)});
        summary.add_row(
            {"largest |p_bar/p* - sin^2(pi a_FE/lambda)|", Table::Cell(worst_load, Table::error_digits)});
        search.add_cost(summary);
        publish(summary, "westergaard-summary.csv", results, log);
        return verdict(worst_load);
      }

      PeriodicGapInput periodic;
      unsigned int     n_points;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      WestergaardCurveScene, "westergaard-curve", "Westergaard curve",
      "the adhesionless sinusoid: contact half-width a from FE roots of K_I = 0 beside p_bar/p* = sin^2(pi "
      "a/lambda)",
      "largest |p_bar/p* - sin^2(pi a_FE/lambda)|")
} // namespace penny
