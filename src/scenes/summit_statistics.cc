// summit-statistics: the summits of the full-contact pressure of sampled
// Gaussian surfaces over realisations (doc/theory.md, section 7): the sampled
// moments, the summit density eta, the summit heights and the mean summit
// curvature 1/R_p, beside their expectation for the sampled lattice (Kac-Rice)
// and both conventions of the continuum. PASS when the sampled moments,
// density and mean curvature lie within 'Largest deviation' standard errors
// of the lattice expectation.
#include "statistics/summit_statistics.h"
#include "contact/half_space.h"
#include "numerics/relative_error.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "problems/random_surfaces.h"
#include "problems/rough_surface.h"
#include "problems/solid.h"
#include "scenes/scene.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace penny
{
  namespace
  {
    // |value - expected| in standard errors.
    double deviation(const double value, const double expected, const double standard_error)
    {
      return std::abs(value - expected) / standard_error;
    }

    struct SummitStatisticsScene : Scene
    {
      // The verdict weighs deviations in standard errors of the mean: two
      // realisations at least.
      void inputs(Sections &sections) override { input.sections(sections, false, 2); }

      void entries(Entries &entries) override
      {
        power_laws.entries(entries, {8, 32}, above(1));
        entries.integer("Height bins", n_height_bins, 12u, 1u, 1000u,
                        "Bins of the summit height distribution over [-2, 4] sqrt(V). Units: none.");
        entries.number(
            "Largest deviation", largest_deviation, 4, above(0),
            "The verdict: the sampled moments, summit density and mean summit curvature lie within this "
            "many standard errors of their expectation for the sampled lattice. Units: standard errors.");
      }

      // Per realisation: the height moments m0, m2, m4, the pressure moments
      // m0, m2, m4, m22, then the packed summit sample of the pressure field.
      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        // Peak resident size, one realisation on one rank: 110 bytes a point
        // more at 2048^2 than at 1024^2.
        check_grid_memory(input.surfaces, 120, MPI_COMM_WORLD);
        const double  E_star = input.material.plane_strain_modulus();
        dealii::Timer timer;
        Table         summary({"H", "zeta", "summits", "eta sampled (1/m^2)", "eta std error (1/m^2)",
                               "eta lattice Kac-Rice (1/m^2)", "eta consistent (1/m^2)", "eta paper (1/m^2)",
                               "1/R_p sampled (Pa/m^2)", "1/R_p std error (Pa/m^2)",
                               "1/R_p lattice Kac-Rice (Pa/m^2)", "1/R_p consistent (Pa/m^2)", "1/R_p paper (Pa/m^2)",
                               "V sampled (Pa^2)", "V consistent (Pa^2)", "V paper (Pa^2)"});
        Table         screen({"H",
                              "zeta",
                              "summits",
                              {"eta/eta_cons", {4}},
                              {"+-", {1, true}},
                              {"eta_lattice/eta_cons", {4}},
                              {"eta_paper/eta_cons", {4}},
                              {"kappa/kappa_cons", {4}},
                              {"+-", {1, true}},
                              {"kappa_lattice/kappa_cons", {4}},
                              {"kappa_paper/kappa_cons", {4}}});
        Table  moments_table({"H", "zeta", "field", "moment", "sampled", "std error", "lattice expectation",
                              "continuum", "deviation (std errors)"});
        Table  heights({"H", "zeta", "z low/sqrtV", "z high/sqrtV", "summits",
                        "density per height (1/(m^2 Pa))", "density std error (1/(m^2 Pa))",
                        "density Kac-Rice at bin centre (1/(m^2 Pa))", "mean curvature (Pa/m^2)",
                        "mean curvature std error (Pa/m^2)",
                        "mean curvature Kac-Rice at bin centre (Pa/m^2)"});
        double worst = 0;
        for (const double hurst : power_laws.hurst_exponents)
          for (const double zeta : power_laws.magnifications)
            {
              const PowerSpectrum spectrum =
                  power_law_spectrum(hurst, input.roughness.q0, zeta, input.roughness.amplitude);
              const PeriodicGrid     grid = surface_grid(input.surfaces, spectrum);
              const FourierTransform transform(grid);
              const LatticeMoments   height_lattice = lattice_moments(grid, spectrum);
              const LatticeMoments   pressure_lattice =
                  lattice_moments(grid, pressure_spectrum(spectrum, E_star));
              check_summit_spectrum(
                  pressure_lattice.expected,
                  "Summit statistics/Magnifications = " + shortest(zeta) +
                      " with Random surfaces/Period L/lambda0 = " + shortest(input.surfaces.period));
              const double     sqrt_V = std::sqrt(pressure_lattice.expected.m0);
              const HeightBins bins{-2 * sqrt_V, 4 * sqrt_V, n_height_bins};

              const auto rows =
                  spread_over_ranks(MPI_COMM_WORLD, input.surfaces.n_realisations, [&](const unsigned int k) {
                    const GridField h =
                        gaussian_field(transform, spectrum, realisation_seed(input.surfaces.seed, k));
                    const GridField    p  = full_contact_pressure(transform, h, E_star);
                    const FieldMoments mh = sampled_moments(transform, h), mp = sampled_moments(transform, p);
                    std::vector<double> row = {mh.m0, mh.m2, mh.m4, mp.m0, mp.m2, mp.m4, mp.m22};
                    const auto          sample =
                        summarise_summits(find_summits(transform, p), grid.area(), bins).pack();
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
                            {"height", "m2", 1, height_lattice.expected.m2,
                             height_lattice.standard_deviation.m2, continuum.m2},
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
                  const double sampled = mean_over(rows, check.column).value,
                               error   = check.spread / std::sqrt(n);
                  const double off     = deviation(sampled, check.expected, error);
                  worst                = worse(worst, off);
                  moments_table.add_row({hurst, zeta, check.field, check.name, sampled, error, check.expected,
                                         check.continuum, off});
                }

              const ExpectedSummits lattice    = expected_summits(pressure_lattice.expected);
              const PressureSummits consistent = pressure_summits(continuum, E_star, Convention::consistent);
              const PressureSummits paper      = pressure_summits(continuum, E_star, Convention::paper);
              worst = worse(worse(worst, deviation(ensemble.density.value, lattice.density,
                                                   ensemble.density.standard_error)),
                            deviation(ensemble.mean_curvature.value, lattice.mean_curvature,
                                      ensemble.mean_curvature.standard_error));
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

        log << "Summits of the full-contact pressure p_fc over " << input.surfaces.n_realisations
            << " realisations on " << input.surfaces.n_points << "^2 grids (L = " << input.surfaces.period
            << " lambda0), " << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " rank(s), "
            << timer.wall_time() << " s wall\n"
            << "eta: summit density, kappa = 1/R_p: mean summit curvature; in units of the consistent "
               "(Nayak) values of the continuum spectrum\n";
        screen.print(log);
        log << "Tables: summit-statistics.csv, sampled-moments.csv, summit-heights.csv in "
            << results.directory().string() << "/\n";

        std::ostringstream message;
        message.precision(2);
        message << "sampled moments, summit density and mean curvature within " << worst
                << " standard errors of their lattice expectation "
                << (worst <= largest_deviation ? "<= " : "> ")
                << "Summit statistics/Largest deviation = " << largest_deviation;
        return {worst <= largest_deviation, message.str()};
      }

      RandomSurfaceInput input;
      SampledPowerLaws   power_laws;
      unsigned int       n_height_bins;
      double             largest_deviation;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      SummitStatisticsScene, "summit-statistics", "Summit statistics",
      "summits of the full-contact pressure of sampled Gaussian surfaces over realisations: moments, eta, "
      "summit heights and mean curvature 1/R_p beside the lattice expectation and both conventions",
      "")
} // namespace penny
