// measured-adhesion: the paper's adhesive claims on a measured surface and
// on its Gaussian twins (doc/measured.md, "Adhesion on a measured surface").
// The prepared map taken as one period, and its twins (its Fourier amplitudes
// with random phases), each solved by the adhesive boundary-element solver at
// several cohesive zones (the map's Fourier series resampled on grids fine
// enough for each) and extrapolated to the JKR limit, on the loading path from
// first contact and with adhesion switched on at each load (as
// adhesive-random-contact does on synthetic surfaces), beside the adhesionless
// solution at p_bar and at p_bar + p0. p0 = psi (K_Ic^4/R_p)^(1/5) takes R_p
// from the summits of each surface's tension: the map's own, and for the
// twins Kac-Rice's from the map's moments; K_Ic (the work of adhesion) is the
// one that gives the map p0/sqrt(V) = 'Adhesion p0/sqrt(V)'. Judged: claim 1
// (adhesion acts as the extra pressure p0) and, where p0/sqrt(V) >= 4, full
// contact at zero load. The magnification claim needs several magnifications
// of one surface and is not judged on one map. No verdict of the run: the
// claims are the paper's.
#include "closed_forms/adhesive_gap.h"
#include "contact/half_space.h"
#include "fourier/grid_resampling.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "problems/adhesive_random_surfaces.h"
#include "problems/contact_solver.h"
#include "problems/measured_surface.h"
#include "problems/random_surfaces.h"
#include "problems/solid.h"
#include "scenes/scene.h"
#include "statistics/random_field.h"
#include "statistics/summit_statistics.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <tuple>

namespace penny
{
  namespace
  {
    // The least power of two at or above x.
    unsigned int power_of_two_at_least(const double x)
    {
      unsigned int p = 1;
      while (p < x)
        p *= 2;
      return p;
    }

    std::string value_with_error(const double value, const double error)
    {
      return Table::label(value, 4) + (std::isfinite(error) ? " +- " + Table::label(error, 2) : "");
    }

    struct MeasuredAdhesionScene : Scene
    {
      void inputs(Sections &sections) override
      {
        measured_surface_section(sections, input);
        material_section(sections, material);
        contact_solver_section(sections, control, 1e-8);
      }

