// adhesive-random-contact: the paper's adhesive claims against a full contact
// solution. Power-law random surfaces (several H and zeta) near full contact
// with adhesion of a fixed work w, by the adhesive boundary-element solver at
// several cohesive zones extrapolated to the JKR limit, over realisations, on
// two branches of the multistable equilibria: the loading path from first
// contact, and at each load the adhesionless state with adhesion switched on
// (the state whose gaps the isolated-gap law sums). Beside them (a) the
// adhesionless solution at p_bar and at p_bar + p0, (b) the statistical
// layer's laws with adhesion in both conventions and (c) the isolated-gap law
// with adhesion summed over each realisation's own summits. Then the paper's
// three claims, each judged in plain words: the shift by p0, full contact at
// zero load for p0/sqrt(V) about 5, and how the non-contact area moves with
// magnification as the sign of theta = (2/5)(2H - 1) says. No verdict: the
// claims are the paper's, not the verifier's.
#include "closed_forms/adhesive_gap.h"
#include "contact/extrapolation.h"
#include "output/grid_fields.h"
#include "output/progress.h"
#include "parallel/memory_budget.h"
#include "parallel/spread_over_ranks.h"
#include "problems/adhesive_random_surfaces.h"
#include "problems/contact_solver.h"
#include "problems/random_surfaces.h"
#include "problems/rough_surface.h"
#include "problems/solid.h"
#include "scenes/scene.h"
#include "statistics/contact_area.h"
#include "statistics/random_field.h"
#include "statistics/summit_statistics.h"

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace penny
{
  namespace
  {
    // The statistical layer's A_nc/A_0 at one load in the paper's and the
    // consistent convention ([0], [1]), with three gap laws: the paper's
    // linear law, the fit it is derived from (p0/2) and the exact branch g.
    struct LayerAreas
    {
      double linear[2], fitted[2], exact[2];
    };

    // One power law of the study and its results over realisations, per
    // load: the JKR limits of the two branches, the adhesionless areas at
    // p_bar and p_bar + p0, the layer's areas.
    struct Case
    {
      double                  hurst, adhesion_ratio, zeta; // adhesion_ratio: p0/sqrt(V) at the first zeta
      AdhesiveRandomSurfaces  surfaces;
      std::vector<JkrLimit>   loading, switched_on;
      std::vector<Estimate>   adhesionless, shifted;
      std::vector<LayerAreas> layer;
    };

    // The statistical layer's population of gaps in one convention, with the
    // pressure spread its loads are measured in.
    struct Law
    {
      GapPopulation gaps;
      double        sqrt_V;
    };

    Law layer_law(const AdhesiveRandomSurfaces &s, const Convention convention)
    {
      const PressureSummits summits = pressure_summits(spectral_moments(s.spectrum), s.E_star, convention);
      return {surface_population(summits, s.critical_intensity, convention), std::sqrt(summits.variance)};
    }

    // "0.12 (+-0.03)": a value with its standard error.
    std::string with_error(const double value, const double error)
    {
      std::ostringstream text;
      text.precision(3);
      text << value << " (+-" << error << ")";
      return text.str();
    }

    struct AdhesiveRandomContactScene : Scene
    {
      void inputs(Sections &sections) override
      {
        material_section(sections, material);
        roughness_section(sections, roughness, false);
        contact_solver_section(sections, control, 1e-8);
        fields_section(sections, write_fields);
      }

      void entries(Entries &entries) override
      {
        power_laws.entries(entries, {4, 8, 16}, interval("[]", 2, 256));
        entries.increasing_numbers(
            "Adhesion p0/sqrt(V)", adhesion_ratios, {1}, 1, interval("[]", 1e-3, 20),
            "p0/sqrt(V) at the first magnification, p0 = psi (K_Ic^4/R_p)^(1/5) with R_p and V of "
            "the sampled lattice's summits (Kac-Rice), one study each: this fixes w = K_Ic^2/(2 E*) "
            "of each H for every magnification. Units: none.");
        entries.increasing_numbers("Mean pressures", mean_pressures, {0, 0.5, 1, 1.5, 2}, 1,
                                   interval("[]", 0, 100, "sqrt(V)"),
                                   "p_bar/sqrt(V): the states of the loading path. Units: sqrt(V).");
        entries.number(
            "First contact load", first_contact, 0.25, interval("(]", 0, 100, "sqrt(V)"),
            "p_s/sqrt(V): the surfaces are first pressed together without adhesion at p_s; then "
            "adhesion acts and the mean pressures are applied in increasing order. Units: sqrt(V).");
        zones.entries(
            entries, "lambda1", {{1. / 8, 1. / 16, 1. / 32}, 4}, 2, interval("[]", 1e-3, 1),
            "the shortest wavelength lambda1 = lambda0/zeta, extrapolated to 0 at the order the last "
            "three show; the grid is the next power of two.");
        entries.integer("Realisations", n_realisations, 8u, 2u, 100000u,
                        "Surfaces per H and zeta, spread over the MPI ranks. Units: none.");
        entries.integer("Seed", seed, std::uint64_t(1), std::uint64_t(0), std::uint64_t(1) << 62,
                        "Realisation k uses realisation_seed(Seed, k). Units: none.");
        if (!entries.reading())
          return;
        // Beyond 8192 points a side a solve outgrows this verifier's memory.
        const double finest = zones.points_per_zone * power_laws.magnifications.back() / zones.lengths.back();
        entries.require(finest <= 8192, "Cohesive zones l_pz/lambda1", zones.lengths.back(),
                        "at least Points per cohesive zone x largest magnification/8192 = " +
                            Table::label(zones.points_per_zone * power_laws.magnifications.back() / 8192, 3));
      }

      // The power law (H, zeta) of the Roughness amplitude and q0, on a grid of `n` points a side.
      AdhesiveRandomSurfaces surfaces(const double hurst, const double zeta, const double K_Ic) const
      {
        AdhesiveRandomSurfaces s{power_law_spectrum(hurst, roughness.q0, zeta, roughness.amplitude),
                                 material.plane_strain_modulus(),
                                 K_Ic,
                                 0,
                                 0,
                                 mean_pressures,
                                 first_contact,
                                 zones,
                                 control};
        const PeriodicGrid grid = square_grid(s.grid_points(zones.lengths.front()), 2 * M_PI / roughness.q0);
        const FieldMoments lattice = lattice_moments(grid, pressure_spectrum(s.spectrum, s.E_star)).expected;
        s.sqrt_V                   = std::sqrt(lattice.m0);
        s.p0 = closed_form::psi * adhesion_tension(1 / expected_summits(lattice).mean_curvature, K_Ic);
        return s;
      }

      // K_Ic of the power law of `hurst` at the first magnification with p0/sqrt(V) = `ratio`.
      double critical_intensity(const double hurst, const double ratio) const
      {
        const AdhesiveRandomSurfaces unit = surfaces(hurst, power_laws.magnifications.front(), 1);
        // p0 grows like K_Ic^(4/5).
        return std::pow(ratio * unit.sqrt_V / unit.p0, 1.25);
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        dealii::Timer     timer;
        std::vector<Case> cases;
        for (const double hurst : power_laws.hurst_exponents)
          for (const double ratio : adhesion_ratios)
            {
              const double K_Ic = critical_intensity(hurst, ratio);
              for (const double zeta : power_laws.magnifications)
                cases.push_back({hurst, ratio, zeta, surfaces(hurst, zeta, K_Ic), {}, {}, {}, {}, {}});
            }
        // Peak resident size, one rank: 164 bytes a point of the finest grid
        // more at 2048^2 than at 1024^2.
        unsigned int finest = 0;
        for (const Case &one : cases)
          finest = std::max(finest, one.surfaces.grid_points(zones.lengths.back()));
        check_grid_memory(
            finest, 180,
            "Adhesive random contact/Cohesive zones l_pz/lambda1 = " + shortest(zones.lengths.back()) +
                " with Points per cohesive zone = " + shortest(zones.points_per_zone) +
                " and Magnifications up to " + shortest(power_laws.magnifications.back()),
            MPI_COMM_WORLD);

        const std::size_t n_zones = zones.lengths.size(), n_loads = mean_pressures.size();
        Progress          progress(log, "realisations", 30);
        const auto        rows =
            spread_over_ranks(MPI_COMM_WORLD, cases.size() * n_realisations, [&](const unsigned int piece) {
              const Case &one = cases[piece / n_realisations];
              const auto  row =
                  solve_realisation(one.surfaces, realisation_seed(seed, piece % n_realisations));
              progress.step("of " + std::to_string(cases.size() * n_realisations) +
                            ", last H = " + Table::label(one.hurst) + ", zeta = " + Table::label(one.zeta));
              return row.pack();
            });
        log << "Solved " << rows.size() << " realisations in " << Table::label(timer.wall_time(), 4)
            << " s\n";

        Table table = area_table();
        for (std::size_t c = 0; c < cases.size(); ++c)
          {
            Case                         &one = cases[c];
            const AdhesiveRandomSurfaces &s   = one.surfaces;
            std::vector<RealisationAreas> areas;
            for (unsigned int k = 0; k < n_realisations; ++k)
              areas.push_back(RealisationAreas::unpack(rows[c * n_realisations + k], n_zones, n_loads));
            const Law laws[2] = {layer_law(s, Convention::paper), layer_law(s, Convention::consistent)};
            for (std::size_t j = 0; j < n_loads; ++j)
              {
                std::vector<std::vector<double>> values;
                for (const auto &a : areas)
                  values.push_back({a.adhesionless[j], a.shifted[j], a.isolated_gaps[j]});
                one.loading.push_back(jkr_limit(areas, &RealisationAreas::loading, j, zones.lengths));
                one.switched_on.push_back(jkr_limit(areas, &RealisationAreas::switched_on, j, zones.lengths));
                one.adhesionless.push_back(mean_over(values, 0));
                one.shifted.push_back(mean_over(values, 1));

                const double p_bar = mean_pressures[j] * s.sqrt_V, shifted = one.shifted.back().value;
                LayerAreas   layer;
                for (const int k : {0, 1})
                  {
                    const GapPopulation &gaps = laws[k].gaps;
                    const double         load = p_bar / laws[k].sqrt_V;
                    layer.linear[k]           = linear_law_noncontact_area(gaps, load);
                    layer.fitted[k]           = noncontact_area(gaps, fitted_gap_law(gaps.adhesion), load);
                    layer.exact[k]            = noncontact_area(gaps, exact_gap_law(gaps.adhesion), load);
                  }
                one.layer.push_back(layer);
                for (const auto *branch : {&one.loading, &one.switched_on})
                  {
                    const JkrLimit &limit = branch->back();
                    if (std::isnan(limit.value.value))
                      continue;
                    std::vector<Table::Cell> row = {one.hurst, one.zeta, s.p0 / s.sqrt_V, mean_pressures[j],
                                                    branch == &one.loading ? "loading" : "switched on"};
                    row.insert(row.end(), limit.means.begin(), limit.means.end());
                    for (const double cell :
                         {limit.value.value, limit.value.standard_error, limit.extrapolation_error,
                          limit.order, one.adhesionless.back().value, shifted})
                      row.emplace_back(cell);
                    row.emplace_back(shifted > 0 ? Table::Cell(limit.value.value / shifted, Table::Format{4})
                                                 : Table::Cell("adhesionless: no gaps"));
                    for (const auto law : {&LayerAreas::linear, &LayerAreas::fitted, &LayerAreas::exact})
                      for (const int k : {0, 1})
                        row.emplace_back((layer.*law)[k]);
                    row.emplace_back(mean_over(values, 2).value);
                    table.add_row(row);
                  }
              }
          }
        publish(
            table, "adhesive-random-contact.csv", results, log,
            "Adhesive random surfaces on two branches: loading (first contact without adhesion at p_s = " +
                Table::label(first_contact, 3) +
                " sqrt(V), then adhesion, then increasing load) and switched on (at each load the "
                "adhesionless state, then adhesion). A_nc/A_0 by the adhesive BEM at each cohesive zone and "
                "in the JKR limit, beside (a) the adhesionless BEM at p_bar and at "
                "p_bar + p0, (b) the statistical layer with adhesion in both conventions (the paper's linear "
                "law, the p0/2 fit it is derived from, the exact g) and (c) the isolated-gap law over the "
                "realisations' own summits");
        publish(claims(cases), "adhesive-random-contact-claims.csv", results, log,
                "The paper's adhesive claims against the full solution (JKR limit, mean over realisations "
                "with its standard error):");
        Table summary = Table::summary();
        summary.add_row({"realisations per H and zeta", n_realisations});
        summary.add_row({"grids (points a side, largest zeta)",
                         Table::label(cases.back().surfaces.grid_points(zones.lengths.front())) + " ... " +
                             Table::label(cases.back().surfaces.grid_points(zones.lengths.back()))});
        summary.add_row({"MPI ranks", dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
        summary.add_row({"wall time (s)", Table::Cell(timer.wall_time(), Table::Format{4})});
        publish(summary, "adhesive-random-contact-summary.csv", results, log);
        if (write_fields)
          write_first_realisation(cases.front(), results);
        return {};
      }

      // The first realisation of the first H and zeta for ParaView
      // (surface.vti), on the finest zone's grid: heights, full-contact
      // pressure, and per load the gaps without and with adhesion and the
      // adhesive pressure. Each rank solves it (the write is collective; rank
      // 0's counts).
      void write_first_realisation(const Case &first, const ResultFolder &results) const
      {
        RealisationFields fields;
        solve_realisation(first.surfaces, realisation_seed(seed, 0), &fields);
        std::vector<GridFieldOutput> outputs{
            {"height (m)", &fields.heights},
            {"full-contact pressure less its mean (Pa)", &fields.full_contact}};
        std::size_t without = 0;
        for (std::size_t j = 0; j < mean_pressures.size(); ++j)
          {
            const std::string at = " at p_bar = " + Table::label(mean_pressures[j], 4) + " sqrt(V)";
            if (mean_pressures[j] > 0)
              outputs.push_back({"gap without adhesion" + at + " (m)", &fields.adhesionless_gaps[without++]});
            outputs.push_back({"gap with adhesion" + at + " (m)", &fields.adhesive_gaps[j]});
            outputs.push_back({"pressure with adhesion" + at + " (Pa)", &fields.adhesive_pressures[j]});
          }
        const PeriodicGrid &grid = fields.grid;
        write_grid_fields("surface", grid.nx, grid.ny, grid.lx / grid.nx, grid.ly / grid.ny, outputs,
                          results);
      }

      Table area_table() const
      {
        std::vector<Table::Column> columns = {"H", "zeta", {"p0/sqrtV", {4}}, "p_bar/sqrtV", "branch"};
        for (const double zone : zones.lengths)
          columns.push_back({"BEM l_pz/lambda1=" + Table::label(zone, 4), {4, true}});
        for (const char *name : {"BEM JKR limit", "std error", "extrapolation error"})
          columns.push_back({name, {3, true}});
        columns.push_back({"order", {2}});
        for (const char *name : {"adhesionless BEM", "adhesionless BEM at p_bar + p0"})
          columns.push_back({name, {4, true}});
        columns.push_back({"JKR/adhesionless at p_bar + p0", {4}});
        for (const char *name : {"layer linear paper", "layer linear consistent", "layer p0/2 fit paper",
                                 "layer p0/2 fit consistent", "layer exact g paper",
                                 "layer exact g consistent", "isolated gaps sampled summits"})
          columns.push_back({name, {4, true}});
        return Table(columns);
      }

      // The three claims, judged on the JKR limits with their error bars:
      // two standard errors (of both sides) plus the extrapolation error.
      Table claims(const std::vector<Case> &cases) const
      {
        // Claim 1 per load: beside the BEM's ratio, the ratios the paper's own
        // picture of isolated gaps predicts (the layer's exact branch or the
        // p0/2 fit over its linear law, which is the adhesionless law at
        // p_bar + p0), and what is left to the picture itself (the BEM's
        // ratio over the exact branch's, consistent convention).
        Table      table({"claim", "branch", "H", "zeta", "p_bar/sqrtV", "measured", "the paper",
                          "exact g/linear law paper", "exact g/linear law consistent", "p0/2 fit/linear law paper",
                          "p0/2 fit/linear law consistent", "BEM/(exact g/linear) consistent", "verdict"});
        const auto span = [](const std::vector<double> &values) {
          const auto [low, high] = std::minmax_element(values.begin(), values.end());
          return Table::label(*low, 3) + (*high > *low ? " ... " + Table::label(*high, 3) : "");
        };
        const auto list = [](const std::vector<double> &values) {
          std::string text;
          for (const double value : values)
            text += (text.empty() ? "" : ", ") + (std::isfinite(value) ? Table::label(value, 3) : "-");
          return text;
        };
        const auto bar = [](const JkrLimit &limit, const Estimate &other) {
          return 2 * std::hypot(limit.value.standard_error, other.standard_error) + limit.extrapolation_error;
        };
        const auto name = [&](const std::vector<JkrLimit> Case::*branch) {
          return branch == &Case::loading ? "loading" : "switched on";
        };

        // 1. A_nc(p_bar) = adhesionless A_nc(p_bar + p0), over the loads with
        // gaps (the switched-on branch is undefined at zero load alone).
        for (const auto branch : {&Case::switched_on, &Case::loading})
          for (const Case &one : cases)
            if (branch == &Case::loading || mean_pressures.back() > 0)
              {
                bool                within = true;
                std::vector<double> loads, measured, exact[2], fitted[2], picture;
                for (std::size_t j = 0; j < mean_pressures.size(); ++j)
                  {
                    const JkrLimit &limit = (one.*branch)[j];
                    if (!(one.shifted[j].value > 0) || std::isnan(limit.value.value))
                      continue;
                    const LayerAreas &layer = one.layer[j];
                    loads.push_back(mean_pressures[j]);
                    measured.push_back(limit.value.value / one.shifted[j].value);
                    for (const int k : {0, 1})
                      {
                        exact[k].push_back(layer.exact[k] / layer.linear[k]);
                        fitted[k].push_back(layer.fitted[k] / layer.linear[k]);
                      }
                    picture.push_back(measured.back() / exact[1].back());
                    within &=
                        std::abs(limit.value.value - one.shifted[j].value) <= bar(limit, one.shifted[j]);
                  }
                table.add_row(
                    {"A_nc(p_bar) = adhesionless A_nc(p_bar + p0), p0/sqrt(V) = " +
                         Table::label(one.surfaces.p0 / one.surfaces.sqrt_V, 3),
                     name(branch), one.hurst, one.zeta, list(loads),
                     loads.empty() ? "no load with gaps" : "ratio " + list(measured), "ratio 1",
                     list(exact[0]), list(exact[1]), list(fitted[0]), list(fitted[1]), list(picture),
                     loads.empty() ? "not tested"
                     : within      ? "holds within the error bars"
                                   : "fails: of the ratio, the paper's algebra (exact g over its "
                                     "linear law, consistent) accounts for a factor " +
                                    span(exact[1]) + ", the isolated-gap picture for " + span(picture)});
              }

        // 2. Full contact at zero load once p0/sqrt(V) is about 5 (only the
        // loading branch reaches zero load).
        for (const Case &one : cases)
          if (mean_pressures.front() == 0 && one.surfaces.p0 / one.surfaces.sqrt_V >= 4)
            {
              const JkrLimit &limit = one.loading.front();
              table.add_row(
                  {"full contact at zero load for p0/sqrt(V) = " +
                       Table::label(one.surfaces.p0 / one.surfaces.sqrt_V, 3),
                   "loading", one.hurst, one.zeta, "0",
                   "A_nc(0)/A_0 = " + with_error(limit.value.value, limit.value.standard_error), "about 0",
                   "", "", "", "", "",
                   limit.value.value <= bar(limit, {0, 0}) ? "holds within the error bars" : "fails"});
            }

        // 3. With magnification at fixed w: the share of the adhesionless
        // non-contact area that adhesion closes, 1 - A_nc/A_nc(adhesionless),
        // from the first to the last zeta (the cases of one H and w follow
        // each other), at the first load where the branch exists and every
        // zeta has gaps without adhesion.
        for (const auto branch : {&Case::loading, &Case::switched_on})
          for (std::size_t start = 0; start < cases.size(); start += power_laws.magnifications.size())
            {
              std::vector<const Case *> of_hurst;
              for (std::size_t c = start; c < start + power_laws.magnifications.size(); ++c)
                of_hurst.push_back(&cases[c]);
              const double hurst      = cases[start].hurst;
              const auto   comparable = [&](const std::size_t load) {
                for (const Case *one : of_hurst)
                  if (std::isnan((one->*branch)[load].value.value) || !(one->adhesionless[load].value > 0))
                    return false;
                return true;
              };
              std::size_t j = 0;
              while (j < mean_pressures.size() && !comparable(j))
                ++j;
              if (of_hurst.size() < 2 || j == mean_pressures.size())
                continue;
              const auto closed = [&](const Case &one) {
                const JkrLimit &limit = (one.*branch)[j];
                return Estimate{1 - limit.value.value / one.adhesionless[j].value,
                                limit.value.standard_error / one.adhesionless[j].value};
              };
              const Case    &first = *of_hurst.front(), &last = *of_hurst.back();
              const Estimate from = closed(first), to = closed(last);
              const double   change = to.value - from.value, theta = 0.4 * (2 * hurst - 1);
              const double   error =
                  2 * std::hypot(from.standard_error, to.standard_error) +
                  ((last.*branch)[j].extrapolation_error + (first.*branch)[j].extrapolation_error) /
                      last.adhesionless[j].value;
              const std::string verdict = std::abs(change) <= error
                                              ? "undecided: the change lies within the error bars"
                                          : theta != 0 && (change > 0) == (theta > 0) ? "agrees in sign"
                                                                                      : "disagrees";
              table.add_row({"share closed by adhesion with magnification, p0/sqrt(V) = " +
                                 Table::label(first.adhesion_ratio, 3) + " at the first",
                             name(branch), hurst,
                             Table::label(first.zeta) + " ... " + Table::label(last.zeta),
                             Table::label(mean_pressures[j]),
                             with_error(from.value, from.standard_error) + " ... " +
                                 with_error(to.value, to.standard_error),
                             theta > 0   ? "grows (theta > 0: towards full contact)"
                             : theta < 0 ? "falls (theta < 0: adhesion vanishes)"
                                         : "stays (theta = 0)",
                             "", "", "", "", "", verdict});
            }
        return table;
      }

      MaterialParameters   material;
      RoughnessParameters  roughness;
      ContactSolverControl control;
      SampledPowerLaws     power_laws;
      std::vector<double>  adhesion_ratios, mean_pressures;
      CohesiveZones        zones; // l_pz/lambda1
      double               first_contact;
      unsigned int         n_realisations;
      std::uint64_t        seed;
      bool                 write_fields;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      AdhesiveRandomContactScene, "adhesive-random-contact", "Adhesive random contact",
      "the paper's adhesive claims against the adhesive BEM on random surfaces in the JKR limit: "
      "A_nc/A_0 against p_bar/sqrt(V) beside the adhesionless BEM at p_bar + p0, the statistical "
      "layer and the isolated-gap law over the sampled summits",
      "")
} // namespace penny
