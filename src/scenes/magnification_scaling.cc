// magnification-scaling: theta of p0/sqrt(V) ~ zeta^theta fitted from the
// spectral moments for each H, in both conventions, beside the paper's
// (2/5)(2H - 1).
#include "closed_forms/adhesive_gap.h"
#include "closed_forms/periodic_array.h"
#include "numerics/relative_error.h"
#include "output/table.h"
#include "problems/rough_surface.h"
#include "scenes/scene.h"
#include "statistics/contact_area.h"
#include "statistics/roughness.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace penny
{
  namespace
  {
    struct MagnificationScalingScene : Scene
    {
      void inputs(Sections &sections) override { hurst_exponents_entry(sections, hurst_exponents); }

      void entries(Entries &entries) override
      {
        // Beyond 1e30 the spectral moments leave the range of a double.
        entries.increasing_numbers("Fit magnifications", fit, {1e12, 1e16}, 2, interval("(]", 1, 1e30),
                                   "The zeta range of the least-squares fit of theta: two numbers. Units: "
                                   "none.");
        if (!entries.reading())
          return;
        entries.require(fit.size() == 2, "Fit magnifications", fit.back(), "two numbers, no more");
        // A log-log fit over less than a decade measures the rounding of the
        // moments (1 + 1e-10 to 1 + 2e-10 gave theta = -2.7e9).
        entries.require(fit[1] >= 10 * fit[0], "Fit magnifications", fit[1],
                        "[10 x first = " + Table::label(10 * fit[0], 3) + ", 1e30]: a decade or more");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        double worst = 0;
        Table  table({"H",
                      "theta (2/5)(2H-1)",
                      "theta fit paper",
                      "theta fit consistent",
                      {"largest |fit - theta|", Table::Format{2, true}}});
        for (const double hurst : hurst_exponents)
          {
            const double theta = scaling_exponent(hurst);
            double       fits[2];
            for (const Convention convention : {Convention::paper, Convention::consistent})
              fits[convention == Convention::consistent] =
                  fitted_scaling_exponent(hurst, fit[0], fit[1], 41, convention);
            const double error = worse(std::abs(fits[0] - theta), std::abs(fits[1] - theta));
            worst              = worse(worst, error);
            table.add_row({hurst, theta, fits[0], fits[1], error});
          }
        log << "Magnification exponent: p0/sqrt(V) ~ zeta^theta, least-squares fit of the moments' values "
               "over zeta in ["
            << fit[0] << ", " << fit[1] << "]\n";
        publish(table, "magnification-scaling.csv", results, log);
        log << "Table: " << results.directory().string() << "/magnification-scaling.csv\n";
        return {};
      }

      std::vector<double> hurst_exponents, fit;
    };
  } // namespace

  PENNY_REGISTER_SCENE(MagnificationScalingScene, "magnification-scaling", "Magnification scaling",
                       "theta of p0/sqrt(V) ~ zeta^theta fitted from the moments, for each H", "")
} // namespace penny
