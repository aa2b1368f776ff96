// zero-load-gap-area: the non-contact area at zero mean pressure against
// p0/sqrt(V) (paper Fig. 3), by the linear law in closed form and by
// quadrature, by the exact gap law, and Persson's contact area.
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
#include <sstream>

namespace penny
{
  namespace
  {
    struct ZeroLoadGapAreaScene : Scene
    {
      void inputs(Sections &sections) override
      {
        convention_entry(sections, convention_is_paper);
        power_law_shape_section(sections, roughness,
                                "Convention = consistent: the power law whose moments give the prefactor "
                                "3 pi R_p eta sqrt(V). ");
      }

      void entries(Entries &entries) override
      {
        // Below 1e-250 K_Ic of the closed forms' units underflows.
        entries.number(
            "Largest p0/sqrt(V)", largest_adhesion_ratio, 5,
            {"0 or [1e-30, 1e30]", [](const double x) { return x == 0 || (x >= 1e-30 && x <= 1e30); }},
            "p0/sqrt(V) runs from 0 to this value. Units: none.");
        entries.integer("Number of points", n_points, 61u, 2u, 100000u,
                        "Values of p0/sqrt(V), evenly spaced. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        // No scale enters the prefactor (so no Material or Adhesion either).
        const double prefactor =
            power_law_prefactor(roughness.hurst, roughness.zeta,
                                convention_is_paper ? Convention::paper : Convention::consistent);
        const double largest = largest_adhesion_ratio;
        double       worst   = 0;
        Table        table({"p0/sqrtV", "A_nc linear closed form", "A_nc linear integral", "A_nc exact g",
                            "A_c Persson-type"});
        const Sweep  adhesions{0, largest, n_points}; // p0/sqrt(V)
        for (unsigned int i = 0; i < adhesions.n_points; ++i)
          {
            const GapPopulation gaps{prefactor, adhesions.at(i)};
            const double        closed   = linear_law_noncontact_area(gaps, 0);
            const double        integral = noncontact_area(gaps, linear_gap_law(gaps.adhesion), 0);
            worst                        = worse(worst, relative_error(integral, closed));
            table.add_row({gaps.adhesion, closed, integral,
                           noncontact_area(gaps, exact_gap_law(gaps.adhesion), 0),
                           persson_contact_area(gaps.adhesion, 0)});
          }
        results.write_csv("zero-load-gap-area.csv", table);

        const GapPopulation last{prefactor, largest};
        Table               summary = Table::summary();
        summary.add_row({"prefactor 3 pi R_p eta sqrt(V)", prefactor});
        summary.add_row({"largest p0/sqrt(V)", last.adhesion});
        summary.add_row({"... A_nc/A_0, linear law", linear_law_noncontact_area(last, 0)});
        summary.add_row({"... A_nc/A_0, exact g", noncontact_area(last, exact_gap_law(last.adhesion), 0)});
        summary.add_row(
            {"largest |integral/closed form - 1|, linear law", Table::Cell(worst, Table::Format{2, true})});
        log << "Non-contact area at zero mean pressure against p0/sqrt(V) (paper Fig. 3)\n"
            << (convention_is_paper ? "convention: paper (3 pi R_p eta sqrt(V) = sqrt(2 pi))"
                                    : "convention: consistent (3 pi R_p eta sqrt(V) from the moments of the "
                                      "Roughness power law)")
            << '\n';
        summary.print(log);
        log << "Table: " << results.directory().string() << "/zero-load-gap-area.csv\n";
        return {};
      }

      bool                convention_is_paper;
      RoughnessParameters roughness;
      double              largest_adhesion_ratio;
      unsigned int        n_points;
    };
  } // namespace

  PENNY_REGISTER_SCENE(ZeroLoadGapAreaScene, "zero-load-gap-area", "Zero-load gap area",
                       "A_nc/A_0 at zero mean pressure against p0/sqrt(V) (paper Fig. 3)", "")
} // namespace penny
