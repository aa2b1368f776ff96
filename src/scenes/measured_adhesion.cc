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
// (adhesion acts as the extra pressure p0), where p0/sqrt(V) >= 4 full
// contact at zero load, and, over 'Magnification fractions' (the map
// low-passed at several short-wavelength cut-offs, one work of adhesion),
// whether the share of the area adhesion closes moves with magnification as
// the sign of theta = (2/5)(2H - 1) says, H from the map's PSD fit. No
// verdict of the run: the claims are the paper's.
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

#include <array>
#include <cmath>
#include <tuple>

namespace penny
{
  namespace
  {
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
        zones.entries(
            entries, "lambda1", {{2, 1, 0.5}, 4}, 2, interval("[]", 1e-2, 10),
            "lambda1 = 2 pi/q1, the shortest wavelength the surface holds (2 max(dx, dy) at f = 1); "
            "each zone's grid is the map's refined by the least power of two that puts the points over "
            "l_pz.");
        entries.increasing_numbers(
            "Magnification fractions", fractions, {1}, 1, interval("(]", 0, 1),
            "Each magnification's surface is the map low-passed at q1 = f pi/max(dx, dy): f = 1 the map as "
            "measured, smaller f fewer short wavelengths (zeta = q1/q0, q0 = 2 pi/max(lx, ly)); the work of "
            "adhesion is the first one's. Units: none.");
        entries.integer("Twin realisations", n_twins, 4u, 2u, 10000u,
                        "Gaussian twins of the map, spread over the MPI ranks with the map. Units: none.");
        entries.integer("Seed", seed, 1u, 0u, 4294967295u, "The twins' random seed. Units: none.");
      }

      // One magnification: the map low-passed at q1 (zeta = q1/q0, q0 = 2 pi/max(lx, ly)), its
      // twins, and what the adhesive solver found on them.
      struct Case
      {
        double                        zeta, shortest; // lambda1 = 2 pi/q1 (m)
        GridField                     heights;
        double                        sqrt_V, R_map, R_twins;
        AdhesiveRandomSurfaces        map, twins;
        std::vector<RealisationAreas> map_areas, twin_areas;
      };

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        dealii::Timer          timer;
        const Topography       topography = prepared_topography(input, log);
        const PeriodicGrid    &grid       = topography.grid;
        const double           E_star     = material.plane_strain_modulus();
        const FourierTransform base(grid);
        const double           pixel = std::max(grid.lx / grid.nx, grid.ly / grid.ny);
        const double           q0 = 2 * M_PI / std::max(grid.lx, grid.ly), q_max = M_PI / pixel;
        const auto             zone_grid = [&](const double zone, const double shortest) {
          const unsigned int r = power_of_two_at_least(zones.points_per_zone * pixel / (zone * shortest));
          return PeriodicGrid{grid.nx * r, grid.ny * r, grid.lx, grid.ly};
        };
        const PeriodicGrid finest = zone_grid(zones.lengths.back(), 2 * pixel);
        check_grid_memory(
            std::sqrt(double(finest.n_points())), 180,
            "Measured adhesion/Cohesive zones l_pz/lambda1 = " + shortest_text(zones.lengths.back()) +
                " with Points per cohesive zone = " + shortest_text(zones.points_per_zone),
            MPI_COMM_WORLD);

        // Each magnification's surface, its scale V and summits: the map's own
        // and, for the twins, Kac-Rice's from its moments.
        std::vector<Case> cases;
        for (const double fraction : fractions)
          {
            Case one;
            one.zeta                         = fraction * q_max / q0;
            one.shortest                     = 2 * pixel / fraction;
            FourierTransform::Spectrum modes = base.forward(topography.heights);
            for (std::size_t c = 0; c < modes.size(); ++c)
              if (base.wavevector(c).norm() > fraction * q_max * (1 + 1e-12))
                modes[c] = 0;
            one.heights                  = base.inverse(modes);
            const TensionSummits tension = tension_summits(base, one.heights, E_star);
            const FieldMoments  &moments = tension.moments;
            check_summit_spectrum(moments,
                                  "Measured adhesion/Magnification fractions = " + shortest_text(fraction) +
                                      " with Measured surface/File = " + in_quotes(input.file));
            one.sqrt_V  = std::sqrt(moments.m0);
            one.R_map   = 1 / tension.mean_curvature;
            one.R_twins = 1 / expected_summits(moments).mean_curvature;
            cases.push_back(one);
          }
        // One work of adhesion for all: the K_Ic that gives the first magnification's map its p0/sqrt(V)
        // (p0 grows like K_Ic^(4/5)).
        const double K_Ic = std::pow(adhesion_ratio * cases[0].sqrt_V /
                                         (closed_form::psi * adhesion_tension(cases[0].R_map, 1)),
                                     1.25);
        for (Case &one : cases)
          for (auto [surfaces, R_p] : {std::pair{&one.map, one.R_map}, std::pair{&one.twins, one.R_twins}})
            *surfaces = {{},
                         E_star,
                         K_Ic,
                         one.sqrt_V,
                         closed_form::psi * adhesion_tension(R_p, K_Ic),
                         mean_pressures,
                         first_contact,
                         zones,
                         control};

