// adhesive-equilibrium: the FE gap radius on the stable branch (K_I = K_Ic,
// c >= c_min) for the peak tension P: the paper's g, from FE solves alone.
// PASS when FE and closed form agree on whether the gap closes and, if it is
// open, on its radius within Verification/Tolerance.
#include "closed_forms/adhesive_gap.h"
#include "input/input_error.h"
#include "numerics/relative_error.h"
#include "problems/penny_gap.h"
#include "problems/solid.h"
#include "scenes/scene.h"
#include "searches/gap_searches.h"

#include <cmath>

namespace penny
{
  namespace
  {
    struct AdhesiveEquilibriumScene : Scene
    {
      void inputs(Sections &sections) override
      {
        input.sections(sections, &peak_tension);
        // The stable gap's search widens its bracket from c_min to at most
        // 2^21 c_min: a tension whose gap lies beyond is refused.
        sections.check([&] {
          const double R_p = input.summit.summit_radius, K_Ic = input.summit.critical_stress_intensity;
          const double largest = closed_form::adhesive_tension(
              std::pow(2., 20) * closed_form::c_min_factor * adhesion_length(R_p, K_Ic), R_p, K_Ic);
          const double shown =
              std::pow(10., std::floor(std::log10(largest)) - 2); // three digits, rounded down
          require(peak_tension <= largest, "Load/Peak tension P", peak_tension,
                  "[-1e30, " + shortest(std::floor(largest / shown) * shown) +
                      "] Pa for this Summit radius R_p and Critical stress intensity K_Ic (the stable gap "
                      "radius would exceed 2^20 c_min)");
        });
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PennyGapSearch search(input.gap, log);
        const double   P = peak_tension, R_p = input.summit.summit_radius,
                     K_Ic             = input.summit.critical_stress_intensity;
        const AdhesiveMinimum minimum = fe_adhesive_minimum(search.gaps, R_p, K_Ic, MPI_COMM_WORLD);
        const auto            c_t = fe_stable_gap_radius(search.gaps, P, R_p, K_Ic, minimum, MPI_COMM_WORLD);
        const auto            exact = closed_form::stable_gap_radius(P, R_p, K_Ic);

        Table summary = Table::summary();
        summary.add_row({"peak tension P (Pa)", Table::Cell(P, Table::all_digits)});
        summary.add_row({"p0 FE (Pa)", Table::Cell(minimum.tension, Table::all_digits)});
        if (c_t)
          {
            summary.add_row({"gap radius c_t FE (m)", Table::Cell(*c_t, Table::all_digits)});
            summary.add_row({"c_t closed form (m)", Table::Cell(*exact, Table::all_digits)});
            summary.add_row(
                {"relative error", Table::Cell(relative_error(*c_t, *exact), Table::error_digits)});
          }
        else
          summary.add_row({"gap", "closed: P < p0, no gap survives (full contact)"});
        search.add_cost(summary);
        publish(summary, "adhesive-equilibrium.csv", results, log,
                "Adhesive equilibrium on the stable branch (K_I = K_Ic, c >= c_min), FE");

        if (c_t.has_value() != exact.has_value())
          return {false, std::string("FE and closed form disagree on whether the gap closes (FE: ") +
                             (c_t ? "open" : "closed") + ")"};
        if (!c_t)
          return {true, "FE and closed form agree: the gap closes"};
        return verdict(relative_error(*c_t, *exact));
      }

      AdhesiveGapInput input;
      double           peak_tension;
    };
  } // namespace

  PENNY_REGISTER_SCENE(AdhesiveEquilibriumScene, "adhesive-equilibrium", "",
                       "the FE gap radius on the stable branch for the peak tension P (the paper's g)",
                       "relative error of the gap radius c_t")
} // namespace penny
