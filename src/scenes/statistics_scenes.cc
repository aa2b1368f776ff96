#include "scenes/statistics_scenes.h"

#include "fracture/adhesive_gap.h"
#include "fracture/periodic_array.h"
#include "output/table.h"
#include "scenes/scene_support.h"
#include "statistics/contact_area.h"
#include "statistics/roughness.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace penny
{
  namespace
  {
    const Table::Format error_digits{2, true};

    // The gaps of the power-law surface (H, zeta): the paper's normalised
    // population, or the consistent one from the moments of the Roughness
    // spectrum with this H and zeta.
    GapPopulation population(const Parameters &parameters, const double hurst, const double zeta)
    {
      if (parameters.area_load->convention_is_paper)
        return paper_population(hurst, zeta);
      const auto &roughness = *parameters.roughness;
      const auto  moments =
          spectral_moments(power_law_spectrum(hurst, roughness.q0, zeta, roughness.amplitude));
      return surface_population(
          pressure_summits(moments, parameters.material->plane_strain_modulus(), Convention::consistent),
          parameters.adhesion->critical_stress_intensity, Convention::consistent);
    }

    std::string convention_line(const Parameters &parameters)
    {
      return parameters.area_load->convention_is_paper
                 ? "convention: paper (3 pi R_p eta sqrt(V) = sqrt(2 pi), p0/sqrt(V) = zeta^theta)"
                 : "convention: consistent (V, eta, R_p and p0 from the moments of the Roughness power law)";
    }

    // A number as a column name shows it: 0.2, 1e+16.
    std::string name_of(const double value)
    {
      std::ostringstream text;
      text << value;
      return text.str();
    }
  } // namespace

  void run_sinusoid_contact_scene(const Parameters &parameters, const ResultFolder &results,
                                  std::ostream &log)
  {
    const auto                &sinusoid = *parameters.sinusoid;
    std::vector<Table::Column> columns  = {{"a/lambda"}};
    for (const double alpha : sinusoid.alphas)
      columns.push_back({"p/p* alpha=" + name_of(alpha)});
    Table table(columns);
    for (unsigned int i = 1; i <= sinusoid.n_points; ++i)
      {
        const double             ratio = 0.5 * i / (sinusoid.n_points + 1);
        std::vector<Table::Cell> row   = {ratio};
        for (const double alpha : sinusoid.alphas)
          row.emplace_back(periodic_array::johnson_load(ratio, alpha));
        table.add_row(row);
      }
    results.write_csv("sinusoid-contact.csv", table);

    // The jump into full contact is the curve's maximum inside (0, 1/2), or
    // its end a -> lambda/2 without adhesion; beyond (25/16) (3/5)^(3/4) the
    // curve has none.
    Table jumps({{"alpha"}, {"jump into full contact at p/p*"}, {"a/lambda"}});
    for (const double alpha : sinusoid.alphas)
      if (alpha < periodic_array::largest_alpha_with_extremes())
        {
          const auto jump = periodic_array::jump_into_contact(alpha);
          jumps.add_row({alpha, jump.load_ratio, jump.contact_ratio});
        }
      else
        jumps.add_row({alpha, "none: p/p* falls monotonically", ""});
    log << "Johnson's adhesive 1D sinusoid: p/p* = sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda))\n";
    jumps.print(log);
    log << "Table: " << results.directory().string() << "/sinusoid-contact.csv\n";
  }

  double run_zero_load_gap_area_scene(const Parameters &parameters, const ResultFolder &results,
                                      std::ostream &log)
  {
    const auto  &range   = *parameters.area_load;
    const double largest = parameters.zero_load_gap_area->largest_adhesion_ratio;
    const auto   surface = population(parameters, parameters.roughness->hurst, parameters.roughness->zeta);
    double       worst   = 0;
    Table        table({{"p0/sqrtV"},
                        {"A_nc linear closed form"},
                        {"A_nc linear integral"},
                        {"A_nc exact g"},
                        {"A_c Persson-type"}});
    for (unsigned int i = 0; i < range.n_points; ++i)
      {
        const GapPopulation gaps{surface.prefactor, largest * i / (range.n_points - 1)};
        const double        closed   = linear_law_noncontact_area(gaps, 0);
        const double        integral = noncontact_area(gaps, linear_gap_law(gaps.adhesion), 0);
        worst                        = std::max(worst, relative_error(integral, closed));
        table.add_row({gaps.adhesion, closed, integral,
                       noncontact_area(gaps, exact_gap_law(gaps.adhesion), 0),
                       persson_contact_area(gaps.adhesion, 0)});
      }
    results.write_csv("zero-load-gap-area.csv", table);

    const GapPopulation last{surface.prefactor, largest};
    Table               summary = Table::summary();
    summary.add_row({"prefactor 3 pi R_p eta sqrt(V)", surface.prefactor});
    summary.add_row({"largest p0/sqrt(V)", last.adhesion});
    summary.add_row({"... A_nc/A_0, linear law", linear_law_noncontact_area(last, 0)});
    summary.add_row({"... A_nc/A_0, exact g", noncontact_area(last, exact_gap_law(last.adhesion), 0)});
    summary.add_row({"largest |integral/closed form - 1|, linear law", Table::Cell(worst, error_digits)});
    log << "Non-contact area at zero mean pressure against p0/sqrt(V) (paper Fig. 3)\n"
        << convention_line(parameters) << '\n';
    summary.print(log);
    log << "Table: " << results.directory().string() << "/zero-load-gap-area.csv\n";
    return worst;
  }

  double run_area_load_scene(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
  {
    const auto &range = *parameters.area_load;
    double      worst = 0;
    Table       table({{"H"},
                       {"zeta"},
                       {"p0/sqrtV"},
                       {"p_bar/sqrtV"},
                       {"A_nc linear closed form"},
                       {"A_nc linear integral"},
                       {"A_nc exact g"},
                       {"A_nc adhesionless"},
                       {"A_c Persson-type"},
                       {"A_c Persson-type adhesionless"},
                       {"A_nc linear > 1"},
                       {"A_nc exact g > 1"}});
    Table       summary({{"H"},
                         {"zeta"},
                         {"p0/sqrt(V)"},
                         {"prefactor"},
                         {"A_nc(p_bar = 0), linear law"},
                         {"A_nc(p_bar = 0), exact g"}});
    for (const double hurst : range.hurst_exponents)
      for (const double zeta : range.magnifications)
        {
          const GapPopulation gaps = population(parameters, hurst, zeta);
          const GapPopulation adhesionless{gaps.prefactor, 0};
          const auto          exact = exact_gap_law(gaps.adhesion);
          for (unsigned int i = 0; i < range.n_points; ++i)
            {
              const double p_bar    = range.mean_pressure(i);
              const double closed   = linear_law_noncontact_area(gaps, p_bar);
              const double integral = noncontact_area(gaps, linear_gap_law(gaps.adhesion), p_bar);
              worst                 = std::max(worst, relative_error(integral, closed));
              // At negative loads the isolated-gap laws exceed the whole area:
              // flagged, they are no area fractions.
              const double exact_area = noncontact_area(gaps, exact, p_bar);
              table.add_row({hurst, zeta, gaps.adhesion, p_bar, closed, integral, exact_area,
                             linear_law_noncontact_area(adhesionless, p_bar),
                             persson_contact_area(gaps.adhesion, p_bar), persson_contact_area(0, p_bar),
                             closed > 1, exact_area > 1});
            }
          summary.add_row({hurst, zeta, gaps.adhesion, gaps.prefactor, linear_law_noncontact_area(gaps, 0),
                           noncontact_area(gaps, exact, 0)});
        }
    results.write_csv("area-load.csv", table);
    log << "Area-load curves, A_nc/A_0 against p_bar/sqrt(V) from " << range.smallest_mean_pressure << " to "
        << range.largest_mean_pressure << " (paper Figs. 4 and 5)\n"
        << convention_line(parameters) << '\n';
    summary.print(log);
    std::ostringstream error;
    error << std::scientific << std::setprecision(2) << worst;
    log << "largest |integral/closed form - 1|, linear law: " << error.str() << '\n'
        << "Table: " << results.directory().string() << "/area-load.csv\n";
    return worst;
  }

  void run_rough_surface_scene(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
  {
    const auto  &roughness = *parameters.roughness;
    const double E_star    = parameters.material->plane_strain_modulus();
    const double K_Ic      = parameters.adhesion->critical_stress_intensity;
    const bool   from_file = roughness.spectrum == RoughnessParameters::Spectrum::file;
    const auto   spectrum =
        from_file ? read_power_spectrum(roughness.spectrum_file, "Roughness/Spectrum file")
                    : power_law_spectrum(roughness.hurst, roughness.q0, roughness.zeta, roughness.amplitude);
    const SpectralMoments m = spectral_moments(spectrum);

    Table moments = Table::summary();
    moments.add_row({"spectrum", from_file ? "file " + roughness.spectrum_file
                                           : "power law H = " + name_of(roughness.hurst) +
                                                 ", zeta = " + name_of(roughness.zeta)});
    moments.add_row({"m0 (m^2)", m.m0});
    moments.add_row({"m2", m.m2});
    moments.add_row({"m4 (1/m^2)", m.m4});
    moments.add_row({"m6 (1/m^4)", m.m6});
    moments.add_row({"E* (Pa)", E_star});
    moments.add_row({"K_Ic (Pa m^1/2)", K_Ic});

    const PressureSummits summits[2] = {pressure_summits(m, E_star, Convention::paper),
                                        pressure_summits(m, E_star, Convention::consistent)};
    const GapPopulation   gaps[2]    = {surface_population(summits[0], K_Ic, Convention::paper),
                                        surface_population(summits[1], K_Ic, Convention::consistent)};
    Table                 conventions({{"quantity"}, {"paper"}, {"consistent"}, {"consistent/paper"}});
    const auto            row = [&](const std::string &name, const double paper, const double consistent) {
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

    const auto &range = *parameters.area_load;
    Table       curve({{"p_bar/sqrtV"},
                       {"A_nc paper"},
                       {"A_nc consistent"},
                       {"A_nc paper exact g"},
                       {"A_nc consistent exact g"}});
    for (unsigned int i = 0; i < range.n_points; ++i)
      {
        const double p_bar = range.mean_pressure(i);
        curve.add_row({p_bar, linear_law_noncontact_area(gaps[0], p_bar),
                       linear_law_noncontact_area(gaps[1], p_bar),
                       noncontact_area(gaps[0], exact_gap_law(gaps[0].adhesion), p_bar),
                       noncontact_area(gaps[1], exact_gap_law(gaps[1].adhesion), p_bar)});
      }
    results.write_csv("rough-surface.csv", curve);
    results.write_csv("rough-surface-moments.csv", moments);
    results.write_csv("rough-surface-conventions.csv", conventions);

    log << "Rough surface: moments of the height PSD, the full-contact pressure summits and p0\n";
    moments.print(log);
    log << '\n';
    conventions.print(log);
    log << "(the paper convention replaces its 3 pi R_p eta sqrt(V) by sqrt(2 pi) = " << std::sqrt(2 * M_PI)
        << ")\n"
        << "A_nc/A_0 at p_bar = " << range.smallest_mean_pressure << " sqrt(V), linear law: paper "
        << linear_law_noncontact_area(gaps[0], range.smallest_mean_pressure) << ", consistent "
        << linear_law_noncontact_area(gaps[1], range.smallest_mean_pressure) << '\n'
        << "Tables: " << results.directory().string()
        << "/rough-surface.csv (both conventions), rough-surface-moments.csv, "
           "rough-surface-conventions.csv\n";
  }

  double run_magnification_scaling_scene(const Parameters &parameters, const ResultFolder &results,
                                         std::ostream &log)
  {
    const auto &fit   = *parameters.magnification_scaling;
    double      worst = 0;
    Table       table({{"H"},
                       {"theta (2/5)(2H-1)"},
                       {"theta fit paper"},
                       {"theta fit consistent"},
                       {"largest |fit - theta|", error_digits}});
    for (const double hurst : parameters.area_load->hurst_exponents)
      {
        const double theta = scaling_exponent(hurst);
        double       fits[2];
        for (const Convention convention : {Convention::paper, Convention::consistent})
          fits[convention == Convention::consistent] = fitted_scaling_exponent(
              hurst, fit.first_fit_magnification, fit.last_fit_magnification, 41, convention);
        const double error = std::max(std::abs(fits[0] - theta), std::abs(fits[1] - theta));
        worst              = std::max(worst, error);
        table.add_row({hurst, theta, fits[0], fits[1], error});
      }
    results.write_csv("magnification-scaling.csv", table);
    log << "Magnification exponent: p0/sqrt(V) ~ zeta^theta, least-squares fit of the moments' values over "
           "zeta in ["
        << fit.first_fit_magnification << ", " << fit.last_fit_magnification << "]\n";
    table.print(log);
    log << "Table: " << results.directory().string() << "/magnification-scaling.csv\n";
    return worst;
  }
} // namespace penny
