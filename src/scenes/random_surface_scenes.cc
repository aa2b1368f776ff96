#include "scenes/random_surface_scenes.h"

#include "fracture/periodic_array.h"
#include "input/input_error.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "statistics/contact_area.h"
#include "contact/half_space_contact.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"
#include "statistics/summit_statistics.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace penny
{
  namespace
  {
    const Table::Format error_digits{2, true};

    // Mean and standard error of the mean over the rows' `column`.
    Estimate mean_over(const std::vector<std::vector<double>> &rows, const std::size_t column)
    {
      const double n    = rows.size();
      double       mean = 0, square = 0;
      for (const auto &row : rows)
        mean += row[column] / n;
      for (const auto &row : rows)
        square += std::pow(row[column] - mean, 2);
      return {mean, n > 1 ? std::sqrt(square / (n - 1) / n) : 0.};
    }

    // |value - expected| in standard errors.
    double deviation(const double value, const double expected, const double standard_error)
    {
      return std::abs(value - expected) / standard_error;
    }

    // The square grid of the Random surfaces section for a spectrum on
    // q0 <= q <= zeta q0: side L = period 2 pi/q0; its shortest wavelength must span 4 points.
    PeriodicGrid surface_grid(const RandomSurfaceParameters &surfaces, const PowerSpectrum &spectrum)
    {
      const double q0 = spectrum.wavenumbers.front(), zeta = spectrum.wavenumbers.back() / q0;
      const double points_per_shortest_wavelength = surfaces.n_points / (surfaces.period * zeta);
      if (points_per_shortest_wavelength < 4)
        {
          std::ostringstream message;
          message << "Random surfaces/Grid points per side = " << surfaces.n_points << " leaves "
                  << points_per_shortest_wavelength
                  << " points per shortest wavelength lambda0/zeta; at least 4 are needed";
          throw InputError(message.str());
        }
      return square_grid(surfaces.n_points, surfaces.period * 2 * M_PI / q0);
    }

    // The least-squares slope of y against x.
    double fitted_slope(const std::vector<double> &x, const std::vector<double> &y)
    {
      const double n  = x.size();
      double       sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          sx += x[i];
          sy += y[i];
          sxx += x[i] * x[i];
          sxy += x[i] * y[i];
        }
      return (n * sxy - sx * sy) / (n * sxx - sx * sx);
    }

    int n_ranks()
    {
      return dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    }

    // A number to 3 digits, as text.
    std::string three_digits(const double value)
    {
      std::ostringstream text;
      text.precision(3);
      text << value;
      return text.str();
    }
  } // namespace

  // Per realisation: the height moments m0, m2, m4, the pressure moments m0,
  // m2, m4, m22, then the packed summit sample of the pressure field.
  Verdict run_summit_statistics_scene(const Parameters &parameters, const ResultFolder &results,
                                      std::ostream &log)
  {
    const auto   &surfaces  = *parameters.random_surfaces;
    const auto   &settings  = *parameters.summit_statistics;
    const auto   &roughness = *parameters.roughness;
    const double  E_star    = parameters.material->plane_strain_modulus();
    dealii::Timer timer;
    Table         summary({{"H"},
                           {"zeta"},
                           {"summits"},
                           {"eta sampled (1/m^2)"},
                           {"eta std error (1/m^2)"},
                           {"eta lattice Kac-Rice (1/m^2)"},
                           {"eta consistent (1/m^2)"},
                           {"eta paper (1/m^2)"},
                           {"1/R_p sampled (Pa/m^2)"},
                           {"1/R_p std error (Pa/m^2)"},
                           {"1/R_p lattice Kac-Rice (Pa/m^2)"},
                           {"1/R_p consistent (Pa/m^2)"},
                           {"1/R_p paper (Pa/m^2)"},
                           {"V sampled (Pa^2)"},
                           {"V consistent (Pa^2)"},
                           {"V paper (Pa^2)"}});
    Table         screen({{"H"},
                          {"zeta"},
                          {"summits"},
                          {"eta/eta_cons", {4}},
                          {"+-", {1, true}},
                          {"eta_lattice/eta_cons", {4}},
                          {"eta_paper/eta_cons", {4}},
                          {"kappa/kappa_cons", {4}},
                          {"+-", {1, true}},
                          {"kappa_lattice/kappa_cons", {4}},
                          {"kappa_paper/kappa_cons", {4}}});
    Table         moments_table({{"H"},
                                 {"zeta"},
                                 {"field"},
                                 {"moment"},
                                 {"sampled"},
                                 {"std error"},
                                 {"lattice expectation"},
                                 {"continuum"},
                                 {"deviation (std errors)"}});
    Table         heights({{"H"},
                           {"zeta"},
                           {"z low/sqrtV"},
                           {"z high/sqrtV"},
                           {"summits"},
                           {"density per height (1/(m^2 Pa))"},
                           {"density std error (1/(m^2 Pa))"},
                           {"density Kac-Rice at bin centre (1/(m^2 Pa))"},
                           {"mean curvature (Pa/m^2)"},
                           {"mean curvature std error (Pa/m^2)"},
                           {"mean curvature Kac-Rice at bin centre (Pa/m^2)"}});
    double        worst = 0;
    if (roughness.spectrum == RoughnessParameters::Spectrum::file)
      throw InputError("Roughness/Spectrum = file: summit-statistics samples the power laws of its 'Hurst "
                       "exponents' and 'Magnifications'; set Spectrum = power-law");
    for (const double hurst : settings.hurst_exponents)
      for (const double zeta : settings.magnifications)
        {
          const PowerSpectrum spectrum = power_law_spectrum(hurst, roughness.q0, zeta, roughness.amplitude);
          const PeriodicGrid  grid     = surface_grid(surfaces, spectrum);
          const FourierTransform transform(grid);
          const LatticeMoments   height_lattice = lattice_moments(grid, spectrum);
          const LatticeMoments pressure_lattice = lattice_moments(grid, pressure_spectrum(spectrum, E_star));
          const double         sqrt_V           = std::sqrt(pressure_lattice.expected.m0);
          const HeightBins     bins{-2 * sqrt_V, 4 * sqrt_V, settings.n_height_bins};

          const auto rows = spread_over_ranks(MPI_COMM_WORLD, surfaces.n_realisations, [&](unsigned int k) {
            const GridField     h  = gaussian_field(transform, spectrum, realisation_seed(surfaces.seed, k));
            const GridField     p  = full_contact_pressure(transform, h, E_star);
            const FieldMoments  mh = sampled_moments(transform, h), mp = sampled_moments(transform, p);
            std::vector<double> row = {mh.m0, mh.m2, mh.m4, mp.m0, mp.m2, mp.m4, mp.m22};
            const auto sample       = summarise_summits(find_summits(transform, p), grid.area(), bins).pack();
            row.insert(row.end(), sample.begin(), sample.end());
            return row;
          });
          std::vector<SummitSample> samples;
          for (const auto &row : rows)
            samples.push_back(SummitSample::unpack({row.begin() + 7, row.end()}, bins.n));
          const SummitEnsemble ensemble = summit_ensemble(samples, bins);

          // The moments against their lattice expectation (standard error from
          // the exact spread of one realisation) and the continuum ones.
          const SpectralMoments continuum = spectral_moments(spectrum);
          const double          scale = E_star * E_star / 4, n = rows.size();
          const struct
          {
            const char *field, *name;
            std::size_t column;
            double      expected, spread, continuum;
          } checks[] = {{"height", "m0 (m^2)", 0, height_lattice.expected.m0,
                         height_lattice.standard_deviation.m0, continuum.m0},
                        {"height", "m2", 1, height_lattice.expected.m2, height_lattice.standard_deviation.m2,
                         continuum.m2},
                        {"height", "m4 (1/m^2)", 2, height_lattice.expected.m4,
                         height_lattice.standard_deviation.m4, continuum.m4},
                        // The pressure's profile moments from the heights' (roughness.h).
                        {"pressure", "m0 = V (Pa^2)", 3, pressure_lattice.expected.m0,
                         pressure_lattice.standard_deviation.m0, scale * 2 * continuum.m2},
                        {"pressure", "m2 (Pa^2/m^2)", 4, pressure_lattice.expected.m2,
                         pressure_lattice.standard_deviation.m2, scale * 4 / 3 * continuum.m4},
                        {"pressure", "m4 (Pa^2/m^4)", 5, pressure_lattice.expected.m4,
                         pressure_lattice.standard_deviation.m4, scale * 6 / 5 * continuum.m6},
                        {"pressure", "m22 (Pa^2/m^4)", 6, pressure_lattice.expected.m22,
                         pressure_lattice.standard_deviation.m22, scale * 6 / 5 * continuum.m6 / 3}};
          for (const auto &check : checks)
            {
              const double sampled = mean_over(rows, check.column).value, error = check.spread / std::sqrt(n);
              const double off = deviation(sampled, check.expected, error);
              worst            = std::max(worst, off);
              moments_table.add_row({hurst, zeta, check.field, check.name, sampled, error, check.expected,
                                     check.continuum, off});
            }

          const ExpectedSummits lattice    = expected_summits(pressure_lattice.expected);
          const PressureSummits consistent = pressure_summits(continuum, E_star, Convention::consistent);
          const PressureSummits paper      = pressure_summits(continuum, E_star, Convention::paper);
          worst                            = std::max(
                                         {worst, deviation(ensemble.density.value, lattice.density, ensemble.density.standard_error),
                                          deviation(ensemble.mean_curvature.value, lattice.mean_curvature,
                                                    ensemble.mean_curvature.standard_error)});
          const double kappa_consistent = 1 / consistent.summit_radius;
          summary.add_row(
              {hurst, zeta, ensemble.n_summits, ensemble.density.value, ensemble.density.standard_error,
               lattice.density, consistent.density, paper.density, ensemble.mean_curvature.value,
               ensemble.mean_curvature.standard_error, lattice.mean_curvature, kappa_consistent,
               1 / paper.summit_radius, mean_over(rows, 3).value, consistent.variance, paper.variance});
          screen.add_row(
              {hurst, zeta, ensemble.n_summits, ensemble.density.value / consistent.density,
               ensemble.density.standard_error / consistent.density, lattice.density / consistent.density,
               paper.density / consistent.density, ensemble.mean_curvature.value / kappa_consistent,
               ensemble.mean_curvature.standard_error / kappa_consistent,
               lattice.mean_curvature / kappa_consistent, (1 / paper.summit_radius) / kappa_consistent});
          for (const auto &bin : ensemble.bins)
            {
              const double centre = (bin.height_low + bin.height_high) / 2;
              heights.add_row(
                  {hurst, zeta, bin.height_low / sqrt_V, bin.height_high / sqrt_V, bin.n_summits,
                   bin.density_per_height.value, bin.density_per_height.standard_error,
                   summit_height_density(pressure_lattice.expected, centre),
                   bin.n_summits > 1 ? Table::Cell(bin.mean_curvature.value) : Table::Cell(""),
                   bin.n_summits > 1 ? Table::Cell(bin.mean_curvature.standard_error) : Table::Cell(""),
                   summit_mean_curvature_at(pressure_lattice.expected, centre)});
            }
        }
    results.write_csv("summit-statistics.csv", summary);
    results.write_csv("sampled-moments.csv", moments_table);
    results.write_csv("summit-heights.csv", heights);

    log << "Summits of the full-contact pressure p_fc over " << surfaces.n_realisations << " realisations on "
        << surfaces.n_points << "^2 grids (L = " << surfaces.period << " lambda0), " << n_ranks()
        << " rank(s), " << timer.wall_time() << " s wall\n"
        << "eta: summit density, kappa = 1/R_p: mean summit curvature; in units of the consistent (Nayak) "
           "values of the continuum spectrum\n";
    screen.print(log);
    log << "Tables: summit-statistics.csv, sampled-moments.csv, summit-heights.csv in "
        << results.directory().string() << "/\n";

    std::ostringstream message;
    message.precision(2);
    message << "sampled moments, summit density and mean curvature within " << worst
            << " standard errors of their lattice expectation "
            << (worst <= settings.largest_deviation ? "<= " : "> ")
            << "Summit statistics/Largest deviation = " << settings.largest_deviation;
    return {worst <= settings.largest_deviation, message.str()};
  }

  Verdict run_bem_westergaard_scene(const Parameters &parameters, const ResultFolder &results,
                                    std::ostream &log)
  {
    const auto  &bem    = *parameters.bem_westergaard;
    const double lambda = bem.wavelength;
    const double E_star = parameters.material->plane_strain_modulus();
    const double p_star = M_PI * E_star * bem.amplitude / lambda;
    Table        table({{"points per lambda"},
                        {"p_bar/p*"},
                        {"a/lambda exact", {8}},
                        {"a/lambda BEM", {8}},
                        {"|a error|/lambda", error_digits},
                        {"|a error|/lambda contact points", error_digits},
                        {"max |p error|/p* inside", error_digits},
                        {"iterations"},
                        {"wall time (s)", {3}}});
    // Per load: log N and the logs of both errors, for the fitted rates.
    std::vector<std::vector<double>> log_n(bem.load_ratios.size()), log_error(bem.load_ratios.size()),
        log_pressure_error(bem.load_ratios.size());
    double worst_at_finest = 0;
    for (std::size_t g = 0; g < bem.grid_sizes.size(); ++g)
      {
        const unsigned int     n = bem.grid_sizes[g];
        const PeriodicGrid     grid{n, 4, lambda, 4 * lambda / n};
        const FourierTransform transform(grid);
        GridField              h(grid.n_points());
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < grid.ny; ++j)
            h[i * grid.ny + j] = 2 * bem.amplitude * std::pow(std::sin(M_PI * i / n), 2);
        const HalfSpaceContact contact(transform, h, E_star);
        for (std::size_t l = 0; l < bem.load_ratios.size(); ++l)
          {
            const double          ratio = bem.load_ratios[l];
            dealii::Timer         timer;
            const ContactSolution solution = contact.solve(ratio * p_star, {100000, bem.solver_tolerance});
            // The strip is centred on the crest x = lambda/2 (i = n/2); its
            // edge lies between the last contact point and the gap beside it.
            unsigned int last = n / 2;
            while (last + 1 < n && solution.pressure[(last + 1) * grid.ny] > 0)
              ++last;
            std::vector<double> gaps;
            for (unsigned int k = 1; k <= 8 && last + k < n; ++k)
              gaps.push_back(solution.gap[(last + k) * grid.ny]);
            const double exact      = periodic_array::westergaard_contact_ratio(ratio);
            const double half_width = (last - n / 2. + edge_from_gap(gaps)) / n;
            const double error      = std::abs(half_width - exact);
            const double coarse     = std::abs((last - n / 2. + 0.5) / n - exact);
            // The pressure more than 0.05 lambda inside the edges.
            double pressure_error = 0;
            for (unsigned int i = 0; i < n; ++i)
              {
                const double s = double(i) / n - 0.5;
                if (std::abs(s) < exact - 0.05)
                  pressure_error =
                      std::max(pressure_error, std::abs(solution.pressure[i * grid.ny] / p_star -
                                                        periodic_array::westergaard_pressure(s, ratio)));
              }
            table.add_row({n, ratio, exact, half_width, error, coarse, pressure_error, solution.iterations,
                           timer.wall_time()});
            log_n[l].push_back(std::log(n));
            log_error[l].push_back(std::log(error));
            log_pressure_error[l].push_back(std::log(pressure_error));
            if (g + 1 == bem.grid_sizes.size())
              worst_at_finest = std::max(worst_at_finest, error);
          }
      }
    // The rate r of error ~ N^-r: least squares over all grids (the sub-grid
    // half-width error does not fall monotonically from one grid to the next).
    Table rates({{"p_bar/p*"}, {"half-width rate", {3}}, {"pressure rate", {3}}});
    for (std::size_t l = 0; l < bem.load_ratios.size(); ++l)
      rates.add_row({bem.load_ratios[l], -fitted_slope(log_n[l], log_error[l]),
                     -fitted_slope(log_n[l], log_pressure_error[l])});
    results.write_csv("bem-westergaard.csv", table);
    results.write_csv("bem-westergaard-rates.csv", rates);
    log << "FFT boundary elements on Westergaard's sinusoid h = 2 h0 sin^2(pi x/lambda): contact half-width "
           "(sub-grid, from the gap beside the edge; and from the contact points alone) and pressure against "
           "p_bar/p* = sin^2(pi a/lambda)\n";
    table.print(log);
    log << "Rates r of error ~ N^-r, least squares over the grids:\n";
    rates.print(log);
    log << "Tables: bem-westergaard.csv, bem-westergaard-rates.csv in " << results.directory().string()
        << "/\n";

    std::ostringstream message;
    message.precision(2);
    message << std::scientific << "largest |a error|/lambda at " << bem.grid_sizes.back()
            << " points per wavelength " << worst_at_finest
            << (worst_at_finest <= bem.half_width_tolerance ? " <= " : " > ")
            << "BEM Westergaard/Half-width tolerance = " << bem.half_width_tolerance;
    return {worst_at_finest <= bem.half_width_tolerance, message.str()};
  }

  // Per realisation: the non-contact share at every load, then the iterations.
  void run_random_contact_scene(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
  {
    const auto  &surfaces  = *parameters.random_surfaces;
    const auto  &settings  = *parameters.random_contact;
    const auto  &roughness = *parameters.roughness;
    const double E_star    = parameters.material->plane_strain_modulus();
    // The Roughness spectrum: the power law or the table of its file.
    const PowerSpectrum spectrum =
        roughness.spectrum == RoughnessParameters::Spectrum::file
            ? read_power_spectrum(roughness.spectrum_file, "Roughness/Spectrum file")
            : power_law_spectrum(roughness.hurst, roughness.q0, roughness.zeta, roughness.amplitude);
    const PeriodicGrid     grid = surface_grid(surfaces, spectrum);
    const FourierTransform transform(grid);
    const FieldMoments     pressure = lattice_moments(grid, pressure_spectrum(spectrum, E_star)).expected;
    const double           sqrt_V   = std::sqrt(pressure.m0);
    const std::size_t      n_loads  = settings.mean_pressures.size();
    std::vector<double>    loads;
    for (const double p : settings.mean_pressures)
      loads.push_back(p * sqrt_V);

    dealii::Timer timer;
    const auto    rows      = spread_over_ranks(MPI_COMM_WORLD, surfaces.n_realisations, [&](unsigned int k) {
      const HalfSpaceContact contact(
                  transform, gaussian_field(transform, spectrum, realisation_seed(surfaces.seed, k)), E_star);
      std::vector<double> row(2 * n_loads);
      const auto steps = load_sweep(contact, loads, {settings.max_iterations, settings.solver_tolerance});
      for (std::size_t l = 0; l < n_loads; ++l)
        {
          row[l]           = steps[l].noncontact_fraction;
          row[n_loads + l] = steps[l].iterations;
        }
      return row;
    });
    const double  wall_time = timer.wall_time();

    // The layer's isolated-gap law without adhesion in both conventions, each
    // with its own V, eta and R_p from the continuum moments; the same law
    // summed over the lattice's Kac-Rice summits, each with its own
    // curvature; and Persson's A_nc/A_0 = erfc(p_bar/sqrt(2 V)).
    const SpectralMoments continuum = spectral_moments(spectrum);
    struct Law
    {
      GapPopulation gaps;
      double        sqrt_V;
    };
    std::vector<Law> laws;
    for (const Convention convention : {Convention::paper, Convention::consistent})
      {
        const PressureSummits summits = pressure_summits(continuum, E_star, convention);
        laws.push_back({surface_population(summits, 0, convention), std::sqrt(summits.variance)});
      }
    Table table({{"p_bar/sqrtV"},
                 {"A_nc/A_0 BEM", {4, true}},
                 {"std error", {2, true}},
                 {"linear law paper", {4, true}},
                 {"linear law consistent", {4, true}},
                 {"isolated gaps Kac-Rice", {4, true}},
                 {"Persson erfc", {4, true}},
                 {"BEM/consistent", {3}},
                 {"mean iterations", {4}}});
    for (std::size_t l = 0; l < n_loads; ++l)
      {
        const Estimate area       = mean_over(rows, l);
        const double   consistent = linear_law_noncontact_area(laws[1].gaps, loads[l] / laws[1].sqrt_V);
        table.add_row({settings.mean_pressures[l], area.value, area.standard_error,
                       linear_law_noncontact_area(laws[0].gaps, loads[l] / laws[0].sqrt_V), consistent,
                       expected_gap_area(pressure, loads[l]),
                       std::erfc(settings.mean_pressures[l] / std::sqrt(2.)), area.value / consistent,
                       mean_over(rows, n_loads + l).value});
      }
    results.write_csv("random-contact.csv", table);

    Table summary = Table::summary();
    summary.add_row({"realisations", surfaces.n_realisations});
    summary.add_row({"grid", std::to_string(grid.nx) + "^2"});
    if (roughness.spectrum == RoughnessParameters::Spectrum::file)
      summary.add_row({"spectrum file", roughness.spectrum_file});
    else
      summary.add_row({"H, zeta", three_digits(roughness.hurst) + ", " + three_digits(roughness.zeta)});
    summary.add_row({"MPI ranks", n_ranks()});
    summary.add_row({"wall time (s)", Table::Cell(wall_time, Table::Format{4})});
    summary.add_row({"sqrt(V) sampled lattice (Pa)", sqrt_V});
    summary.add_row({"sqrt(V) paper/consistent/lattice", three_digits(laws[0].sqrt_V / sqrt_V) + " / " +
                                                             three_digits(laws[1].sqrt_V / sqrt_V) + " / 1"});
    summary.add_row({"prefactor 3 pi R_p eta sqrt(V) paper", laws[0].gaps.prefactor});
    summary.add_row({"prefactor 3 pi R_p eta sqrt(V) consistent", laws[1].gaps.prefactor});
    results.write_csv("random-contact-summary.csv", summary);
    log << "Non-contact area of random surfaces by FFT boundary elements, beside the isolated-gap law "
           "(adhesionless)\n";
    summary.print(log);
    table.print(log);
    log << "Tables: random-contact.csv, random-contact-summary.csv in " << results.directory().string()
        << "/\n";
  }
} // namespace penny
