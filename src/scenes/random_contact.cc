// random-contact: the non-contact area of sampled random surfaces by FFT
// boundary elements against p_bar/sqrt(V), over realisations, beside the
// statistical layer's isolated-gap law in both conventions, the same law
// summed over the lattice's Kac-Rice summits, and Persson's erfc.
#include "contact/half_space.h"
#include "contact/half_space_contact.h"
#include "output/grid_fields.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "problems/contact_solver.h"
#include "problems/random_surfaces.h"
#include "problems/rough_surface.h"
#include "problems/solid.h"
#include "scenes/scene.h"
#include "statistics/contact_area.h"
#include "statistics/random_field.h"
#include "statistics/roughness.h"
#include "statistics/summit_statistics.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <sstream>

namespace penny
{
  namespace
  {
    struct RandomContactScene : Scene
    {
      void inputs(Sections &sections) override
      {
        input.sections(sections);
        contact_solver_section(sections, control, 1e-8);
        fields_section(sections, write_fields);
      }

      void entries(Entries &entries) override
      {
        entries.increasing_numbers(
            "Mean pressures", mean_pressures, {1, 1.5, 2, 2.5, 3}, 1, interval("(]", 0, 100, "sqrt(V)"),
            "p_bar/sqrt(V), V the variance of the full-contact pressure of the sampled lattice; each "
            "load a cold start. Units: sqrt(V).");
      }

      // Per realisation: the non-contact share at every load, then the iterations.
      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        // Peak resident size less that of a run that builds nothing, one
        // realisation on one rank, 1024^2 to 4096^2 points: 196 - 200 bytes a point.
        check_grid_memory(input.surfaces, 220, MPI_COMM_WORLD);
        const double           E_star   = input.material.plane_strain_modulus();
        const PowerSpectrum    spectrum = power_spectrum(input.roughness);
        const PeriodicGrid     grid     = surface_grid(input.surfaces, spectrum);
        const FourierTransform transform(grid);
        const FieldMoments     pressure = lattice_moments(grid, pressure_spectrum(spectrum, E_star)).expected;
        check_summit_spectrum(
            pressure, (input.roughness.spectrum == RoughnessParameters::Spectrum::file
                           ? "Roughness/Spectrum file = " + in_quotes(input.roughness.spectrum_file)
                           : "Roughness/Magnification zeta = " + shortest(input.roughness.zeta)) +
                          " with Random surfaces/Period L/lambda0 = " + shortest(input.surfaces.period));
        const double        sqrt_V  = std::sqrt(pressure.m0);
        const std::size_t   n_loads = mean_pressures.size();
        std::vector<double> loads;
        for (const double p : mean_pressures)
          loads.push_back(p * sqrt_V);

        dealii::Timer timer;
        const auto    rows =
            spread_over_ranks(MPI_COMM_WORLD, input.surfaces.n_realisations, [&](const unsigned int k) {
              const HalfSpaceContact contact(
                  transform, gaussian_field(transform, spectrum, realisation_seed(input.surfaces.seed, k)),
                  E_star);
              std::vector<double> row(2 * n_loads);
              const auto          steps = load_sweep(contact, loads, control);
              for (std::size_t l = 0; l < n_loads; ++l)
                {
                  row[l]           = steps[l].noncontact_fraction;
                  row[n_loads + l] = steps[l].iterations;
                }
              return row;
            });
        const double wall_time = timer.wall_time();

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
        Table table({"p_bar/sqrtV",
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
            // Far above sqrt(V) the law's gaps all close: a ratio with nothing to compare.
            const Table::Cell ratio = consistent > 0 ? Table::Cell(area.value / consistent, Table::Format{3})
                                                     : Table::Cell("law: no gaps");
            const Table::Cell error = input.surfaces.n_realisations > 1 ? Table::Cell(area.standard_error)
                                                                        : Table::Cell("one realisation");
            table.add_row({mean_pressures[l], area.value, error,
                           linear_law_noncontact_area(laws[0].gaps, loads[l] / laws[0].sqrt_V), consistent,
                           expected_gap_area(pressure, loads[l]),
                           std::erfc(mean_pressures[l] / std::sqrt(2.)), ratio,
                           mean_over(rows, n_loads + l).value});
          }

        Table summary = Table::summary();
        summary.add_row({"realisations", input.surfaces.n_realisations});
        summary.add_row({"grid", std::to_string(grid.nx) + "^2"});
        if (input.roughness.spectrum == RoughnessParameters::Spectrum::file)
          summary.add_row({"spectrum file", input.roughness.spectrum_file});
        else
          summary.add_row({"H, zeta", Table::label(input.roughness.hurst, 3) + ", " +
                                          Table::label(input.roughness.zeta, 3)});
        summary.add_row({"MPI ranks", dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
        summary.add_row({"wall time (s)", Table::Cell(wall_time, Table::Format{4})});
        summary.add_row({"sqrt(V) sampled lattice (Pa)", sqrt_V});
        summary.add_row(
            {"sqrt(V) paper/consistent/lattice", Table::label(laws[0].sqrt_V / sqrt_V, 3) + " / " +
                                                     Table::label(laws[1].sqrt_V / sqrt_V, 3) + " / 1"});
        summary.add_row({"prefactor 3 pi R_p eta sqrt(V) paper", laws[0].gaps.prefactor});
        summary.add_row({"prefactor 3 pi R_p eta sqrt(V) consistent", laws[1].gaps.prefactor});
        publish(summary, "random-contact-summary.csv", results, log,
                "Non-contact area of random surfaces by FFT boundary elements, beside the isolated-gap law "
                "(adhesionless)");
        publish(table, "random-contact.csv", results, log);
        log << "Tables: random-contact.csv, random-contact-summary.csv in " << results.directory().string()
            << "/\n";
        if (write_fields)
          write_first_realisation(transform, spectrum, E_star, loads, results);
        return {};
      }

      // The first realisation for ParaView (surface.vti): its heights, its
      // full-contact pressure and its gap at every load. Each rank solves it
      // (the write is collective; rank 0's counts).
      void write_first_realisation(const FourierTransform &transform, const PowerSpectrum &spectrum,
                                   const double E_star, const std::vector<double> &loads,
                                   const ResultFolder &results) const
      {
        const HalfSpaceContact contact(
            transform, gaussian_field(transform, spectrum, realisation_seed(input.surfaces.seed, 0)), E_star);
        const GridField        full_contact = full_contact_pressure(transform, contact.heights(), E_star);
        std::vector<GridField> gaps;
        for (const double load : loads)
          gaps.push_back(contact.solve(load, control).gap);
        std::vector<GridFieldOutput> fields{{"height (m)", &contact.heights()},
                                            {"full-contact pressure less its mean (Pa)", &full_contact}};
        for (std::size_t l = 0; l < loads.size(); ++l)
          fields.push_back(
              {"gap at p_bar = " + Table::label(mean_pressures[l], 4) + " sqrt(V) (m)", &gaps[l]});
        const PeriodicGrid &grid = transform.grid();
        write_grid_fields("surface", grid.nx, grid.ny, grid.lx / grid.nx, grid.ly / grid.ny, fields, results);
      }

      RandomSurfaceInput   input;
      std::vector<double>  mean_pressures; // p_bar/sqrt(V)
      ContactSolverControl control;
      bool                 write_fields;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      RandomContactScene, "random-contact", "Random contact",
      "A_nc/A_0 of sampled random surfaces by FFT boundary elements against p_bar/sqrt(V), beside the "
      "isolated-gap law in both conventions and Persson's erfc",
      "")
} // namespace penny
