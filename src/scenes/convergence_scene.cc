#include "scenes/convergence_scene.h"

#include "scenes/penny_gap_scene.h"
#include "scenes/scene_support.h"

#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iomanip>
#include <memory>

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

    // One timer for the scene; a cycle's phases are the differences of its
    // totals, so an adaptive refinement counts towards the cycle it builds.
    TimerOutput                    timer(log, TimerOutput::never, TimerOutput::wall_times);
    const auto                     base = penny_gap_model(parameters);
    const LoadParameters          &load = *parameters.load;
    std::unique_ptr<PennyGapModel> adaptive_model;
    std::vector<ConvergenceRow>    rows;
    for (unsigned int k = 0; k < sequence.cycles; ++k)
      {
        auto before                 = timer.get_summary_data(TimerOutput::total_wall_time);
        const auto [model, setting] = cycle_model(base, sequence, k);
        PennySceneResults solved;
        if (sequence.strategy == Strategy::adaptive)
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

        ConvergenceRow row{k, solved.n_cells, solved.n_dofs, setting, {}, 0, 0, 0};
        for (const auto &ring : solved.rings)
          {
            row.stress_intensity_factors.push_back(ring.signed_stress_intensity_factor);
            row.error = std::max(row.error, relative_error(ring.signed_stress_intensity_factor,
                                                           solved.exact_stress_intensity_factor.value));
          }
        if (!rows.empty())
          row.rate =
              -std::log(row.error / rows.back().error) / std::log(double(row.n_dofs) / rows.back().n_dofs);
        auto times = timer.get_summary_data(TimerOutput::total_wall_time);
        for (auto &[phase, seconds] : times)
          {
            seconds -= before[phase];
            row.wall_time += seconds;
          }
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        const double peak_memory =
            Utilities::MPI::max(memory.VmHWM / 1024., MPI_COMM_WORLD); // of the largest rank

        std::vector<Table::Cell> cells = {k, setting, row.n_cells, row.n_dofs};
        for (const double K : row.stress_intensity_factors)
          cells.push_back(K);
        cells.push_back(row.error);
        cells.push_back(rows.empty() ? Table::Cell("") : Table::Cell(row.rate));
        for (const auto &phase : phases)
          cells.push_back(times.count(phase) ? times.at(phase) : 0.);
        cells.push_back(row.wall_time);
        cells.push_back(peak_memory);
        cells.push_back(solved.solver);
        table.add_row(cells);
        log << std::setw(3) << k << "  " << setting_name(sequence.strategy) << " " << std::setw(8) << setting
            << "  DoFs " << std::setw(8) << row.n_dofs << "  error " << std::scientific
            << std::setprecision(3) << row.error << "  rate " << std::defaultfloat << std::setprecision(3)
            << row.rate << "  wall " << row.wall_time << " s" << std::endl;
        rows.push_back(row);
      }
    log << '\n';
    table.print(log);
    results.write_csv("convergence.csv", table);
    return rows;
  }
} // namespace penny
