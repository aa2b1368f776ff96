#include "penny_scene.h"

#include "face_load.h"
#include "field_output.h"
#include "gap_mesh.h"
#include "j_integral.h"
#include "output_files.h"
#include "penny_gap_model.h"
#include "sneddon_solution.h"

#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>

namespace penny
{
  using namespace dealii;

  namespace
  {
    double relative_error(const double value, const double exact)
    {
      return std::abs(value / exact - 1);
    }

    void write_ring_table(std::ostream &out, const PennySceneResults &results, const char separator)
    {
      const int width = separator == ',' ? 0 : 18;
      const std::vector<std::string> columns = {"ring (c)",
                                                "J (J/m^2)",
                                                "|K_I| FE (Pa m^1/2)",
                                                "K_I signed FE (Pa m^1/2)",
                                                "K_I exact (Pa m^1/2)",
                                                "|K_I| relative error"};
      for (unsigned int i = 0; i < columns.size(); ++i)
        out << (i > 0 ? std::string(1, separator) : "") << std::setw(width + 6 * (i == 3)) << columns[i];
      // The CSV keeps every digit; the printed table 11 significant ones.
      out << '\n' << std::setprecision(separator == ',' ? 16 : 10) << std::scientific;
      const double exact = results.exact_stress_intensity_factor;
      for (const auto &ring : results.rings)
        out << std::setw(width) << ring.radius << separator << std::setw(width) << ring.energy_release_rate
            << separator << std::setw(width) << ring.stress_intensity_factor << separator << std::setw(width + 6)
            << ring.signed_stress_intensity_factor << separator << std::setw(width) << exact << separator
            << std::setw(width) << relative_error(ring.stress_intensity_factor, std::abs(exact)) << '\n';
      out << std::defaultfloat;
    }

    void write_summary(std::ostream &out, const PennySceneResults &results, const Parameters &parameters, TimerOutput &timer)
    {
      out << std::setprecision(10) << std::scientific;
      out << "cells                   " << results.n_cells << '\n'
          << "DoFs                    " << results.n_dofs << '\n'
          << "degree                  " << parameters.finite_element.degree << '\n'
          << "MPI ranks               " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << '\n'
          << "solver                  " << solver_name(parameters.linear_solver) << '\n'
          << "relative residual       " << results.relative_residual << '\n'
          << "opening w(0) FE (m)     " << results.opening_at_centre << '\n'
          << "opening w(0) exact (m)  " << results.exact_opening_at_centre << '\n'
          << "opening relative error  " << relative_error(results.opening_at_centre, results.exact_opening_at_centre) << '\n'
          << "gap volume FE (m^3)     " << results.gap_volume << '\n'
          << "gap volume exact (m^3)  " << results.exact_gap_volume << '\n'
          << "volume relative error   " << relative_error(results.gap_volume, results.exact_gap_volume) << '\n';
      out << std::defaultfloat << std::setprecision(3);
      for (const auto &[phase, seconds] : timer.get_summary_data(TimerOutput::total_wall_time))
        out << "wall time " << std::left << std::setw(14) << phase << std::right << seconds << " s\n";
    }
  } // namespace

  PennySceneResults solve_penny_gap(const Parameters &parameters, TimerOutput &timer)
  {
    PennyGapModel model(parameters, timer);
    return measure_penny_gap(model, timer);
  }

  PennySceneResults measure_penny_gap(PennyGapModel &model, TimerOutput &timer)
  {
    const Parameters &parameters = model.parameters();
    const double      c          = parameters.geometry.gap_radius;
    const FaceLoad    load(parameters.load, c);
    const DisplacementVector u     = model.solve(load);
    const FaceLoad       reference = FaceLoad::unit_uniform();
    const double         residual  = model.last_solve().relative_residual;
    const DisplacementVector u_ref = model.solve(reference);

    PennySceneResults results;
    {
      TimerOutput::Scope scope(timer, "J-integral");
      const JIntegral j_integral(model);
      const double    e_prime = parameters.material.plane_strain_modulus();
      for (const double rho : parameters.j_integral.ring_radii)
        {
          const double G = j_integral.energy_release_rate(u, load, rho * c);
          results.rings.push_back({rho,
                                   G,
                                   std::sqrt(e_prime * std::max(G, 0.)),
                                   j_integral.signed_stress_intensity_factor(u, load, u_ref, reference, rho * c)});
        }
      const SneddonSolution exact(load, c, e_prime);
      results.exact_stress_intensity_factor = exact.stress_intensity_factor();
      results.opening_at_centre             = model.opening_at_centre(u);
      results.exact_opening_at_centre       = exact.opening(0);
      results.gap_volume                    = model.gap_volume(u);
      results.exact_gap_volume              = exact.gap_volume();
    }
    results.n_cells           = model.triangulation().n_global_active_cells();
    results.n_dofs            = model.dof_handler().n_dofs();
    results.relative_residual = std::max(residual, model.last_solve().relative_residual);
    results.condition_estimate = model.last_solve().condition_estimate;

    if (parameters.output.write_fields)
      {
        TimerOutput::Scope scope(timer, "output");
        const double largest = *std::max_element(parameters.j_integral.ring_radii.begin(), parameters.j_integral.ring_radii.end());
        write_fields(model, u, RingWeight{crack_tip(parameters.geometry), largest * c}, parameters.output.directory);
      }
    return results;
  }

  PennySceneResults run_penny_scene(const Parameters &parameters, std::ostream &log)
  {
    const std::filesystem::path directory(parameters.output.directory);
    TimerOutput                 timer(log, TimerOutput::never, TimerOutput::wall_times);
    const PennySceneResults     results = solve_penny_gap(parameters, timer);

    write_ring_table(log, results, ' ');
    if (results.rings.front().signed_stress_intensity_factor < 0)
      log << "K_I < 0: the faces would interpenetrate; no open gap of this radius carries this load.\n";
    log << '\n';
    write_summary(log, results, parameters, timer);
    write_atomically(directory / "rings.csv", [&](std::ostream &out) { write_ring_table(out, results, ','); });
    write_atomically(directory / "summary.txt", [&](std::ostream &out) { write_summary(out, results, parameters, timer); });
    return results;
  }
} // namespace penny
