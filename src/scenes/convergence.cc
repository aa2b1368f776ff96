// convergence: the penny-gap solve over a sequence of discretisations (more
// global refinements, more tip levels, higher degrees, larger domains, or
// Kelly-adaptive refinement), K_I on every ring against the closed form, the
// observed rate against the DoFs, and the time of every phase, in one table
// (postprocess/plot_convergence.py draws it).
#include "numerics/relative_error.h"
#include "output/progress.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "problems/penny_gap.h"
#include "scenes/scene.h"

#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace penny
{
  namespace
  {
    using namespace dealii;

    enum class Strategy
    {
      uniform_h,
      tip_grading,
      degree,
      domain_size,
      adaptive
    };

    // The sequence of discretisations of the convergence scene.
    struct ConvergenceParameters
    {
      Strategy     strategy;
      unsigned int cycles;
      unsigned int first_tip_levels, tip_levels_step;
      double       refined_fraction; // adaptive: share of cells refined per cycle
    };

    // The model of cycle k, and the value the sequence varies.
    std::pair<PennyGapModelParameters, double>
    cycle_model(PennyGapModelParameters model, const ConvergenceParameters &sequence, const unsigned int k)
    {
      switch (sequence.strategy)
        {
        case Strategy::uniform_h:
          model.mesh.global_refinements = k;
          return {model, double(k)};
        case Strategy::tip_grading:
          model.mesh.tip_levels = sequence.first_tip_levels + k * sequence.tip_levels_step;
          return {model, double(model.mesh.tip_levels)};
        case Strategy::degree:
          model.degree = k + 1;
          return {model, double(k + 1)};
        case Strategy::adaptive: // cycle k refines the mesh of cycle k - 1
          model.mesh.tip_levels = sequence.first_tip_levels;
          return {model, double(k)};
        case Strategy::domain_size:
          {
            // R/c from 10 to 1e4, evenly in log.
            const double ratio           = std::pow(10., 1 + 3. * k / std::max(1u, sequence.cycles - 1));
            model.geometry.domain_radius = ratio * model.geometry.gap_radius;
            model.geometry.domain_height = ratio * model.geometry.gap_radius;
            return {model, ratio};
          }
        }
      return {model, 0.};
    }

    const char *setting_name(const Strategy strategy)
    {
      switch (strategy)
        {
        case Strategy::uniform_h:
          return "refinements";
        case Strategy::tip_grading:
          return "tip levels";
        case Strategy::degree:
          return "degree";
        case Strategy::adaptive:
          return "Kelly refinements";
        case Strategy::domain_size:
          return "R/c";
        }
      return "";
    }
    PennyGapModelParameters on_one_rank(PennyGapModelParameters model)
    {
      model.communicator = MPI_COMM_SELF;
      return model;
    }

    // A row of the table of one cycle.
    struct ConvergenceRow
    {
      unsigned int        cycle, n_cells, n_dofs;
      double              setting;
      std::vector<double> stress_intensity_factors; // signed K_I per ring
      double              error;                    // largest relative error over the rings
      double              rate;                     // -d log(error)/d log(DoFs) from the previous cycle
      double              wall_time;
    };

    struct ConvergenceScene : Scene
    {
      void inputs(Sections &sections) override
      {
        gap.sections(sections, &load);
        sections.check([&] {
          // A gmsh mesh has no tip levels: every cycle would be the same.
          if (sequence.strategy == Strategy::tip_grading &&
              gap.model.mesh.generator == MeshParameters::Generator::gmsh)
            throw InputError("Convergence/Strategy = tip-grading needs Mesh/Generator = builtin (a gmsh mesh "
                             "has no tip levels to add; uniform-h, degree or adaptive refine it)");
          check_cycle_sizes();
        });
      }

      void entries(Entries &entries) override
      {
        entries.choice(
            "Strategy", sequence.strategy, Strategy::tip_grading,
            EnumNames<Strategy>{{"uniform-h", Strategy::uniform_h},
                                {"tip-grading", Strategy::tip_grading},
                                {"degree", Strategy::degree},
                                {"domain-size", Strategy::domain_size},
                                {"adaptive", Strategy::adaptive}},
            "The sequence of the convergence scene: uniform-h, one more global refinement per cycle of "
            "the scene's mesh; tip-grading, 'Tip levels step' more tip levels per cycle from 'First tip "
            "levels'; degree, degree 1 to 4 on the scene's mesh; domain-size, R/c = H/c from 10 to 1e4 "
            "at the scene's near-tip mesh; adaptive, from the mesh with 'First tip levels', each cycle "
            "refines the 'Refined fraction' of cells with the largest Kelly error indicators of the "
            "displacement. The entry a sequence varies (Mesh/Global refinements, Mesh/Tip refinement "
            "levels, Finite element/Polynomial degree, Geometry/Domain radius R and Domain height H) is "
            "replaced in each cycle.");
        entries.integer("Cycles", sequence.cycles, 4u, 1u, 30u, "Number of discretisations. Units: none.");
        entries.integer("First tip levels", sequence.first_tip_levels, 4u, 0u, 40u,
                        "tip-grading and adaptive: levels of cycle 0. Units: none.");
        entries.integer("Tip levels step", sequence.tip_levels_step, 4u, 1u, 20u,
                        "tip-grading: levels added per cycle. Units: none.");
        entries.number("Refined fraction", sequence.refined_fraction, 0.1, interval("(]", 0, 1),
                       "adaptive: share of the cells, those with the largest Kelly indicators, refined "
                       "per cycle. Units: none.");
        if (sequence.strategy == Strategy::degree)
          entries.require(sequence.cycles <= 4, "Cycles", sequence.cycles, "[1, 4] for Strategy = degree");
        if (sequence.strategy == Strategy::tip_grading)
          entries.require(sequence.first_tip_levels + (sequence.cycles - 1) * sequence.tip_levels_step <= 40,
                          "Cycles", sequence.cycles, "[1, 1 + (40 - First tip levels)/Tip levels step]");
      }

      // Every model lives on one rank, so each wall time is that of one core
      // (other ranks' cycles run beside it on the other cores) and the table
      // is the same on any number of ranks. The cycles are spread over the
      // ranks, except in the adaptive sequence, whose cycle k refines the
      // mesh of cycle k - 1: it is one piece of work, its cycles in turn on one rank.
      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        const auto                    &radii  = gap.ring_radii;
        const std::vector<std::string> phases = {"mesh",  "setup",      "assembly",
                                                 "solve", "J-integral", "closed form"};
        const Table::Format            digits{12, false};
        std::vector<Table::Column>     columns = {
                {"cycle"}, {setting_name(sequence.strategy), digits}, {"cells"}, {"DoFs"}};
        for (const double rho : radii)
          columns.push_back({"K_I ring " + Utilities::to_string(rho) + " (Pa m^1/2)", digits});
        columns.push_back({"relative error", Table::error_digits});
        columns.push_back({"rate", Table::Format{3, false}});
        for (const auto &phase : phases)
          columns.push_back({phase + " (s)", Table::Format{3, false}});
        for (const std::string name : {"wall (s)", "peak memory (MiB)"})
          columns.push_back({name, Table::Format{4, false}});
        columns.push_back({"solver"});
        Table table(columns);

        const bool adaptive = sequence.strategy == Strategy::adaptive;
        const auto base     = on_one_rank(gap.model);

        // One timer for the cycles of a rank; a cycle's phases are the
        // differences of its totals, so an adaptive refinement counts towards the
        // cycle it builds. A cycle's row: cells, DoFs, the setting, K_I per
        // ring, the largest relative error, the time of each phase, the wall
        // time and the peak memory of the rank (MiB).
        TimerOutput                    timer(log, TimerOutput::never, TimerOutput::wall_times);
        std::unique_ptr<PennyGapModel> adaptive_model;
        Progress                       progress(log, "cycles done");
        const auto                     cycle = [&](const unsigned int k) {
          auto before = timer.get_summary_data(TimerOutput::total_wall_time);
          const auto [model, setting] = cycle_model(base, sequence, k);
          PennyGapMeasurement solved;
          if (adaptive)
            {
              const FaceLoad face_load(load, model.geometry.gap_radius);
              if (k == 0)
                adaptive_model = std::make_unique<PennyGapModel>(model, timer);
              else
                {
                  refinement_check(k, adaptive_model->get_system().get_triangulation().n_active_cells());
                  adaptive_model->refine_by_kelly(adaptive_model->solve(face_load),
                                                                      sequence.refined_fraction);
                }
              solved = measure_penny_gap(*adaptive_model, face_load, radii, timer);
            }
          else
            solved = solve_penny_gap(model, load, radii, timer);

          std::vector<double> row = {double(solved.n_cells), double(solved.n_dofs), setting};
          double              error = 0;
          for (const auto &ring : solved.rings)
            {
              row.push_back(ring.signed_stress_intensity_factor);
              error = worse(error, relative_error(ring.signed_stress_intensity_factor,
                                                                      solved.exact_stress_intensity_factor.value));
            }
          row.push_back(error);
          auto   times = timer.get_summary_data(TimerOutput::total_wall_time);
          double wall  = 0;
          for (const auto &phase : phases)
            {
              const double seconds = times.count(phase) ? times.at(phase) - before[phase] : 0.;
              row.push_back(seconds);
              wall += seconds;
            }
          row.push_back(wall);
          Utilities::System::MemoryStats memory;
          Utilities::System::get_memory_stats(memory);
          row.push_back(memory.VmHWM / 1024.);
          std::ostringstream state;
          state << setting_name(sequence.strategy) << ' ' << setting << ": DoFs " << solved.n_dofs
                << ", error " << std::scientific << std::setprecision(3) << error;
          progress.step(state.str());
          return row;
        };
        std::vector<std::vector<double>> measured;
        if (adaptive)
          {
            const std::vector<double> rows       = spread_over_ranks(MPI_COMM_WORLD, 1, [&](unsigned int) {
              std::vector<double> all;
              for (unsigned int k = 0; k < sequence.cycles; ++k)
                for (const double value : cycle(k))
                  all.push_back(value);
              return all;
            })[0];
            const std::size_t         row_length = rows.size() / sequence.cycles;
            for (auto row = rows.begin(); row != rows.end(); row += row_length)
              measured.emplace_back(row, row + row_length);
          }
        else
          measured = spread_over_ranks(MPI_COMM_WORLD, sequence.cycles, cycle);

        const std::string           solver = solver_name(gap.model.linear_solver, MPI_COMM_SELF);
        std::vector<ConvergenceRow> rows;
        for (unsigned int k = 0; k < sequence.cycles; ++k)
          {
            const auto       &m = measured[k];
            const std::size_t n = radii.size();
            ConvergenceRow    row{k,
                               static_cast<unsigned int>(m[0]),
                               static_cast<unsigned int>(m[1]),
                               m[2],
                               std::vector<double>(m.begin() + 3, m.begin() + 3 + n),
                               m[3 + n],
                               0,
                               m[4 + n + phases.size()]};
            if (!rows.empty())
              row.rate = -std::log(row.error / rows.back().error) /
                         std::log(double(row.n_dofs) / rows.back().n_dofs);
            std::vector<Table::Cell> cells = {k, row.setting, row.n_cells, row.n_dofs};
            for (const double K : row.stress_intensity_factors)
              cells.push_back(K);
            cells.push_back(row.error);
            cells.push_back(rows.empty() ? Table::Cell("") : Table::Cell(row.rate));
            for (std::size_t i = 0; i < phases.size() + 2; ++i) // the phases, the wall time, the memory
              cells.push_back(m[4 + n + i]);
            cells.push_back(solver);
            table.add_row(cells);
            rows.push_back(row);
          }
        log << '\n';
        publish(table, "convergence.csv", results, log);
        return {};
      }

      // Every cycle's model must fit, each built on one rank; the cycles of
      // the adaptive sequence are checked as they refine (refinement_check).
      void check_cycle_sizes() const
      {
        const unsigned int checked = sequence.strategy == Strategy::adaptive ? 1 : sequence.cycles;
        for (unsigned int k = 0; k < checked; ++k)
          in_cycle(k, [&] {
            const PennyGapModelParameters cycle = cycle_model(on_one_rank(gap.model), sequence, k).first;
            check_model_size(cycle, model_cells(cycle));
          });
      }

      // Before the adaptive cycle k refines the mesh of `cells` cells.
      void refinement_check(const unsigned int k, const double cells) const
      {
        in_cycle(k, [&] {
          check_model_size(on_one_rank(gap.model),
                           PennyGapModel::cells_after_refinement(cells, sequence.refined_fraction),
                           ", Convergence/Refined fraction = " + shortest(sequence.refined_fraction) +
                               " (adaptive cycles)");
        });
      }

      // Runs `check`, its InputError saying which cycle failed.
      template <typename Check> void in_cycle(const unsigned int k, Check &&check) const
      {
        try
          {
            check();
          }
        catch (const InputError &error)
          {
            throw InputError("Convergence: cycle " + std::to_string(k) + " (cycles 0 to " +
                             std::to_string(sequence.cycles - 1) + "): " + error.what());
          }
      }

      PennyGapInput         gap;
      LoadParameters        load;
      ConvergenceParameters sequence;
    };
  } // namespace

  PENNY_REGISTER_SCENE(ConvergenceScene, "convergence", "Convergence",
                       "the penny-gap solve over the sequence of discretisations in 'Convergence'", "")
} // namespace penny
