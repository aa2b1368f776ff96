// gap-size-adhesionless: the gap radius at which the FE K_I of the parabola
// P (1 - r^2/a^2) vanishes, a root over c of FE solves alone; PASS when c/a
// lies within Verification/Tolerance of sqrt(3/2).
#include "closed_forms/adhesive_gap.h"
#include "numerics/relative_error.h"
#include "problems/penny_gap.h"
#include "scenes/scene.h"
#include "searches/gap_searches.h"

namespace penny
{
  namespace
  {
    struct GapSizeScene : Scene
    {
      void inputs(Sections &sections) override
      {
        gap.sections(sections);
        parabola_section(sections, load);
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PennyGapSearch search(gap, log);
        const double   a = load.tension_radius;
        const double   c = fe_adhesionless_gap_radius(search.gaps, load.peak_tension, a, MPI_COMM_WORLD);

        const double error   = relative_error(c / a, closed_form::adhesionless_c_over_a);
        Table        summary = Table::summary();
        summary.add_row({"c/a FE", Table::Cell(c / a, Table::all_digits)});
        summary.add_row(
            {"c/a exact, sqrt(3/2)", Table::Cell(closed_form::adhesionless_c_over_a, Table::all_digits)});
        summary.add_row({"relative error", Table::Cell(error, Table::error_digits)});
        search.add_cost(summary);
        publish(summary, "gap-size.csv", results, log,
                "Adhesionless gap size: FE K_I(c) = 0 for the parabola P (1 - r^2/a^2)");
        return verdict(error);
      }

      PennyGapInput  gap;
      LoadParameters load;
    };
  } // namespace

  PENNY_REGISTER_SCENE(GapSizeScene, "gap-size-adhesionless", "",
                       "the gap radius where the FE K_I of the parabola (P, a) vanishes: c/a = sqrt(3/2)",
                       "relative error of c/a")
} // namespace penny
