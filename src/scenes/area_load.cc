// area-load: A_nc/A_0 and A_c/A_0 against p_bar/sqrt(V) for each H and zeta
// (paper Figs. 4 and 5): the linear law in closed form and by quadrature, the
// exact gap law, the adhesionless law and Persson's form.
#include "closed_forms/adhesive_gap.h"
#include "closed_forms/periodic_array.h"
#include "input/input_error.h"
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
    struct AreaLoadScene : Scene
    {
      void inputs(Sections &sections) override
      {
        // Each curve has its own H and zeta: of Roughness only q0 and h0/lambda0.
        rough_surface_sections(sections, surface, false);
        convention_entry(sections, surface.convention_is_paper);
        mean_pressure_entries(sections, mean_pressures);
        hurst_exponents_entry(sections, hurst_exponents);
        magnifications_entry(sections, magnifications, surface.convention_is_paper);
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        double worst = 0;
        Table  table({"H", "zeta", "p0/sqrtV", "p_bar/sqrtV", "A_nc linear closed form",
                      "A_nc linear integral", "A_nc exact g", "A_nc adhesionless", "A_c Persson-type",
                      "A_c Persson-type adhesionless", "A_nc linear > 1", "A_nc exact g > 1",
                      "A_nc adhesionless > 1"});
        Table  summary({"H", "zeta", "p0/sqrt(V)", "prefactor", "A_nc(p_bar = 0), linear law",
                        "A_nc(p_bar = 0), exact g"});
        for (const double hurst : hurst_exponents)
          for (const double zeta : magnifications)
            {
              const GapPopulation gaps  = surface.population(hurst, zeta);
              const std::string   curve = "Area-load/Hurst exponents = " + shortest(hurst) +
                                        " with Magnifications = " + shortest(zeta);
              // The closed forms' units hold p0/sqrt(V) in this range (zero-load-gap-area's).
              if (!(gaps.adhesion >= 1e-30 && gaps.adhesion <= 1e30 && std::isfinite(gaps.prefactor)))
                throw InputError(curve + " give p0/sqrt(V) = " + shortest(gaps.adhesion) +
                                 ", outside [1e-30, 1e30]" +
                                 (surface.convention_is_paper
                                      ? ""
                                      : " (the consistent convention's p0/sqrt(V) also follows Roughness q0 "
                                        "and h0/lambda0, the Material and the Adhesion)"));
              try
                {
                  const GapPopulation adhesionless{gaps.prefactor, 0};
                  const auto          exact = exact_gap_law(gaps.adhesion);
                  for (unsigned int i = 0; i < mean_pressures.n_points; ++i)
                    {
                      const double p_bar    = mean_pressures.at(i);
                      const double closed   = linear_law_noncontact_area(gaps, p_bar);
                      const double integral = noncontact_area(gaps, linear_gap_law(gaps.adhesion), p_bar);
                      worst                 = worse(worst, relative_error(integral, closed));
                      // At negative loads the isolated-gap laws exceed the whole area:
                      // flagged, they are no area fractions.
                      const double exact_area = noncontact_area(gaps, exact, p_bar);
                      const double without    = linear_law_noncontact_area(adhesionless, p_bar);
                      table.add_row({hurst, zeta, gaps.adhesion, p_bar, closed, integral, exact_area, without,
                                     persson_contact_area(gaps.adhesion, p_bar),
                                     persson_contact_area(0, p_bar), closed > 1, exact_area > 1,
                                     without > 1});
                    }
                  summary.add_row({hurst, zeta, gaps.adhesion, gaps.prefactor,
                                   linear_law_noncontact_area(gaps, 0), noncontact_area(gaps, exact, 0)});
                }
              catch (const std::runtime_error &error) // a closed form's root search out of its reach
                {
                  throw InputError(curve + ": " + error.what());
                }
            }
        results.write_csv("area-load.csv", table);
        log << "Area-load curves, A_nc/A_0 against p_bar/sqrt(V) from " << mean_pressures.smallest << " to "
            << mean_pressures.largest << " (paper Figs. 4 and 5)\n"
            << surface.convention_line() << '\n';
        summary.print(log);
        std::ostringstream error;
        error << std::scientific << std::setprecision(2) << worst;
        log << "largest |integral/closed form - 1|, linear law: " << error.str() << '\n'
            << "Table: " << results.directory().string() << "/area-load.csv\n";
        return {};
      }

      RoughSurfaceProblem surface;
      Sweep               mean_pressures; // p_bar/sqrt(V)
      std::vector<double> hurst_exponents, magnifications;
    };
  } // namespace

  PENNY_REGISTER_SCENE(AreaLoadScene, "area-load", "",
                       "A_nc/A_0 and A_c/A_0 against p_bar/sqrt(V) for each H and zeta (paper Figs. 4 and 5)",
                       "")
} // namespace penny