      void entries(Entries &entries) override
      {
        entries.number("Adhesion p0/sqrt(V)", adhesion_ratio, 1, interval("[]", 0.01, 20),
                       "p0/sqrt(V) of the map (R_p from its summits): fixes the work of adhesion of the map "
                       "and of its twins. Units: none.");
        entries.increasing_numbers("Mean pressures", mean_pressures, {0, 0.5, 1, 2}, 1,
                                   interval("[]", 0, 100, "sqrt(V)"),
                                   "p_bar/sqrt(V): the states of the loading path. Units: sqrt(V).");
        entries.number("First contact load", first_contact, 0.25, interval("(]", 0, 100, "sqrt(V)"),
                       "p_s/sqrt(V): first pressed together without adhesion at p_s, then adhesion, then "
                       "the mean pressures in increasing order. Units: sqrt(V).");
        zones.entries(entries, "lambda1", {{2, 1, 0.5}, 4}, 2, interval("[]", 1e-2, 10),
                      "lambda1 = 2 max(dx, dy), the shortest wavelength the map holds; each zone's grid is "
                      "the map's refined by the least power of two that puts the points over l_pz.");
        entries.integer("Twin realisations", n_twins, 4u, 2u, 10000u,
                        "Gaussian twins of the map, spread over the MPI ranks with the map. Units: none.");
        entries.integer("Seed", seed, 1u, 0u, 4294967295u, "The twins' random seed. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        dealii::Timer          timer;
        const Topography       topography = prepared_topography(input, log);
        const PeriodicGrid    &grid       = topography.grid;
        const double           E_star     = material.plane_strain_modulus();
        const FourierTransform base(grid);
        const double           shortest  = 2 * std::max(grid.lx / grid.nx, grid.ly / grid.ny);
        const auto             zone_grid = [&](const double zone) {
          const unsigned int r = power_of_two_at_least(zones.points_per_zone / (2 * zone));
          return PeriodicGrid{grid.nx * r, grid.ny * r, grid.lx, grid.ly};
        };
        const PeriodicGrid finest = zone_grid(zones.lengths.back());
        check_grid_memory(
            std::sqrt(double(finest.n_points())), 180,
            "Measured adhesion/Cohesive zones l_pz/lambda1 = " + shortest_text(zones.lengths.back()) +
                " with Points per cohesive zone = " + shortest_text(zones.points_per_zone),
            MPI_COMM_WORLD);

        // The scale V, the map's summits and the twins' expected ones.
        GridField          tension = full_contact_pressure(base, topography.heights, E_star);
        const FieldMoments moments = sampled_moments(base, tension);
        check_summit_spectrum(moments, "Measured surface/File = " + in_quotes(input.file));
        for (double &t : tension)
          t = -t;
        double                    curvature = 0;
        const std::vector<Summit> summits   = find_summits(base, tension);
        for (const Summit &summit : summits)
          curvature += summit.mean_curvature() / summits.size();
        const double sqrt_V = std::sqrt(moments.m0);
        // p0 grows like K_Ic^(4/5): the K_Ic of the map's p0/sqrt(V).
        const double R_map = 1 / curvature, R_twins = 1 / expected_summits(moments).mean_curvature;
        const double K_Ic =
            std::pow(adhesion_ratio * sqrt_V / (closed_form::psi * adhesion_tension(R_map, 1)), 1.25);
        const auto surfaces = [&](const double R_p) {
          return AdhesiveRandomSurfaces{{},
                                        E_star,
                                        K_Ic,
                                        sqrt_V,
                                        closed_form::psi * adhesion_tension(R_p, K_Ic),
                                        mean_pressures,
                                        first_contact,
                                        zones,
                                        control};
        };
        const AdhesiveRandomSurfaces map = surfaces(R_map), twins = surfaces(R_twins);

        const auto        rows    = spread_over_ranks(MPI_COMM_WORLD, n_twins + 1, [&](const unsigned int k) {
          const GridField heights =
              k == 0 ? topography.heights
                               : gaussian_twin(base, topography.heights, realisation_seed(seed, k - 1));
          return solve_surface(k == 0 ? map : twins, base, heights, shortest, zone_grid).pack();
        });
        const std::size_t n_zones = zones.lengths.size(), n_loads = mean_pressures.size();
        std::vector<RealisationAreas> map_areas = {RealisationAreas::unpack(rows[0], n_zones, n_loads)},
                                      twin_areas;
        for (unsigned int k = 1; k <= n_twins; ++k)
          twin_areas.push_back(RealisationAreas::unpack(rows[k], n_zones, n_loads));
        log << "Solved the map and " << n_twins << " twins in " << Table::label(timer.wall_time(), 4)
            << " s (zones' grids up to " << finest.nx << " x " << finest.ny << ")\n";

        std::vector<std::string> zone_columns;
        for (const double zone : zones.lengths)
          zone_columns.push_back("l_pz/lambda1 = " + Table::label(zone));
        std::vector<Table::Column> columns = {"surface", "p0/sqrtV", "p_bar/sqrtV", "branch"};
        columns.insert(columns.end(), zone_columns.begin(), zone_columns.end());
        for (const char *name : {"JKR limit", "std error", "extrapolation error", "adhesionless at p_bar",
                                 "adhesionless at p_bar + p0", "JKR limit/adhesionless at p_bar + p0",
                                 "isolated gaps with adhesion"})
          columns.emplace_back(name);
        Table table(columns),
            claims({"claim", "surface", "branch", "p_bar/sqrtV", "measured", "the paper", "verdict"});
        for (const auto &[name, areas, s] : {std::tuple{"measured map", &map_areas, &map},
                                             std::tuple{"Gaussian twins", &twin_areas, &twins}})
          {
            const double ratio = s->p0 / sqrt_V;
            for (const auto branch : {&RealisationAreas::loading, &RealisationAreas::switched_on})
              {
                const char *branch_name = branch == &RealisationAreas::loading ? "loading" : "switched on";
                std::vector<double> loads, measured;
                bool                within = true;
                for (std::size_t j = 0; j < n_loads; ++j)
                  {
                    const JkrLimit limit = jkr_limit(*areas, branch, j, zones.lengths);
                    if (std::isnan(limit.value.value))
                      continue;
                    std::vector<std::vector<double>> values;
                    for (const auto &a : *areas)
                      values.push_back({a.adhesionless[j], a.shifted[j], a.isolated_gaps[j]});
                    const Estimate free = mean_over(values, 0), shifted = mean_over(values, 1);
                    // One map has no scatter: its error is the extrapolation's alone.
                    const double spread          = areas->size() > 1 ? limit.value.standard_error : 0,
                                 shifted_spread  = areas->size() > 1 ? shifted.standard_error : 0;
                    std::vector<Table::Cell> row = {name, ratio, mean_pressures[j], branch_name};
                    row.insert(row.end(), limit.means.begin(), limit.means.end());
                    for (const double cell :
                         {limit.value.value, spread, limit.extrapolation_error, free.value, shifted.value})
                      row.emplace_back(cell);
                    row.emplace_back(shifted.value > 0
                                         ? Table::Cell(limit.value.value / shifted.value, Table::Format{4})
                                         : Table::Cell("adhesionless: no gaps"));
                    row.emplace_back(mean_over(values, 2).value);
                    table.add_row(row);
                    if (shifted.value > 0)
                      {
                        loads.push_back(mean_pressures[j]);
                        measured.push_back(limit.value.value / shifted.value);
                        within &= std::abs(limit.value.value - shifted.value) <=
                                  2 * std::hypot(spread, shifted_spread) + limit.extrapolation_error;
                      }
                    if (j == 0 && mean_pressures[0] == 0 && branch == &RealisationAreas::loading &&
                        ratio >= 4)
                      claims.add_row({"full contact at zero load for p0/sqrt(V) = " + Table::label(ratio, 3),
                                      name, branch_name, "0",
                                      "A_nc(0)/A_0 = " + value_with_error(limit.value.value, spread),
                                      "about 0",
                                      limit.value.value <= 2 * spread + limit.extrapolation_error
                                          ? "holds within the error bars"
                                          : "fails"});
                  }
                std::string loads_text, ratios_text;
                for (std::size_t k = 0; k < loads.size(); ++k)
                  {
                    loads_text += (k ? ", " : "") + Table::label(loads[k], 3);
                    ratios_text += (k ? ", " : "") + Table::label(measured[k], 3);
                  }
                claims.add_row(
                    {"A_nc(p_bar) = adhesionless A_nc(p_bar + p0), p0/sqrt(V) = " + Table::label(ratio, 3),
                     name, branch_name, loads_text,
                     loads.empty() ? "no load with gaps" : "ratio " + ratios_text, "ratio 1",
                     loads.empty() ? "not tested"
                     : within      ? "holds within the error bars"
                                   : "fails"});
              }
          }
        claims.add_row({"the share of the area adhesion closes grows or falls with magnification as "
                        "theta = (2/5)(2H - 1) says",
                        "measured map", "", "", "one magnification", "",
                        "not judged: one map has one magnification"});
        publish(table, "measured-adhesion.csv", results, log,
                "Adhesive contact of the measured map and its Gaussian twins: A_nc/A_0 at each cohesive zone "
                "and in "
                "the JKR limit, beside the adhesionless solution at p_bar and p_bar + p0");
        log << '\n';
        publish(claims, "measured-adhesion-claims.csv", results, log,
                "The paper's adhesive claims on this surface");
        log << "Tables: " << results.directory().string()
            << "/measured-adhesion.csv, measured-adhesion-claims.csv\n";
        return {};
      }

      static std::string shortest_text(const double value) { return Table::label(value); }

      MeasuredSurfaceInput input;
      MaterialParameters   material;
      ContactSolverControl control;
      double               adhesion_ratio, first_contact;
      std::vector<double>  mean_pressures; // p_bar/sqrt(V)
      CohesiveZones        zones;          // l_pz/lambda1
      unsigned int         n_twins;
      unsigned int         seed;
    };
  } // namespace

  PENNY_REGISTER_SCENE(MeasuredAdhesionScene, "measured-adhesion", "Measured adhesion",
                       "the paper's adhesive claims on a measured surface and its Gaussian twins, by the "
                       "adhesive BEM in the JKR limit",
                       "")
} // namespace penny
