// measured-surface: a measured topography read from its instrument's file and
// prepared (points not measured filled, a trend removed), with its rms
// height, slope and curvature, its isotropic PSD and the power law fitted to
// it over the range the map resolves (doc/measured.md). No verdict: it states
// what the surface is, for the scenes that put it in contact.
#include "problems/measured_surface.h"
#include "output/grid_fields.h"
#include "output/table.h"
#include "scenes/scene.h"

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
        fields_section(sections, write_fields);
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
        summary.add_row({"PSD fit: H", fit.hurst});
        summary.add_row({"PSD fit: C at q_low (m^4)", fit.c0});
        summary.add_row({"PSD fit: q_low (1/m)", fit.q_low});
        summary.add_row({"PSD fit: q_high (1/m)", fit.q_high});
        summary.add_row({"PSD fit: bins", fit.n_bins});
        summary.add_row({"PSD fit: R^2 of log C", fit.r_squared});
        summary.add_row({"PSD fit: rms of log10(C/fit)", fit.rms_log_deviation});
        publish(summary, "measured-surface.csv", results, log,
                "The prepared surface (rms slope: forward differences; rms curvature: half the rms of the "
                "five-point Laplacian; the PSD fitted from half the shorter side to four pixels)");

        Table spectrum({"q (1/m)", "C (m^4)", "power-law fit (m^4)", "fitted"});
        for (std::size_t k = 0; k < psd.wavenumbers.size(); ++k)
          {
            const double q = psd.wavenumbers[k];
            spectrum.add_row({q, psd.densities[k], fit.c0 * std::pow(q / fit.q_low, -2 * (1 + fit.hurst)),
                              q >= range.q_low && q <= range.q_high ? "yes" : "no"});
          }
        results.write_csv("measured-surface-psd.csv", spectrum);

        if (write_fields)
          write_grid_fields("surface", grid.nx, grid.ny, grid.lx / grid.nx, grid.ly / grid.ny,
                            {{"height (m)", &topography.heights}}, results);
        log << "Tables: " << results.directory().string() << "/measured-surface.csv, measured-surface-psd.csv"
            << (write_fields ? "; fields: surface.pvd" : "") << '\n';
        return {};
      }

      MeasuredSurfaceInput input;
      bool                 write_fields;
    };
  } // namespace

  PENNY_REGISTER_SCENE(MeasuredSurfaceScene, "measured-surface", "",
                       "a measured topography file read and prepared: its rms height, slope and curvature, "
                       "its isotropic PSD and a fitted power law",
                       "")
} // namespace penny
