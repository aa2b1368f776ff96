#include "convergence_scene.h"

#include "output_files.h"
#include "penny_scene.h"

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

    // The parameters of one cycle, and the value the sequence varies.
    std::pair<Parameters, double> cycle_parameters(Parameters parameters, const unsigned int k)
    {
      const auto &sequence           = parameters.convergence;
      parameters.output.write_fields = false;
      switch (sequence.strategy)
        {
          case Strategy::uniform_h:
            parameters.mesh.global_refinements = k;
            return {parameters, double(k)};
          case Strategy::tip_grading:
            parameters.mesh.tip_levels = sequence.first_tip_levels + k * sequence.tip_levels_step;
            return {parameters, double(parameters.mesh.tip_levels)};
          case Strategy::degree:
            parameters.finite_element.degree = k + 1;
            return {parameters, double(k + 1)};
          case Strategy::adaptive: // cycle k refines the mesh of cycle k - 1
            parameters.mesh.tip_levels = sequence.first_tip_levels;
            return {parameters, double(k)};
          case Strategy::domain_size:
            {
              // R/c from 10 to 1e4, evenly in log.
              const double ratio = std::pow(10., 1 + 3. * k / std::max(1u, sequence.cycles - 1));
              parameters.geometry.domain_radius = ratio * parameters.geometry.gap_radius;
              parameters.geometry.domain_height = ratio * parameters.geometry.gap_radius;
              return {parameters, ratio};
            }
        }
      return {parameters, 0.};
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

  std::vector<ConvergenceRow> run_convergence_scene(const Parameters &parameters, std::ostream &log)
  {
    const auto                 &sequence = parameters.convergence;
    const std::vector<std::string> phases = {"mesh", "setup", "assembly", "solve", "J-integral"};
    std::vector<ConvergenceRow> rows;
    std::ostringstream          table;
    table << "cycle," << setting_name(sequence.strategy) << ",cells,DoFs";
    for (const double rho : parameters.j_integral.ring_radii)
      table << ",K_I ring " << rho << " (Pa m^1/2)";
    table << ",relative error,rate";
    for (const auto &phase : phases)
      table << "," << phase << " (s)";
    table << ",wall (s),peak memory (MiB),solver\n" << std::setprecision(12);

    // One timer for the scene; a cycle's phases are the differences of its
    // totals, so an adaptive refinement counts towards the cycle it builds.
    TimerOutput                    timer(log, TimerOutput::never, TimerOutput::wall_times);
    std::unique_ptr<PennyGapModel> adaptive_model;
    for (unsigned int k = 0; k < sequence.cycles; ++k)
      {
        auto before = timer.get_summary_data(TimerOutput::total_wall_time);
        const auto [cycle, setting] = cycle_parameters(parameters, k);
        PennySceneResults results;
        if (sequence.strategy == Strategy::adaptive)
          {
            if (k == 0)
              adaptive_model = std::make_unique<PennyGapModel>(cycle, timer);
            else
              adaptive_model->refine_by_kelly(
                adaptive_model->solve(FaceLoad(cycle.load, cycle.geometry.gap_radius)), sequence.refined_fraction);
            results = measure_penny_gap(*adaptive_model, timer);
          }
        else
          results = solve_penny_gap(cycle, timer);

        ConvergenceRow row{k, results.n_cells, results.n_dofs, setting, {}, 0, 0, 0};
        for (const auto &ring : results.rings)
          {
            row.stress_intensity_factors.push_back(ring.signed_stress_intensity_factor);
            row.error = std::max(row.error, std::abs(ring.signed_stress_intensity_factor / results.exact_stress_intensity_factor - 1));
          }
        if (!rows.empty())
          row.rate = -std::log(row.error / rows.back().error) / std::log(double(row.n_dofs) / rows.back().n_dofs);
        auto times = timer.get_summary_data(TimerOutput::total_wall_time);
        for (auto &[phase, seconds] : times)
          {
            seconds -= before[phase];
            row.wall_time += seconds;
          }
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        const double peak_memory = Utilities::MPI::max(memory.VmHWM / 1024., MPI_COMM_WORLD); // of the largest rank

        table << k << ',' << setting << ',' << row.n_cells << ',' << row.n_dofs;
        for (const double K : row.stress_intensity_factors)
          table << ',' << K;
        table << ',' << row.error << ',' << (rows.empty() ? std::string("") : Utilities::to_string(row.rate));
        for (const auto &phase : phases)
          table << ',' << (times.count(phase) ? times.at(phase) : 0.);
        table << ',' << row.wall_time << ',' << peak_memory << ','
              << solver_name(cycle.linear_solver) << '\n';
        log << std::setw(3) << k << "  " << setting_name(sequence.strategy) << " " << std::setw(8) << setting
            << "  DoFs " << std::setw(8) << row.n_dofs << "  error " << std::scientific << std::setprecision(3)
            << row.error << "  rate " << std::defaultfloat << std::setprecision(3) << row.rate << "  wall "
            << row.wall_time << " s" << std::endl;
        rows.push_back(row);
      }
    write_atomically(std::filesystem::path(parameters.output.directory) / "convergence.csv",
                     [&](std::ostream &out) { out << table.str(); });
    return rows;
  }
} // namespace penny
