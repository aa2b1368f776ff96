// elliptical-summits: the paper's remark that elliptical gaps "do not change
// the results significantly", asked of summits P (1 - x^2/Ax^2 - y^2/Ay^2)
// with two principal radii (doc/theory.md, section 8). For each Ay/Ax: the
// adhesionless gap (K_I = 0 at both ends of the front) and the adhesive
// minimum (K_I = K_Ic at both ends, least P: psi), searched on 3D FE models
// sampled at Chebyshev points in log(b/a) and interpolated between them, on
// Galin's closed form, and on two discretisations: first one with half the
// cells along and around the front of 'Elliptical model' (the coarse model,
// for the error estimate), then 'Elliptical model' itself, sampled only from
// just below the coarse model's slenderest gap. The same sampling of the
// closed form measures the interpolation's share of the error. PASS when b/a,
// the gap-area ratio and psi lie within Verification/Tolerance of the closed
// form.
#include "searches/elliptical_summits.h"
#include "fracture/front_stress_intensity.h"
#include "input/input_error.h"
#include "numerics/relative_error.h"
#include "numerics/solver_failure.h"
#include "output/phase_times.h"
#include "output/progress.h"
#include "output/table.h"
#include "problems/elliptical_gap.h"
#include "scenes/scene.h"
#include "searches/elliptical_gap_family.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace penny
{
  namespace
  {
    using namespace dealii;

    // The gaps of one summit Ay/Ax by one method (FE or Galin's closed form).
    struct SummitGaps
    {
      AdhesionlessSummitGap adhesionless;
      AdhesiveSummitGap     adhesive;
      std::vector<double>
          adhesionless_front;             // K_I/(P K_uniform) at the front points: 0 if the ellipse is exact
      std::vector<double> adhesive_front; // K_I/K_Ic at the front points: 1 at both ends
    };

    struct EllipticalSummitsResults
    {
      std::vector<double>     tension_aspect_ratios; // Ay/Ax
      std::vector<double>     angles;                // front points
      std::vector<SummitGaps> fe, coarse_fe, exact;  // per Ay/Ax; coarse_fe: cells and sectors halved
      std::vector<SummitGaps> sampled_exact;         // the closed form, sampled as the fine FE is
      double                  largest_error;         // of b/a, the area ratio and psi, FE against exact
      double                  interpolation_error;   // the same, sampled closed form against exact
      double                  estimated_error;       // the same, FE against coarse FE: its estimate
      double                  smallest_fine_shape;   // the fine models' smallest b/a sampled
      unsigned int            fe_models;
    };

    const Table::Format ratio_digits{8, false}, estimate_digits{2, true};

    // The searches and the front of the gaps found, by one method: one call
    // of `sifs` per shape found, along the front from phi = 0 to pi/2.
    SummitGaps summit_gaps(const EllipticalGapSifs &sifs, const double rho, const std::vector<double> &angles,
                           const double slenderest = 0)
    {
      SummitGaps   gaps;
      const double s0     = adhesionless_summit_shape(sifs, rho, slenderest);
      const auto   front0 = sifs(s0, angles);
      gaps.adhesionless   = adhesionless_gap(s0, {{front0.front(), front0.back()}});
      const double s1     = adhesive_summit_shape(sifs, rho, s0);
      const auto   front1 = sifs(s1, angles);
      gaps.adhesive       = adhesive_gap(s1, rho, {{front1.front(), front1.back()}});
      for (const auto &K : front0)
        gaps.adhesionless_front.push_back(gaps.adhesionless.relative_sif(K));
      for (const auto &K : front1)
        gaps.adhesive_front.push_back(gaps.adhesive.relative_sif(K));
      return gaps;
    }

    // The largest relative difference of b/a, the gap-area ratio and psi.
    double largest_relative_error(const std::vector<SummitGaps> &found, const std::vector<SummitGaps> &exact)
    {
      double largest = 0;
      for (unsigned int k = 0; k < found.size(); ++k)
        for (const double error :
             {relative_error(found[k].adhesionless.aspect_ratio, exact[k].adhesionless.aspect_ratio),
              relative_error(found[k].adhesionless.area_ratio, exact[k].adhesionless.area_ratio),
              relative_error(found[k].adhesive.aspect_ratio, exact[k].adhesive.aspect_ratio),
              relative_error(found[k].adhesive.tension, exact[k].adhesive.tension)})
          largest = worse(largest, error);
      return largest;
    }

    double largest_magnitude(const std::vector<double> &values)
    {
      double largest = 0;
      for (const double v : values)
        largest = std::max(largest, std::abs(v));
      return largest;
    }

    double spread(const std::vector<double> &values)
    {
      return *std::max_element(values.begin(), values.end()) -
             *std::min_element(values.begin(), values.end());
    }

    // A quantity of the gaps: its FE value, the closed form, the FE error and
    // the estimate |FE - coarse FE|, in four columns.
    struct Quantity
    {
      std::string                               name;
      std::function<double(const SummitGaps &)> of;
    };

    Table quantity_table(const std::vector<Quantity> &quantities, const EllipticalSummitsResults &solved)
    {
      std::vector<Table::Column> columns = {{"Ay/Ax", Table::Format{4, false}}};
      for (const auto &q : quantities)
        {
          columns.push_back({q.name + " FE", ratio_digits});
          columns.push_back({q.name + " exact", ratio_digits});
          columns.push_back({q.name + " FE error", estimate_digits});
          columns.push_back({q.name + " FE error estimate", estimate_digits});
        }
      Table table(columns);
      for (unsigned int k = 0; k < solved.tension_aspect_ratios.size(); ++k)
        {
          std::vector<Table::Cell> row = {solved.tension_aspect_ratios[k]};
          for (const auto &q : quantities)
            {
              const double fe = q.of(solved.fe[k]), exact = q.of(solved.exact[k]);
              row.emplace_back(fe);
              row.emplace_back(exact);
              row.emplace_back(fe - exact);
              row.emplace_back(std::abs(fe - q.of(solved.coarse_fe[k])));
            }
          table.add_row(row);
        }
      return table;
    }

    Table summit_front_table(const EllipticalSummitsResults &solved)
    {
      Table table({{"Ay/Ax", Table::Format{4, false}},
                   {"phi (rad)", Table::Format{6, false}},
                   {"adhesionless K_I/(P K_uniform) FE", estimate_digits},
                   {"adhesionless K_I/(P K_uniform) exact", estimate_digits},
                   {"adhesive K_I/K_Ic FE", ratio_digits},
                   {"adhesive K_I/K_Ic exact", ratio_digits}});
      for (unsigned int k = 0; k < solved.tension_aspect_ratios.size(); ++k)
        for (unsigned int i = 0; i < solved.angles.size(); ++i)
          table.add_row({solved.tension_aspect_ratios[k], solved.angles[i],
                         solved.fe[k].adhesionless_front[i], solved.exact[k].adhesionless_front[i],
                         solved.fe[k].adhesive_front[i], solved.exact[k].adhesive_front[i]});
      return table;
    }
    struct EllipticalSummitsScene : Scene
    {
      void inputs(Sections &sections) override
      {
        elliptical_model_sections(sections, model);
        // The coarse model halves the cells along and around the front.
        const auto &mesh = model.model.mesh;
        sections.require(mesh.cells_along_front % 4 == 0, "Elliptical model/Cells along front",
                         mesh.cells_along_front,
                         "{4, 8, 12, ..., 256} for this scene (its coarse model halves it)");
        sections.require(mesh.cells_around_front % 8 == 0, "Elliptical model/Sectors around front",
                         mesh.cells_around_front,
                         "{8, 16, 24, ..., 64} for this scene (its coarse model halves it)");
        sections.require(
            model.front_weight.half_width_cells <= model.front_cells() / 2,
            "Elliptical model/Front weight half-width", model.front_weight.half_width_cells,
            "(0, Cells along front x 2^Global refinements/2] for this scene (its coarse model halves the "
            "cells)");
      }

      void entries(Entries &entries) override
      {
        entries.numbers(
            "Tension aspect ratios Ay/Ax", tension_aspect_ratios, {1, 0.8, 0.5, 0.25, 0.1},
            interval("[]", 0.05, 1),
            "Summits t = P (1 - x^2/Ax^2 - y^2/Ay^2) of principal radii R_1 = Ax^2/(2 P) and R_2 = "
            "Ay^2/(2 P); for each, the gaps are searched with and without adhesion. Every gap found is "
            "rounder than its summit, so the coarse FE models are sampled for b/a from the smallest Ay/Ax "
            "(at most 0.5) to 1, the fine ones from 5 % below the coarse models' slenderest gap; slender "
            "summits need slender gap models (b/a about 0.14 for Ay/Ax = 0.1). Units: none.");
        entries.integer(
            "Shapes sampled", shapes_sampled, 14u, 2u, 64u,
            "FE models (each solved for three unit loads) per discretisation, at Chebyshev points in "
            "log(b/a) up to 1 (from the smallest Ay/Ax, at most 0.5, for the coarse models; from 5 % below "
            "their slenderest gap for the fine ones); the searches run on their interpolant. Its error falls "
            "geometrically with the samples: in b/a, the area ratio and psi "
            "within 1e-5 with 12 and 1e-7 with 14 from Ay/Ax = 0.1, 1e-6 with 16 from 0.05, 5e-8 with 12 "
            "from b/a = 0.13 (on the closed form); summary.csv reports it, measured by sampling the closed "
            "form as the FE is. Units: "
            "none.");
        entries.integer(
            "Front points", front_points, 9u, 2u, 1000u,
            "K_I along the front of each gap found, at phi = i pi/(2 (n - 1)), i = 0 ... n - 1, for the "
            "front table; the searches use phi = 0 and pi/2 only. On a gap with b/a < 1 the points between "
            "lie between the mesh's front vertices, where the front weight's ends fall inside cells: K_I "
            "there is good to a few 1e-4 only. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        TimerOutput                  timer(log, TimerOutput::never, TimerOutput::wall_times);
        EllipticalGapModelParameters fine   = model.with_semi_axes(1, 1);
        EllipticalGapModelParameters coarse = fine;
        coarse.mesh.cells_along_front /= 2;
        coarse.mesh.cells_around_front /= 2;
        const double ring = model.ring_radii.back();

        EllipticalSummitsResults solved;
        solved.tension_aspect_ratios = tension_aspect_ratios;
        // The family's gaps differ in b/a: one set of points for all, evenly
        // spaced in phi (the circle's front coordinate).
        solved.angles    = front_point_angles(front_points, EllipticalFront(1, 1));
        solved.fe_models = 0;
        {
          // First, as it takes milliseconds: a summit the closed form cannot answer stops the scene here.
          TimerOutput::Scope scope(timer, "closed form");
          for (const double ratio : solved.tension_aspect_ratios)
            solved.exact.push_back(summit_gaps(galin_unit_load_sifs, ratio, solved.angles));
        }
        // The shapes sampled: from the slenderest summit's Ay/Ax (its gap is
        // rounder) to the circle, a range even when every summit is round.
        const double smallest = std::min(
            0.5, *std::min_element(solved.tension_aspect_ratios.begin(), solved.tension_aspect_ratios.end()));
        // The closed form's gaps, sampled as the FE is from `lowest` to the
        // circle.
        const auto sampled_closed_form = [&](const double lowest, const double ratio) {
          TimerOutput::Scope   scope(timer, "closed form");
          const SampledGapSifs sampled(galin_unit_load_sifs, lowest, shapes_sampled, solved.angles);
          return summit_gaps(sampled, ratio, solved.angles, lowest);
        };
        // Too few samples, where the search fails or the interpolation alone
        // misses Verification/Tolerance, are bad input: found here, on the
        // closed form, before any FE model.
        for (unsigned int k = 0; k < solved.tension_aspect_ratios.size(); ++k)
          {
            const double ratio = solved.tension_aspect_ratios[k];
            std::string  failure;
            try
              {
                const double error =
                    largest_relative_error({sampled_closed_form(smallest, ratio)}, {solved.exact[k]});
                if (!(error <= tolerance))
                  failure = "b/a, the area ratio or psi is off by " + Table::label(error, 3) +
                            ", more than Verification/Tolerance = " + shortest(tolerance);
              }
            catch (const std::exception &error)
              {
                failure = error.what();
              }
            if (!failure.empty())
              throw InputError("Elliptical summits/Shapes sampled = " + std::to_string(shapes_sampled) +
                               " is too few for Ay/Ax = " + shortest(ratio) +
                               ": on the closed form sampled so, " + failure +
                               "; allowed: [2, 64], 14 or more from Ay/Ax = 0.1, 16 from 0.05");
          }
        // The largest model: the fine discretisation's slenderest shape (the
        // most rings around its front).
        EllipticalGapModelParameters slenderest = fine;
        slenderest.mesh.semi_axis_b             = smallest;
        check_elliptical_model_size(slenderest);

        Progress progress(log, "3D models");
        // The FE models of a discretisation, sampled from `lowest` to the circle.
        const auto sampled_family = [&](const EllipticalGapModelParameters &discretisation,
                                        const std::string &name, const double lowest) {
          EllipticalGapFamily family(discretisation, model.front_weight, ring, lowest, timer);
          family.observe([&](const double s) {
            std::ostringstream state;
            state << name << ": b/a = " << s << ", shape " << family.n_models() << " of " << shapes_sampled;
            progress.step(state.str());
          });
          // A model that fails names its shape and discretisation (a solver's
          // failure and bad input already name their settings).
          const SampledGapSifs sampled(
              [&](const double s, const std::vector<double> &angles) {
                try
                  {
                    return family.unit_load_sifs(s, angles);
                  }
                catch (const SolverFailure &)
                  {
                    throw;
                  }
                catch (const InputError &)
                  {
                    throw;
                  }
                catch (const std::exception &error)
                  {
                    std::ostringstream what;
                    what << "the " << name << " model of b/a = " << s << " ("
                         << discretisation.mesh.cells_along_front << " cells along and "
                         << discretisation.mesh.cells_around_front
                         << " around the front) failed: " << error.what()
                         << "; the mesh may be too coarse for so slender a gap (Elliptical model/"
                            "Cells along front and Sectors around front; the coarse model halves both)";
                    throw std::runtime_error(what.str());
                  }
              },
              lowest, shapes_sampled, solved.angles);
          solved.fe_models += family.n_models();
          return sampled;
        };

        // The coarse models first: their gaps show which shapes the fine
        // models need. Those sample from 5 % below the coarse model's
        // slenderest gap (the two discretisations' gaps differ by far less),
        // sparing the slender shapes where the Chebyshev points crowd and CG
        // takes longest.
        const SampledGapSifs coarse_sifs = sampled_family(coarse, "coarse FE", smallest);
        for (const double ratio : solved.tension_aspect_ratios)
          solved.coarse_fe.push_back(summit_gaps(coarse_sifs, ratio, solved.angles, smallest));
        double slenderest_gap = 1;
        for (const auto &gaps : solved.coarse_fe)
          slenderest_gap = std::min(slenderest_gap, gaps.adhesionless.aspect_ratio);
        solved.smallest_fine_shape     = std::max(smallest, 0.95 * slenderest_gap);
        const SampledGapSifs fine_sifs = sampled_family(fine, "FE", solved.smallest_fine_shape);
        for (const double ratio : solved.tension_aspect_ratios)
          try
            {
              solved.fe.push_back(summit_gaps(fine_sifs, ratio, solved.angles, solved.smallest_fine_shape));
            }
          catch (const std::runtime_error &error)
            {
              throw std::runtime_error(
                  "the FE search for Ay/Ax = " + shortest(ratio) +
                  " failed on b/a >= " + shortest(solved.smallest_fine_shape) +
                  " (5 % below the coarse model's slenderest gap): " + error.what() +
                  "; the coarse model (half the cells along and around the front) may be "
                  "too coarse (Elliptical model/Cells along front and Sectors around front)");
            }
        for (const double ratio : solved.tension_aspect_ratios)
          solved.sampled_exact.push_back(sampled_closed_form(solved.smallest_fine_shape, ratio));

        const auto adhesionless = [](const auto member) {
          return [member](const SummitGaps &g) { return g.adhesionless.*member; };
        };
        const auto adhesive = [](const auto member) {
          return [member](const SummitGaps &g) { return g.adhesive.*member; };
        };
        const Table adhesionless_table =
            quantity_table({{"b/a", adhesionless(&AdhesionlessSummitGap::aspect_ratio)},
                            {"a/Ax", adhesionless(&AdhesionlessSummitGap::a_over_Ax)},
                            {"b/Ay", adhesionless(&AdhesionlessSummitGap::b_over_Ay)},
                            {"gap area/tension area", adhesionless(&AdhesionlessSummitGap::area_ratio)},
                            {"largest |K_I|/(P K_uniform) on the front",
                             [](const SummitGaps &g) { return largest_magnitude(g.adhesionless_front); }}},
                           solved);
        const Table adhesive_table =
            quantity_table({{"b/a", adhesive(&AdhesiveSummitGap::aspect_ratio)},
                            {"a/(R_p K_Ic)^(2/5)", adhesive(&AdhesiveSummitGap::a)},
                            {"psi", adhesive(&AdhesiveSummitGap::tension)},
                            {"spread of K_I/K_Ic on the front",
                             [](const SummitGaps &g) { return spread(g.adhesive_front); }}},
                           solved);
        const Table front = summit_front_table(solved);

        solved.largest_error       = largest_relative_error(solved.fe, solved.exact);
        solved.interpolation_error = largest_relative_error(solved.sampled_exact, solved.exact);
        solved.estimated_error     = largest_relative_error(solved.fe, solved.coarse_fe);
        Table summary              = Table::summary();
        summary.add_row({"3D models solved (3 loads each)", solved.fe_models});
        summary.add_row({"shapes sampled per discretisation", shapes_sampled});
        summary.add_row({"smallest b/a sampled, coarse FE", smallest});
        summary.add_row({"smallest b/a sampled, FE (5 % below the coarse FE's slenderest gap)",
                         solved.smallest_fine_shape});
        summary.add_row({"MPI ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
        summary.add_row({"largest relative error of b/a, the area ratio and psi",
                         Table::Cell(solved.largest_error, Table::error_digits)});
        summary.add_row({"the same, of the closed form sampled as the FE is (the interpolation's share)",
                         Table::Cell(solved.interpolation_error, Table::error_digits)});
        summary.add_row({"its estimate from the two discretisations, largest |FE - coarse FE|/coarse FE",
                         Table::Cell(solved.estimated_error, Table::error_digits)});
        add_phase_times(summary, timer);

        publish(
            adhesionless_table, "adhesionless.csv", results, log,
            "\nWithout adhesion: the gap with K_I = 0 at phi = 0 and pi/2 under P (1 - x^2/Ax^2 - y^2/Ay^2)");
        publish(adhesive_table, "adhesive.csv", results, log,
                "\nWith adhesion (K_Ic = 1, R_p = (R_1 R_2)^(1/2) = 1): the least P with K_I = K_Ic at phi = "
                "0 and pi/2, psi = P/(K_Ic^4/R_p)^(1/5)");
        log << '\n';
        publish(summary, "summary.csv", results, log);
        results.write_csv("front.csv", front);
        return verdict(solved.largest_error);
      }

      EllipticalModel     model;
      std::vector<double> tension_aspect_ratios;
      unsigned int        shapes_sampled;
      unsigned int        front_points;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      EllipticalSummitsScene, "elliptical-summits", "Elliptical summits",
      "3D FE searches (distributed) for the gaps of summits P (1 - x^2/Ax^2 - y^2/Ay^2): without adhesion "
      "K_I = 0, with adhesion K_I = K_Ic at the ends of the front at the least P (psi), beside Galin's "
      "closed form",
      "largest relative error of b/a, the gap-area ratio and psi")
} // namespace penny
