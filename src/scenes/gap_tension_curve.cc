// gap-tension-curve: p_hat = P/p0 against c_hat = c/c_min from FE (paper
// Fig. 2), beside (c_hat^2 + 4/sqrt(c_hat))/5 and the paper's linear law. P
// and c are normalised by the closed-form p0 and c_min so that FE and closed
// form share one axis. PASS when every p_hat lies within
// Verification/Tolerance of the closed form.
#include "closed_forms/adhesive_gap.h"
#include "numerics/relative_error.h"
#include "problems/penny_gap.h"
#include "problems/solid.h"
#include "scenes/scene.h"

#include <cmath>

namespace penny
{
  namespace
  {
    struct GapTensionCurveScene : Scene
    {
      void inputs(Sections &sections) override { input.sections(sections); }

      void entries(Entries &entries) override
      {
        entries.sweep("c_hat", "Number of points", c_hats, {0.3, 4, 24}, 2, 1000, above(0),
                      "The range of the curve, c/c_min. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PennyGapSearch search(input.gap, log);
        const double   R_p   = input.summit.summit_radius;
        const double   K_Ic  = input.summit.critical_stress_intensity;
        const double   c_min = closed_form::c_min_factor * adhesion_length(R_p, K_Ic);
        const double   p0    = closed_form::psi * adhesion_tension(R_p, K_Ic);

        const Table::Format digits{12, false};
        Table               table({{"c_hat", digits},
                                   {"p_hat FE", digits},
                                   {"p_hat exact", digits},
                                   {"p_hat linear", digits},
                                   {"relative error", digits}});
        std::vector<double> radii;
        for (unsigned int i = 0; i < c_hats.n_points; ++i)
          radii.push_back(c_hats.at(i) * c_min);
        const std::vector<PennyUnitSifs> sifs  = search.gaps.unit_load_sifs(radii, MPI_COMM_WORLD);
        double                           worst = 0;
        for (unsigned int i = 0; i < c_hats.n_points; ++i)
          {
            const double        c_hat  = c_hats.at(i);
            const PennyUnitSifs K      = sifs[i];
            const double        p_fe   = (K_Ic + K.quadratic / (2 * R_p)) / K.uniform / p0;
            const double        exact  = (c_hat * c_hat + 4 / std::sqrt(c_hat)) / 5;
            const double        linear = c_hat * c_hat > 2.5 ? c_hat * c_hat / 5 + 0.5 : 1.;
            worst                      = worse(worst, relative_error(p_fe, exact));
            table.add_row({c_hat, p_fe, exact, linear, relative_error(p_fe, exact)});
          }
        publish(table, "gap-tension-curve.csv", results, log);
        Table summary = Table::summary();
        summary.add_row({"largest relative error", Table::Cell(worst, Table::error_digits)});
        search.add_cost(summary);
        summary.print(log);
        return verdict(worst);
      }

      AdhesiveGapInput input;
      Sweep            c_hats;
    };
  } // namespace

  PENNY_REGISTER_SCENE(GapTensionCurveScene, "gap-tension-curve", "Gap-tension curve",
                       "p_hat(c_hat) from FE beside (c_hat^2 + 4/sqrt(c_hat))/5 (paper Fig. 2)",
                       "largest relative error of p_hat")
} // namespace penny
