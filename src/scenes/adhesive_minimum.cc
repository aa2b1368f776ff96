// adhesive-minimum: the minimum over c of the FE peak tension P(c) that holds
// a gap at K_I = K_Ic, from FE solves alone: psi and c_min. PASS when psi lies
// within Verification/Tolerance of the closed form; c_min, the place of a
// minimum, carries the square root of the FE error and is reported, not judged.
#include "closed_forms/adhesive_gap.h"
#include "numerics/relative_error.h"
#include "problems/penny_gap.h"
#include "problems/solid.h"
#include "scenes/scene.h"
#include "searches/gap_searches.h"

namespace penny
{
  namespace
  {
    struct AdhesiveMinimumScene : Scene
    {
      void inputs(Sections &sections) override { input.sections(sections); }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PennyGapSearch        search(input.gap, log);
        const double          R_p     = input.summit.summit_radius;
        const double          K_Ic    = input.summit.critical_stress_intensity;
        const AdhesiveMinimum minimum = fe_adhesive_minimum(search.gaps, R_p, K_Ic, MPI_COMM_WORLD);
        const double          psi     = minimum.tension / adhesion_tension(R_p, K_Ic);
        const double          c_hat   = minimum.gap_radius / adhesion_length(R_p, K_Ic);

        Table summary = Table::summary();
        summary.add_row({"p0 FE (Pa)", Table::Cell(minimum.tension, Table::all_digits)});
        summary.add_row({"c_min FE (m)", Table::Cell(minimum.gap_radius, Table::all_digits)});
        summary.add_row({"psi FE", Table::Cell(psi, Table::all_digits)});
        summary.add_row({"psi exact", Table::Cell(closed_form::psi, Table::all_digits)});
        summary.add_row({"c_min/(R_p K_Ic)^(2/5) FE", Table::Cell(c_hat, Table::all_digits)});
        summary.add_row(
            {"c_min/(R_p K_Ic)^(2/5) exact", Table::Cell(closed_form::c_min_factor, Table::all_digits)});
        summary.add_row(
            {"psi relative error", Table::Cell(relative_error(psi, closed_form::psi), Table::error_digits)});
        summary.add_row({"c_min relative error",
                         Table::Cell(relative_error(c_hat, closed_form::c_min_factor), Table::error_digits)});
        search.add_cost(summary);
        publish(summary, "adhesive-minimum.csv", results, log,
                "Adhesive minimum: min over c of P(c) = [K_Ic + K_2(c)/(2 R_p)] / K_1(c), FE");
        return verdict(relative_error(psi, closed_form::psi));
      }

      AdhesiveGapInput input;
    };
  } // namespace

  PENNY_REGISTER_SCENE(AdhesiveMinimumScene, "adhesive-minimum", "",
                       "the minimum over c of the FE peak tension P(c) at K_I = K_Ic: psi and c_min",
                       "relative error of psi")
} // namespace penny
