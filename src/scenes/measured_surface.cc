// measured-surface: a measured topography read from its instrument's file and
// prepared (points not measured filled, a trend removed), with its rms
// height, slope and curvature, its isotropic PSD and the power law fitted to
// it over the range the map resolves, and its adhesionless contact with an
// elastic half-space at a few loads, the map taken as one period (the
// periodic solver) and as an isolated patch (the non-periodic one) side by
// side (doc/measured.md). No verdict: it states what the surface is and how
// much the choice of boundary moves its contact.
#include "problems/measured_surface.h"
#include "contact/half_space.h"
#include "contact/nonperiodic_contact.h"
#include "fourier/grid_resampling.h"
#include "output/grid_fields.h"
#include "output/table.h"
#include "parallel/memory_budget.h"
#include "problems/contact_solver.h"
#include "problems/solid.h"
#include "scenes/scene.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cmath>

namespace penny
{
  namespace
  {
    struct MeasuredSurfaceScene : Scene
    {
      void inputs(Sections &sections) override
      {
        measured_surface_section(sections, input);
        material_section(sections, material);
        contact_solver_section(sections, control, 1e-8);
        fields_section(sections, write_fields);
      }

      void entries(Entries &entries) override
      {
        entries.increasing_numbers(
            "Mean pressures", mean_pressures, {0.5, 1, 2, 3}, 1, interval("(]", 0, 100, "sqrt(V)"),
            "p_bar/sqrt(V) of the contacts, V = <p_fc^2> the variance of the full-contact pressure of "
            "the prepared map taken as one period. Units: sqrt(V).");
        entries.integer("Refinement", refinement, 1u, 1u, 64u,
                        "1: the contacts on the map's own grid, as a period and as a patch. r > 1: the map's "
                        "Fourier series sampled on a grid r times finer in each direction (no roughness "
                        "added below the pixel), its periodic contact alone, the grid split over the MPI "
                        "ranks, with the peak memory of each rank. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        const Topography       topography = prepared_topography(input, log);
        const PeriodicGrid    &grid       = topography.grid;
        const SurfaceRoughness rms        = surface_roughness(topography);
        const PowerSpectrum    psd        = isotropic_spectrum(topography, input.hann_window);
        const WavenumberRange  range      = reliable_range(topography);
        const PowerLawFit      fit        = fit_power_law(psd, range);

        Table summary = Table::summary();
        summary.add_row({"points nx x ny", std::to_string(grid.nx) + " x " + std::to_string(grid.ny)});
        summary.add_row({"size lx (m)", grid.lx});
        summary.add_row({"size ly (m)", grid.ly});
        summary.add_row({"pixel dx (m)", grid.lx / grid.nx});
        summary.add_row({"pixel dy (m)", grid.ly / grid.ny});
        summary.add_row({"rms height (m)", rms.rms_height});
        summary.add_row({"rms slope", rms.rms_slope});
        summary.add_row({"rms curvature (1/m)", rms.rms_curvature});
        summary.add_row({"PSD fit: q_low (1/m)", fit.q_low});
        summary.add_row({"PSD fit: q_high (1/m)", fit.q_high});
        summary.add_row({"PSD fit: bins", fit.n_bins});
        const bool fitted       = fit.n_bins >= 3;
        const auto fitted_value = [&](const double value) -> Table::Cell {
          return fitted ? Table::Cell(value) : Table::Cell("not fitted (fewer than 3 bins)");
        };
        summary.add_row({"PSD fit: H", fitted_value(fit.hurst)});
        summary.add_row({"PSD fit: C at q_low (m^4)", fitted_value(fit.c0)});
        summary.add_row({"PSD fit: R^2 of log C", fitted_value(fit.r_squared)});
        summary.add_row({"PSD fit: rms of log10(C/fit)", fitted_value(fit.rms_log_deviation)});
        publish(summary, "measured-surface.csv", results, log,
                "The prepared surface (rms slope: forward differences; rms curvature: half the rms of the "
                "five-point Laplacian; the PSD fitted from half the shorter side to four pixels)");

        Table spectrum({"q (1/m)", "C (m^4)", "power-law fit (m^4)", "fitted"});
        for (std::size_t k = 0; k < psd.wavenumbers.size(); ++k)
          {
            const double q = psd.wavenumbers[k];
            spectrum.add_row({q, psd.densities[k],
                              fitted_value(fit.c0 * std::pow(q / fit.q_low, -2 * (1 + fit.hurst))),
                              fitted && q >= range.q_low && q <= range.q_high ? "yes" : "no"});
          }
        results.write_csv("measured-surface-psd.csv", spectrum);

        if (refinement > 1)
          {
            refined_contact(topography, results, log);
            if (write_fields)
              write_grid_fields("surface", grid.nx, grid.ny, grid.lx / grid.nx, grid.ly / grid.ny,
                                {{"height (m)", &topography.heights}}, results);
            return {};
          }

        // The contacts: the map as one period, and as an isolated patch.
        const double           E_star = material.plane_strain_modulus();
        const FourierTransform transform(grid);
        double                 V = 0;
        for (const double p : full_contact_pressure(transform, topography.heights, E_star))
          V += p * p / grid.n_points();
        const HalfSpaceContact       periodic(transform, topography.heights, E_star);
        const NonperiodicContact     isolated(grid, topography.heights, E_star);
        Table                        contact({"p_bar/sqrtV",
                                              "p_bar (Pa)",
                                              {"A_nc/A_0 periodic", {6}},
                                              {"A_nc/A_0 patch", {6}},
                                              "iterations periodic",
                                              "iterations patch"});
        std::vector<GridField>       gaps;
        std::vector<GridFieldOutput> fields = {{"height (m)", &topography.heights}};
        gaps.reserve(2 * mean_pressures.size());
        for (const double load : mean_pressures)
          {
            const double              p_bar = load * std::sqrt(V);
            const ContactSolution     cell  = periodic.solve(p_bar, control);
            const NonperiodicSolution patch = isolated.solve(p_bar, control);
            contact.add_row({load, p_bar, 1 - cell.contact_fraction, 1 - patch.contact_fraction,
                             cell.iterations, patch.iterations});
            gaps.push_back(cell.gap);
            gaps.push_back(patch.separation);
            const std::string at = " at p_bar = " + Table::label(load, 4) + " sqrt(V) (m)";
            fields.push_back({"gap periodic" + at, &gaps[gaps.size() - 2]});
            fields.push_back({"gap patch" + at, &gaps.back()});
          }
        log << '\n';
        publish(contact, "measured-surface-contact.csv", results, log,
                "Adhesionless contact, E* = " + Table::label(E_star) +
                    " Pa, sqrt(V) = " + Table::label(std::sqrt(V)) +
                    " Pa: the map as one period, and as an isolated patch (DC-FFT)");

        if (write_fields)
          write_grid_fields("surface", grid.nx, grid.ny, grid.lx / grid.nx, grid.ly / grid.ny, fields,
                            results);
        log << "Tables: " << results.directory().string()
            << "/measured-surface.csv, measured-surface-psd.csv, measured-surface-contact.csv"
            << (write_fields ? "; fields: surface.pvd" : "") << '\n';
        return {};
      }

      // The periodic contact of the map resampled on a grid `refinement` times
      // finer, split over the ranks, and the peak memory of each rank.
      void refined_contact(const Topography &topography, const ResultFolder &results, std::ostream &log) const
      {
        const MPI_Comm      world = MPI_COMM_WORLD;
        const PeriodicGrid &grid  = topography.grid;
        const PeriodicGrid  fine_grid{grid.nx * refinement, grid.ny * refinement, grid.lx, grid.ly};
        // Peak resident size of random-contact's split solver, measured: 220 bytes a point of a rank's share.
        const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(world);
        check_memory_need(220. * fine_grid.n_points() / ranks,
                          "Measured contact/Refinement = " + std::to_string(refinement) + ": " +
                              std::to_string(fine_grid.nx) + " x " + std::to_string(fine_grid.ny) +
                              " points need about",
                          world);
        const FourierTransform coarse(grid, Planning::estimate, world),
            fine(fine_grid, Planning::estimate, world);
        const GridField rows(topography.heights.begin() + std::size_t(coarse.first_row()) * grid.ny,
                             topography.heights.begin() +
                                 std::size_t(coarse.first_row() + coarse.n_rows()) * grid.ny);
        const GridField heights = resampled(coarse, fine, rows);
        const double    E_star  = material.plane_strain_modulus();
        double          squares = 0;
        for (const double p : full_contact_pressure(fine, heights, E_star))
          squares += p * p;
        const double           sqrt_V = std::sqrt(fine.sum(squares) / fine_grid.n_points());
        const HalfSpaceContact contact(fine, heights, E_star);
        Table contact_table({"p_bar/sqrtV", "p_bar (Pa)", {"A_nc/A_0 periodic", {6}}, "iterations periodic"});
        for (const double load : mean_pressures)
          {
            const ContactSolution cell = contact.solve(load * sqrt_V, control);
            contact_table.add_row({load, load * sqrt_V, 1 - cell.contact_fraction, cell.iterations});
          }
        dealii::Utilities::System::MemoryStats memory;
        dealii::Utilities::System::get_memory_stats(memory);
        const std::vector<double> peaks   = dealii::Utilities::MPI::all_gather(world, memory.VmHWM / 1024.);
        Table                     summary = Table::summary();
        summary.add_row({"grid", std::to_string(fine_grid.nx) + " x " + std::to_string(fine_grid.ny)});
        summary.add_row({"sqrt(V) (Pa)", sqrt_V});
        log << '\n';
        publish(contact_table, "measured-surface-contact.csv", results, log,
                "Adhesionless contact of the map as one period, resampled " + std::to_string(refinement) +
                    " times finer (E* = " + Table::label(E_star) + " Pa)");
        publish(summary, "measured-surface-refined.csv", results, log);
        log << "Peak memory of each of the " << ranks << " rank(s) (MiB):";
        for (const double peak : peaks)
          log << ' ' << Table::label(peak, 5);
        log << "\nTables: " << results.directory().string()
            << "/measured-surface.csv, measured-surface-psd.csv, measured-surface-contact.csv, "
               "measured-surface-refined.csv\n";
      }

      MeasuredSurfaceInput input;
      MaterialParameters   material;
      ContactSolverControl control;
      std::vector<double>  mean_pressures; // p_bar/sqrt(V)
      unsigned int         refinement;
      bool                 write_fields;
    };
  } // namespace

  PENNY_REGISTER_SCENE(MeasuredSurfaceScene, "measured-surface", "Measured contact",
                       "a measured topography file read and prepared: its rms height, slope and curvature, "
                       "its isotropic PSD, a fitted power law, and its contact as a period and as a patch",
                       "")
} // namespace penny
