// rough-surface: the moments of one rough surface's height PSD, the summits
// of its full-contact pressure and p0 in both conventions (the paper's and
// the consistent one), and its area-load curve in each.
#include "problems/rough_surface.h"
#include "closed_forms/adhesive_gap.h"
#include "closed_forms/periodic_array.h"
#include "numerics/relative_error.h"
#include "output/table.h"
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
    // The moments of the Roughness spectrum, and the solid and adhesion they meet.
    Table moments_table(const RoughSurfaceProblem &surface, const SpectralMoments &m)
    {
      const auto &roughness = surface.roughness;
      Table       moments   = Table::summary();
      moments.add_row({"spectrum", roughness.spectrum == RoughnessParameters::Spectrum::file
                                       ? "file " + roughness.spectrum_file
                                       : "power law H = " + Table::label(roughness.hurst) +
                                             ", zeta = " + Table::label(roughness.zeta)});
      moments.add_row({"m0 (m^2)", m.m0});
      moments.add_row({"m2", m.m2});
      moments.add_row({"m4 (1/m^2)", m.m4});
      moments.add_row({"m6 (1/m^4)", m.m6});
      moments.add_row({"E* (Pa)", surface.material.plane_strain_modulus()});
      moments.add_row({"K_Ic (Pa m^1/2)", surface.critical_stress_intensity});
      return moments;
    }

    // The pressure summits and the gaps they hold, in the paper's convention
    // (index 0) and the consistent one (1), side by side.
    Table conventions_table(const PressureSummits (&summits)[2], const GapPopulation (&gaps)[2])
    {
      Table      conventions({"quantity", "paper", "consistent", "consistent/paper"});
      const auto row = [&](const std::string &name, const double paper, const double consistent) {
        conventions.add_row({name, paper, consistent, consistent / paper});
      };
      row("V (Pa^2)", summits[0].variance, summits[1].variance);
      row("eta (1/m^2)", summits[0].density, summits[1].density);
      row("R_p (m^2/Pa)", summits[0].summit_radius, summits[1].summit_radius);
      row("p0 (Pa)", gaps[0].adhesion * std::sqrt(summits[0].variance),
          gaps[1].adhesion * std::sqrt(summits[1].variance));
      row("p0/sqrt(V)", gaps[0].adhesion, gaps[1].adhesion);
      row("3 pi R_p eta sqrt(V)",
          3 * M_PI * summits[0].summit_radius * summits[0].density * std::sqrt(summits[0].variance),
          gaps[1].prefactor);
      return conventions;
    }

    struct RoughSurfaceScene : Scene
    {
      void inputs(Sections &sections) override
      {
        rough_surface_sections(sections, surface);
        mean_pressure_entries(sections, mean_pressures);
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        const SpectralMoments m          = spectral_moments(power_spectrum(surface.roughness));
        const double          E_star     = surface.material.plane_strain_modulus();
        const double          K_Ic       = surface.critical_stress_intensity;
        const PressureSummits summits[2] = {pressure_summits(m, E_star, Convention::paper),
                                            pressure_summits(m, E_star, Convention::consistent)};
        const GapPopulation   gaps[2]    = {surface_population(summits[0], K_Ic, Convention::paper),
                                            surface_population(summits[1], K_Ic, Convention::consistent)};

        Table curve({"p_bar/sqrtV", "A_nc paper", "A_nc consistent", "A_nc paper exact g",
                     "A_nc consistent exact g"});
        for (unsigned int i = 0; i < mean_pressures.n_points; ++i)
          {
            const double p_bar = mean_pressures.at(i);
            curve.add_row({p_bar, linear_law_noncontact_area(gaps[0], p_bar),
                           linear_law_noncontact_area(gaps[1], p_bar),
                           noncontact_area(gaps[0], exact_gap_law(gaps[0].adhesion), p_bar),
                           noncontact_area(gaps[1], exact_gap_law(gaps[1].adhesion), p_bar)});
          }
        results.write_csv("rough-surface.csv", curve);

        publish(moments_table(surface, m), "rough-surface-moments.csv", results, log,
                "Rough surface: moments of the height PSD, the full-contact pressure summits and p0");
        log << '\n';
        publish(conventions_table(summits, gaps), "rough-surface-conventions.csv", results, log);
        log << "(the paper convention replaces its 3 pi R_p eta sqrt(V) by sqrt(2 pi) = "
            << std::sqrt(2 * M_PI) << ")\n"
            << "A_nc/A_0 at p_bar = " << mean_pressures.smallest << " sqrt(V), linear law: paper "
            << linear_law_noncontact_area(gaps[0], mean_pressures.smallest) << ", consistent "
            << linear_law_noncontact_area(gaps[1], mean_pressures.smallest) << '\n'
            << "Tables: " << results.directory().string()
            << "/rough-surface.csv (both conventions), rough-surface-moments.csv, "
               "rough-surface-conventions.csv\n";
        return {};
      }

      RoughSurfaceProblem surface;
      Sweep               mean_pressures; // p_bar/sqrt(V)
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      RoughSurfaceScene, "rough-surface", "",
      "moments, summit statistics and p0 of the Roughness spectrum in both conventions, and its area-load "
      "curve",
      "")
} // namespace penny
