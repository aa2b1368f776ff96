#include "scenes/convergence_scene.h"

#include "input/input_error.h"
#include "output/progress.h"
#include "parallel/spread_over_ranks.h"
#include "scenes/penny_gap_scene.h"
#include "scenes/scene_support.h"

#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    using Strategy = ConvergenceParameters::Strategy;

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
  } // namespace

  // Every model lives on one rank, so each wall time is that of one core
  // (other ranks' cycles run beside it on the other cores) and the table is
  // the same on any number of ranks. The cycles are spread over the ranks,
  // except in the adaptive sequence, whose cycle k refines the mesh of cycle
  // k - 1: it is one piece of work, its cycles in turn on one rank.
  std::vector<ConvergenceRow> run_convergence_scene(const Parameters &parameters, const ResultFolder &results,
                                                    std::ostream &log)
  {
    const auto                    &sequence = *parameters.convergence;
    const auto                    &radii    = parameters.j_integral->ring_radii;
    const std::vector<std::string> phases   = {"mesh",  "setup",      "assembly",
                                               "solve", "J-integral", "closed form"};
    const Table::Format            digits{12, false};
    std::vector<Table::Column>     columns = {
            {"cycle"}, {setting_name(sequence.strategy), digits}, {"cells"}, {"DoFs"}};
    for (const double rho : radii)
      columns.push_back({"K_I ring " + Utilities::to_string(rho) + " (Pa m^1/2)", digits});
    columns.push_back({"relative error", Table::Format{3, true}});
    columns.push_back({"rate", Table::Format{3, false}});
    for (const auto &phase : phases)
      columns.push_back({phase + " (s)", Table::Format{3, false}});
    for (const std::string name : {"wall (s)", "peak memory (MiB)"})
      columns.push_back({name, Table::Format{4, false}});
    columns.push_back({"solver"});
    Table table(columns);

    const bool            adaptive = sequence.strategy == Strategy::adaptive;
    auto                  base     = penny_gap_model(parameters);
    const LoadParameters &load     = *parameters.load;
    base.communicator              = MPI_COMM_SELF;

    // One timer for the cycles of a rank; a cycle's phases are the
    // differences of its totals, so an adaptive refinement counts towards the
    // cycle it builds. A cycle's row: cells, DoFs, the setting, K_I per
    // ring, the largest relative error, the time of each phase, the wall
    // time and the peak memory of the rank (MiB).
    TimerOutput                    timer(log, TimerOutput::never, TimerOutput::wall_times);
    std::unique_ptr<PennyGapModel> adaptive_model;
    Progress                       progress(log, "cycles done");
    const auto                     cycle = [&](const unsigned int k) {
      auto before                 = timer.get_summary_data(TimerOutput::total_wall_time);
      const auto [model, setting] = cycle_model(base, sequence, k);
      PennySceneResults solved;
      try
        {
          if (adaptive)
            {
              const FaceLoad face_load(load, model.geometry.gap_radius);
              if (k == 0)
                adaptive_model = std::make_unique<PennyGapModel>(model, timer);
              else
                adaptive_model->refine_by_kelly(adaptive_model->solve(face_load), sequence.refined_fraction);
              solved = measure_penny_gap(*adaptive_model, face_load, radii, timer);
            }
          else
            solved = solve_penny_gap(model, load, radii, timer);
        }
      catch (const InputError &error) // a model too large, say: which cycle
        {
          throw InputError("Convergence: cycle " + std::to_string(k) + " (cycles 0 to " +
                                               std::to_string(sequence.cycles - 1) + "): " + error.what());
        }

      std::vector<double> row = {double(solved.n_cells), double(solved.n_dofs), setting};
      double              error = 0;
      for (const auto &ring : solved.rings)
        {
          row.push_back(ring.signed_stress_intensity_factor);
          error = std::max(error, relative_error(ring.signed_stress_intensity_factor,
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
      state << setting_name(sequence.strategy) << ' ' << setting << ": DoFs " << solved.n_dofs << ", error "
            << std::scientific << std::setprecision(3) << error;
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

    const std::string           solver = solver_name(parameters.linear_solver.value(), MPI_COMM_SELF);
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
          row.rate =
              -std::log(row.error / rows.back().error) / std::log(double(row.n_dofs) / rows.back().n_dofs);
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
    table.print(log);
    results.write_csv("convergence.csv", table);
    return rows;
  }
} // namespace penny