        const unsigned int per_case = n_twins + 1;
        const auto         rows =
            spread_over_ranks(MPI_COMM_WORLD, cases.size() * per_case, [&](const unsigned int piece) {
              const Case        &one = cases[piece / per_case];
              const unsigned int k   = piece % per_case;
              const GridField    heights =
                  k == 0 ? one.heights : gaussian_twin(base, one.heights, realisation_seed(seed, k - 1));
              return solve_surface(k == 0 ? one.map : one.twins, base, heights, one.shortest,
                                   [&](const double zone) { return zone_grid(zone, one.shortest); })
                  .pack();
            });
        const std::size_t n_zones = zones.lengths.size(), n_loads = mean_pressures.size();
        for (std::size_t c = 0; c < cases.size(); ++c)
          for (unsigned int k = 0; k < per_case; ++k)
            (k == 0 ? cases[c].map_areas : cases[c].twin_areas)
                .push_back(RealisationAreas::unpack(rows[c * per_case + k], n_zones, n_loads));
        log << "Solved the map and " << n_twins << " twins at " << cases.size() << " magnification(s) in "
            << Table::label(timer.wall_time(), 4) << " s (zones' grids up to " << finest.nx << " x "
            << finest.ny << ")\n";

        std::vector<Table::Column> columns = {"surface", "zeta", "p0/sqrtV", "p_bar/sqrtV", "branch"};
        for (const double zone : zones.lengths)
          columns.emplace_back("l_pz/lambda1 = " + Table::label(zone));
        for (const char *name : {"JKR limit", "std error", "extrapolation error", "adhesionless at p_bar",
                                 "adhesionless at p_bar + p0", "JKR limit/adhesionless at p_bar + p0",
                                 "isolated gaps with adhesion"})
          columns.emplace_back(name);
        Table table(columns),
            claims({"claim", "surface", "branch", "zeta", "p_bar/sqrtV", "measured", "the paper", "verdict"});
        const auto error_bar = [](const std::vector<RealisationAreas> &areas, const JkrLimit &limit,
                                  const Estimate &other) {
          // One map has no scatter: its error is the extrapolation's alone.
          return areas.size() > 1 ? 2 * std::hypot(limit.value.standard_error, other.standard_error) +
                                        limit.extrapolation_error
                                  : limit.extrapolation_error;
        };
        const auto adhesionless = [&](const std::vector<RealisationAreas> &areas, const std::size_t j,
                                      const std::size_t column) {
          std::vector<std::vector<double>> values;
          for (const auto &a : areas)
            values.push_back({a.adhesionless[j], a.shifted[j], a.isolated_gaps[j]});
          return mean_over(values, column);
        };
        for (const Case &one : cases)
          for (const auto &[name, areas, s] : {std::tuple{"measured map", &one.map_areas, &one.map},
                                               std::tuple{"Gaussian twins", &one.twin_areas, &one.twins}})
            {
              const double ratio = s->p0 / one.sqrt_V;
              for (const auto branch : {&RealisationAreas::loading, &RealisationAreas::switched_on})
                {
                  const char *branch_name = branch == &RealisationAreas::loading ? "loading" : "switched on";
                  std::string loads_text, ratios_text;
                  bool        within = true, tested = false;
                  for (std::size_t j = 0; j < n_loads; ++j)
                    {
                      const JkrLimit limit = jkr_limit(*areas, branch, j, zones.lengths);
                      if (std::isnan(limit.value.value))
                        continue;
                      const Estimate free = adhesionless(*areas, j, 0), shifted = adhesionless(*areas, j, 1);
                      std::vector<Table::Cell> row = {name, one.zeta, ratio, mean_pressures[j], branch_name};
                      row.insert(row.end(), limit.means.begin(), limit.means.end());
                      for (const double cell :
                           {limit.value.value, areas->size() > 1 ? limit.value.standard_error : 0.,
                            limit.extrapolation_error, free.value, shifted.value})
                        row.emplace_back(cell);
                      row.emplace_back(shifted.value > 0
                                           ? Table::Cell(limit.value.value / shifted.value, Table::Format{4})
                                           : Table::Cell("adhesionless: no gaps"));
                      row.emplace_back(adhesionless(*areas, j, 2).value);
                      table.add_row(row);
                      if (shifted.value > 0)
                        {
                          loads_text += (tested ? ", " : "") + Table::label(mean_pressures[j], 3);
                          ratios_text +=
                              (tested ? ", " : "") + Table::label(limit.value.value / shifted.value, 3);
                          tested = true;
                          within &= std::abs(limit.value.value - shifted.value) <=
                                    error_bar(*areas, limit, shifted);
                        }
                      if (j == 0 && mean_pressures[0] == 0 && branch == &RealisationAreas::loading &&
                          ratio >= 4)
                        claims.add_row(
                            {"full contact at zero load for p0/sqrt(V) = " + Table::label(ratio, 3), name,
                             branch_name, Table::label(one.zeta, 4), "0",
                             "A_nc(0)/A_0 = " +
                                 value_with_error(limit.value.value,
                                                  areas->size() > 1 ? limit.value.standard_error : 0),
                             "about 0",
                             limit.value.value <= error_bar(*areas, limit, {0, 0})
                                 ? "holds within the error bars"
                                 : "fails"});
                    }
                  claims.add_row(
                      {"A_nc(p_bar) = adhesionless A_nc(p_bar + p0), p0/sqrt(V) = " + Table::label(ratio, 3),
                       name, branch_name, Table::label(one.zeta, 4), loads_text,
                       tested ? "ratio " + ratios_text : "no load with gaps", "ratio 1",
                       !tested  ? "not tested"
                       : within ? "holds within the error bars"
                                : "fails"});
                }
            }

