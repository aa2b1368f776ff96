#include "contact_scenes.h"

#include "adhesive_gap.h"
#include "contact_area.h"
#include "output_files.h"
#include "roughness.h"

#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace penny
{
  namespace
  {
    void
    write_table(const Parameters &parameters, const std::string &file, const std::string &table)
    {
      write_atomically(std::filesystem::path(parameters.output.directory) / file,
                       [&](std::ostream &out) { out << table; });
    }

    double
    relative_difference(const double value, const double reference)
    {
      return reference == 0 ? std::abs(value) : std::abs(value / reference - 1);
    }

    // The gaps of the power-law surface (H, zeta): the paper's normalised
    // population, or the consistent one from the moments of the Roughness
    // spectrum with this H and zeta.
    GapPopulation
    population(const Parameters &parameters, const double hurst, const double zeta)
    {
      if (parameters.area_load.convention_is_paper)
        return paper_population(hurst, zeta);
      const auto &roughness = parameters.roughness;
      const auto  moments =
          spectral_moments(power_law_spectrum(hurst, roughness.q0, zeta, roughness.amplitude));
      return surface_population(
          pressure_summits(moments, parameters.material.plane_strain_modulus(), Convention::consistent),
          parameters.adhesion.critical_stress_intensity,
          Convention::consistent);
    }

    double
    mean_pressure(const AreaLoadParameters &range, const unsigned int i)
    {
      return range.smallest_mean_pressure +
             i * (range.largest_mean_pressure - range.smallest_mean_pressure) / (range.n_points - 1);
    }

    std::string
    convention_line(const Parameters &parameters)
    {
      return parameters.area_load.convention_is_paper
                 ? "convention: paper (3 pi R_p eta sqrt(V) = sqrt(2 pi), p0/sqrt(V) = zeta^theta)"
                 : "convention: consistent (V, eta, R_p and p0 from the moments of the Roughness power law)";
    }
  } // namespace

  void
  run_sinusoid_contact_scene(const Parameters &parameters, std::ostream &log)
  {
    const auto        &sinusoid = parameters.sinusoid;
    std::ostringstream table;
    table << "a/lambda";
    for (const double alpha : sinusoid.alphas)
      table << ",p/p* alpha=" << alpha;
    table << '\n' << std::setprecision(12);
    std::vector<std::vector<double>> loads(sinusoid.alphas.size());
    std::vector<double>              ratios;
    for (unsigned int i = 1; i <= sinusoid.n_points; ++i)
      {
        ratios.push_back(0.5 * i / (sinusoid.n_points + 1));
        table << ratios.back();
        for (unsigned int k = 0; k < sinusoid.alphas.size(); ++k)
          {
            loads[k].push_back(johnson_sinusoid_load(ratios.back(), sinusoid.alphas[k]));
            table << ',' << loads[k].back();
          }
        table << '\n';
      }
    write_table(parameters, "sinusoid-contact.csv", table.str());
    // The jump into full contact is the curve's maximum inside (0, 1/2), or
    // its end a -> lambda/2 without adhesion.
    log << "Johnson's adhesive 1D sinusoid: p/p* = sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda))\n"
        << "  alpha   jump into full contact at p/p*   a/lambda   (largest interior maximum on the grid)\n";
    for (unsigned int k = 0; k < sinusoid.alphas.size(); ++k)
      {
        const auto  &load = loads[k];
        unsigned int best = load.size() - 1;
        for (unsigned int i = 1; i + 1 < load.size(); ++i)
          if (load[i] >= load[i - 1] && load[i] >= load[i + 1] &&
              (best == load.size() - 1 || load[i] > load[best]))
            best = i;
        log << "  " << std::setw(5) << sinusoid.alphas[k] << std::setw(33) << load[best] << std::setw(11)
            << ratios[best] << '\n';
      }
    log << "Table: " << parameters.output.directory << "/sinusoid-contact.csv\n";
  }

  double
  run_zero_load_gap_area_scene(const Parameters &parameters, std::ostream &log)
  {
    const auto &range   = parameters.area_load;
    const auto  surface = population(parameters, parameters.roughness.hurst, parameters.roughness.zeta);
    double      worst   = 0;
    std::ostringstream table;
    table << "p0/sqrtV,A_nc linear closed form,A_nc linear integral,A_nc exact g,A_c Persson-type\n"
          << std::setprecision(15);
    for (unsigned int i = 0; i < range.n_points; ++i)
      {
        const GapPopulation gaps{ surface.prefactor,
                                  range.largest_adhesion_ratio * i / (range.n_points - 1) };
        const double        closed   = linear_law_noncontact_area(gaps, 0);
        const double        integral = noncontact_area(gaps, linear_gap_law(gaps.adhesion), 0);
        worst                        = std::max(worst, relative_difference(integral, closed));
        table << gaps.adhesion << ',' << closed << ',' << integral << ','
              << noncontact_area(gaps, exact_gap_law(gaps.adhesion), 0) << ','
              << persson_contact_area(gaps.adhesion, 0) << '\n';
      }
    write_table(parameters, "zero-load-gap-area.csv", table.str());
    const GapPopulation last{ surface.prefactor, range.largest_adhesion_ratio };
    log << "Non-contact area at zero mean pressure against p0/sqrt(V) (paper Fig. 3)\n  "
        << convention_line(parameters) << "\n  prefactor 3 pi R_p eta sqrt(V) = " << surface.prefactor << '\n'
        << std::setprecision(4) << "  at p0/sqrt(V) = " << last.adhesion << ": A_nc/A_0 linear law "
        << linear_law_noncontact_area(last, 0) << ", exact g "
        << noncontact_area(last, exact_gap_law(last.adhesion), 0) << '\n'
        << std::scientific << std::setprecision(2)
        << "  largest |integral/closed form - 1|, linear law: " << worst << std::defaultfloat << '\n'
        << "Table: " << parameters.output.directory << "/zero-load-gap-area.csv\n";
    return worst;
  }

  double
  run_area_load_scene(const Parameters &parameters, std::ostream &log)
  {
    const auto        &range = parameters.area_load;
    double             worst = 0;
    std::ostringstream table, summary;
    table << "H,zeta,p0/sqrtV,p_bar/sqrtV,A_nc linear closed form,A_nc linear integral,A_nc exact g,"
             "A_nc adhesionless,A_c Persson-type,A_c Persson-type adhesionless\n"
          << std::setprecision(15);
    summary << "       H        zeta  p0/sqrt(V)   prefactor   A_nc(p_bar = 0): linear law     exact g\n";
    for (const double hurst : range.hurst_exponents)
      for (const double zeta : range.magnifications)
        {
          const GapPopulation gaps = population(parameters, hurst, zeta);
          const GapPopulation adhesionless{ gaps.prefactor, 0 };
          const auto          exact = exact_gap_law(gaps.adhesion);
          for (unsigned int i = 0; i < range.n_points; ++i)
            {
              const double p_bar    = mean_pressure(range, i);
              const double closed   = linear_law_noncontact_area(gaps, p_bar);
              const double integral = noncontact_area(gaps, linear_gap_law(gaps.adhesion), p_bar);
              worst                 = std::max(worst, relative_difference(integral, closed));
              table << hurst << ',' << zeta << ',' << gaps.adhesion << ',' << p_bar << ',' << closed << ','
                    << integral << ',' << noncontact_area(gaps, exact, p_bar) << ','
                    << linear_law_noncontact_area(adhesionless, p_bar) << ','
                    << persson_contact_area(gaps.adhesion, p_bar) << ',' << persson_contact_area(0, p_bar)
                    << '\n';
            }
          summary << std::setprecision(5) << std::setw(8) << hurst << std::setw(12) << zeta << std::setw(12)
                  << gaps.adhesion << std::setw(12) << gaps.prefactor << std::setw(31)
                  << linear_law_noncontact_area(gaps, 0) << std::setw(12) << noncontact_area(gaps, exact, 0)
                  << std::setprecision(15) << '\n';
        }
    write_table(parameters, "area-load.csv", table.str());
    log << "Area-load curves, A_nc/A_0 against p_bar/sqrt(V) from " << range.smallest_mean_pressure << " to "
        << range.largest_mean_pressure << " (paper Figs. 4 and 5)\n  " << convention_line(parameters) << '\n'
        << summary.str() << std::scientific << std::setprecision(2)
        << "  largest |integral/closed form - 1|, linear law: " << worst << std::defaultfloat << '\n'
        << "Table: " << parameters.output.directory << "/area-load.csv\n";
    return worst;
  }

  void
  run_rough_surface_scene(const Parameters &parameters, std::ostream &log)
  {
    const auto  &roughness = parameters.roughness;
    const double E_star    = parameters.material.plane_strain_modulus();
    const double K_Ic      = parameters.adhesion.critical_stress_intensity;
    const auto   spectrum =
        roughness.spectrum == RoughnessParameters::Spectrum::file
              ? read_power_spectrum(roughness.spectrum_file, "Roughness/Spectrum file")
              : power_law_spectrum(roughness.hurst, roughness.q0, roughness.zeta, roughness.amplitude);
    const SpectralMoments m = spectral_moments(spectrum);

    const Convention   conventions[] = { Convention::paper, Convention::consistent };
    GapPopulation      gaps[2];
    std::ostringstream text;
    text << std::setprecision(6)
         << "Rough surface: moments of the height PSD, the full-contact pressure summits and p0\n"
         << "  spectrum          "
         << (roughness.spectrum == RoughnessParameters::Spectrum::file
                 ? "file " + roughness.spectrum_file
                 : "power law H = " + std::to_string(roughness.hurst) +
                       ", zeta = " + std::to_string(roughness.zeta))
         << "\n  m0 (m^2)          " << m.m0 << "\n  m2                " << m.m2 << "\n  m4 (1/m^2)        "
         << m.m4 << "\n  m6 (1/m^4)        " << m.m6 << "\n  E* (Pa)           " << E_star
         << "\n  K_Ic (Pa m^1/2)   " << K_Ic
         << "\n                          paper      consistent   consistent/paper\n";
    PressureSummits summits[2];
    for (unsigned int k = 0; k < 2; ++k)
      {
        summits[k] = pressure_summits(m, E_star, conventions[k]);
        gaps[k]    = surface_population(summits[k], K_Ic, conventions[k]);
      }
    const auto row = [&](const std::string &name, const double paper, const double consistent) {
      text << "  " << std::left << std::setw(22) << name << std::right << std::setw(12) << paper
           << std::setw(14) << consistent << std::setw(14) << consistent / paper << '\n';
    };
    row("V (Pa^2)", summits[0].variance, summits[1].variance);
    row("eta (1/m^2)", summits[0].density, summits[1].density);
    row("R_p (m^2/Pa)", summits[0].summit_radius, summits[1].summit_radius);
    row("p0 (Pa)",
        gaps[0].adhesion * std::sqrt(summits[0].variance),
        gaps[1].adhesion * std::sqrt(summits[1].variance));
    row("p0/sqrt(V)", gaps[0].adhesion, gaps[1].adhesion);
    row("3 pi R_p eta sqrt(V)",
        3 * M_PI * summits[0].summit_radius * summits[0].density * std::sqrt(summits[0].variance),
        gaps[1].prefactor);
    text << "  (the paper convention replaces its 3 pi R_p eta sqrt(V) by sqrt(2 pi) = "
         << std::sqrt(2 * M_PI) << ")\n";

    const auto        &range = parameters.area_load;
    std::ostringstream table;
    table << "p_bar/sqrtV,A_nc paper,A_nc consistent,A_nc paper exact g,A_nc consistent exact g\n"
          << std::setprecision(15);
    for (unsigned int i = 0; i < range.n_points; ++i)
      {
        const double p_bar = mean_pressure(range, i);
        table << p_bar << ',' << linear_law_noncontact_area(gaps[0], p_bar) << ','
              << linear_law_noncontact_area(gaps[1], p_bar) << ','
              << noncontact_area(gaps[0], exact_gap_law(gaps[0].adhesion), p_bar) << ','
              << noncontact_area(gaps[1], exact_gap_law(gaps[1].adhesion), p_bar) << '\n';
      }
    text << "  A_nc/A_0 at p_bar = " << range.smallest_mean_pressure << " sqrt(V), linear law: paper "
         << linear_law_noncontact_area(gaps[0], range.smallest_mean_pressure) << ", consistent "
         << linear_law_noncontact_area(gaps[1], range.smallest_mean_pressure) << '\n'
         << "Table (both conventions): " << parameters.output.directory << "/rough-surface.csv\n";
    write_table(parameters, "rough-surface.csv", table.str());
    write_table(parameters, "rough-surface.txt", text.str());
    log << text.str();
  }

  double
  run_magnification_scaling_scene(const Parameters &parameters, std::ostream &log)
  {
    const auto        &range = parameters.area_load;
    double             worst = 0;
    std::ostringstream table;
    table << "H,theta (2/5)(2H-1),theta fit paper,theta fit consistent\n" << std::setprecision(12);
    log << "Magnification exponent: p0/sqrt(V) ~ zeta^theta, least-squares fit of the moments' values over "
           "zeta in ["
        << range.first_fit_magnification << ", " << range.last_fit_magnification << "]\n"
        << "     H   (2/5)(2H-1)   fit, paper   fit, consistent   largest |fit - theta|\n";
    for (const double hurst : range.hurst_exponents)
      {
        const double theta = scaling_exponent(hurst);
        double       fits[2];
        for (const Convention convention : { Convention::paper, Convention::consistent })
          fits[convention == Convention::consistent] = fitted_scaling_exponent(
              hurst, range.first_fit_magnification, range.last_fit_magnification, 41, convention);
        const double error = std::max(std::abs(fits[0] - theta), std::abs(fits[1] - theta));
        worst              = std::max(worst, error);
        table << hurst << ',' << theta << ',' << fits[0] << ',' << fits[1] << '\n';
        log << std::fixed << std::setprecision(6) << std::setw(6) << hurst << std::setw(14) << theta
            << std::setw(13) << fits[0] << std::setw(18) << fits[1] << std::scientific << std::setprecision(2)
            << std::setw(24) << error << std::defaultfloat << '\n';
      }
    write_table(parameters, "magnification-scaling.csv", table.str());
    log << "Table: " << parameters.output.directory << "/magnification-scaling.csv\n";
    return worst;
  }

  // The FE g at Chebyshev points of t, P = p0 + t^2 sqrt(V), interpolated in t
  // and aggregated; the closed-form g goes through the same table (to show the
  // interpolation error alone) and through the exact law.
  double
  run_fe_gap_area_scene(const Parameters &parameters, std::ostream &log)
  {
    dealii::TimerOutput timer(log, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    GapFamily           family(parameters, timer);
    const auto         &range   = parameters.area_load;
    const double        R_p     = parameters.load.summit_radius;
    const double        K_Ic    = parameters.adhesion.critical_stress_intensity;
    const double        p0      = closed_form::psi * adhesion_tension(R_p, K_Ic);
    const double        sqrt_V  = p0 / range.adhesion_ratio;
    const auto          minimum = fe_adhesive_minimum(family, R_p, K_Ic);

    const GapPopulation exact_gaps{ std::sqrt(2 * M_PI), range.adhesion_ratio };
    const GapPopulation fe_gaps{ exact_gaps.prefactor, minimum.tension / sqrt_V };
    const double        t_max   = std::max(integration_limit(fe_gaps.adhesion, range.smallest_mean_pressure),
                                  integration_limit(exact_gaps.adhesion, range.smallest_mean_pressure));
    const auto          fe_P    = chebyshev_tensions(fe_gaps.adhesion, t_max, range.n_tabulated_tensions);
    const auto          exact_P = chebyshev_tensions(exact_gaps.adhesion, t_max, range.n_tabulated_tensions);
    const auto          exact   = exact_gap_law(exact_gaps.adhesion);
    std::vector<double> fe_areas, exact_areas;
    std::ostringstream  gap_table;
    gap_table << "P/sqrtV,c_t FE (m),c_t closed form (m),relative error\n" << std::setprecision(15);
    double worst_radius = 0;
    for (unsigned int j = 0; j < fe_P.size(); ++j)
      {
        // fe_P[0] sqrt(V) may round a hair below the FE p0.
        const double P  = std::max(fe_P[j] * sqrt_V, minimum.tension);
        const double c  = *fe_stable_gap_radius(family, P, R_p, K_Ic, minimum);
        const double c0 = *closed_form::stable_gap_radius(std::max(P, p0), R_p, K_Ic);
        fe_areas.push_back(c * c / (3 * R_p * sqrt_V));
        exact_areas.push_back(exact(exact_P[j]));
        worst_radius = std::max(worst_radius, relative_difference(c, c0));
        gap_table << fe_P[j] << ',' << c << ',' << c0 << ',' << relative_difference(c, c0) << '\n';
      }
    const auto fe_law      = tabulated_gap_law(fe_gaps.adhesion, t_max, fe_areas);
    const auto exact_table = tabulated_gap_law(exact_gaps.adhesion, t_max, exact_areas);

    double             worst = 0, worst_table = 0;
    std::ostringstream table;
    table << "p_bar/sqrtV,A_nc FE g,A_nc closed-form g,A_nc closed-form g tabulated,relative difference\n"
          << std::setprecision(15);
    for (unsigned int i = 0; i < range.n_points; ++i)
      {
        const double p_bar     = mean_pressure(range, i);
        const double fe        = noncontact_area(fe_gaps, fe_law, p_bar);
        const double reference = noncontact_area(exact_gaps, exact, p_bar);
        const double tabulated = noncontact_area(exact_gaps, exact_table, p_bar);
        worst                  = std::max(worst, relative_difference(fe, reference));
        worst_table            = std::max(worst_table, relative_difference(tabulated, reference));
        table << p_bar << ',' << fe << ',' << reference << ',' << tabulated << ','
              << relative_difference(fe, reference) << '\n';
      }
    write_table(parameters, "fe-gap-table.csv", gap_table.str());
    write_table(parameters, "fe-gap-area.csv", table.str());

    log << "Area-load curve with the FE gap function g (stable branch of K_I = K_Ic)\n"
        << "  convention: paper prefactor sqrt(2 pi); p0/sqrt(V) = " << range.adhesion_ratio
        << " (the comparison is a ratio, free of the prefactor)\n"
        << "  FE g tabulated at " << fe_P.size() << " peak tensions P/sqrt(V) in [" << fe_P.front() << ", "
        << fe_P.back() << "]\n"
        << std::scientific << std::setprecision(2) << "  largest |c_t FE/c_t closed form - 1|          "
        << worst_radius << "\n  largest |A_nc(FE g)/A_nc(closed-form g) - 1|  " << worst
        << "\n  ... of the table alone (closed-form g)       " << worst_table << std::defaultfloat
        << "\n  FE solves " << family.n_solves() << ", wall time " << family.wall_time() << " s\n"
        << "Tables: " << parameters.output.directory << "/fe-gap-area.csv, fe-gap-table.csv\n";
    return worst;
  }
} // namespace penny
