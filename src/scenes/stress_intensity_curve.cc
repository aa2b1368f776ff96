// stress-intensity-curve: K_I of the Bueckner parabola P (1 - r^2/a^2) on a
// gap of radius c, against c/a, from FE solves of the two unit loads beside
// the paper's K_I = 2 P sqrt(c/pi) [1 - (2/3) c^2/a^2]. K_I changes sign at
// c/a = sqrt(3/2), so the error is scaled by the uniform-pressure K_I,
// 2 P sqrt(c/pi); PASS when its largest value is within
// Verification/Tolerance.
#include "closed_forms/sneddon_solution.h"
#include "numerics/relative_error.h"
#include "output/table.h"
#include "problems/penny_gap.h"
#include "scenes/scene.h"

#include <cmath>

namespace penny
{
  namespace
  {
    struct StressIntensityCurveScene : Scene
    {
      void inputs(Sections &sections) override
      {
        gap.sections(sections);
        parabola_section(sections, load);
      }

      void entries(Entries &entries) override
      {
        entries.sweep("c/a", "Number of points", ratios, {0.1, 1.5, 15}, 1, 1000, interval("(]", 0, 10),
                      "The gap radii of the curve, in units of the parabola's a.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PennyGapSearch      search(gap, log);
        const double        a = load.tension_radius, P = load.peak_tension;
        std::vector<double> radii;
        for (unsigned int i = 0; i < ratios.n_points; ++i)
          radii.push_back(a * ratios.at(i));
        const auto sifs = search.gaps.unit_load_sifs(radii, MPI_COMM_WORLD);

        Table  curve({{"c/a", Table::Format{6, false}},
                      {"K_I FE (Pa m^1/2)", Table::digits},
                      {"K_I closed form (Pa m^1/2)", Table::digits},
                      {"error/(2 P sqrt(c/pi))", Table::error_digits}});
        double worst = 0;
        for (unsigned int i = 0; i < radii.size(); ++i)
          {
            const double c  = radii[i];
            const double fe = P * sifs[i].uniform - P / (a * a) * sifs[i].quadratic;
            const double exact =
                SneddonSolution(FaceLoad(load, c), c, gap.model.material.plane_strain_modulus())
                    .stress_intensity_factor()
                    .value;
            const double error = std::abs(fe - exact) / (2 * P * std::sqrt(c / M_PI));
            worst              = worse(worst, error);
            curve.add_row({c / a, fe, exact, error});
          }
        publish(curve, "stress-intensity-curve.csv", results, log,
                "K_I of the parabola P (1 - r^2/a^2) against c/a (zero at sqrt(3/2) = 1.2247)");
        Table summary = Table::summary();
        summary.add_row({"largest error/(2 P sqrt(c/pi))", Table::Cell(worst, Table::error_digits)});
        search.add_cost(summary);
        publish(summary, "summary.csv", results, log);
        return verdict(worst);
      }

      PennyGapInput  gap;
      LoadParameters load;
      Sweep          ratios; // c/a
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      StressIntensityCurveScene, "stress-intensity-curve", "Stress intensity curve",
      "K_I of the Bueckner parabola against c/a from FE beside 2 P sqrt(c/pi) [1 - (2/3) c^2/a^2]",
      "largest |K_I FE - closed form|/(2 P sqrt(c/pi))")
} // namespace penny