        // With magnification at fixed w: the share of the adhesionless
        // non-contact area that adhesion closes, 1 - A_nc/A_nc(adhesionless),
        // from the first to the last zeta, at the first load above zero where
        // every zeta has gaps without adhesion (the loading branch).
        const double theta = 0.4 * (2 * hurst_of(topography) - 1);
        for (const auto areas : {&Case::map_areas, &Case::twin_areas})
          {
            const char *name       = areas == &Case::map_areas ? "measured map" : "Gaussian twins";
            std::size_t j          = 0;
            const auto  comparable = [&](const std::size_t load) {
              if (!(mean_pressures[load] > 0)) // no contact without adhesion to close
                return false;
              for (const Case &one : cases)
                if (!(adhesionless(one.*areas, load, 0).value > 0) ||
                    std::isnan(
                         jkr_limit(one.*areas, &RealisationAreas::loading, load, zones.lengths).value.value))
                  return false;
              return true;
            };
            while (j < n_loads && !comparable(j))
              ++j;
            if (cases.size() < 2 || j == n_loads)
              {
                claims.add_row(
                    {"the share of the area adhesion closes grows (theta > 0) or falls (theta < 0) with "
                     "magnification, theta = (2/5)(2H - 1)",
                     name, "loading", "", "", cases.size() < 2 ? "one magnification" : "no common load", "",
                     "not judged"});
                continue;
              }
            const auto closed = [&](const Case &one) {
              const JkrLimit limit = jkr_limit(one.*areas, &RealisationAreas::loading, j, zones.lengths);
              const double   free  = adhesionless(one.*areas, j, 0).value;
              return std::array<double, 3>{{1 - limit.value.value / free,
                                            (one.*areas).size() > 1 ? limit.value.standard_error / free : 0,
                                            limit.extrapolation_error / free}};
            };
            const auto   from = closed(cases.front()), to = closed(cases.back());
            const double change = to[0] - from[0], error = 2 * std::hypot(from[1], to[1]) + from[2] + to[2];
            claims.add_row(
                {"the share of the area adhesion closes grows (theta > 0) or falls (theta < 0) with "
                 "magnification, theta = (2/5)(2H - 1) = " +
                     Table::label(theta, 3) + " (H of the map's PSD fit)",
                 name, "loading",
                 Table::label(cases.front().zeta, 4) + " ... " + Table::label(cases.back().zeta, 4),
                 Table::label(mean_pressures[j], 3),
                 value_with_error(from[0], from[1]) + " ... " + value_with_error(to[0], to[1]),
                 theta > 0   ? "grows"
                 : theta < 0 ? "falls"
                             : "stays",
                 std::abs(change) <= error ? "undecided: the change lies within the error bars"
                 : theta != 0 && (change > 0) == (theta > 0) ? "agrees in sign"
                                                             : "disagrees"});
          }
        publish(
            table, "measured-adhesion.csv", results, log,
            "Adhesive contact of the measured map and its Gaussian twins at each magnification: A_nc/A_0 at "
            "each cohesive zone and in the JKR limit, beside the adhesionless solution at p_bar and p_bar + "
            "p0");
        log << '\n';
        publish(claims, "measured-adhesion-claims.csv", results, log,
                "The paper's adhesive claims on this surface");
        log << "Tables: " << results.directory().string()
            << "/measured-adhesion.csv, measured-adhesion-claims.csv\n";
        return {};
      }

      // H of the power law fitted to the map's PSD over the range it resolves.
      double hurst_of(const Topography &topography) const
      {
        return fit_power_law(isotropic_spectrum(topography, input.hann_window), reliable_range(topography))
            .hurst;
      }

      static std::string shortest_text(const double value) { return Table::label(value); }

      MeasuredSurfaceInput input;
      MaterialParameters   material;
      ContactSolverControl control;
      double               adhesion_ratio, first_contact;
      std::vector<double>  fractions;      // of the map's Nyquist wavenumber
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
