#include "scenes/elliptical_scenes.h"

#include "fracture/elliptical_crack.h"
#include "fracture/front_stress_intensity.h"
#include "output/elliptical_fields.h"
#include "output/table.h"
#include "scenes/scene_support.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    const Table::Format digits{10, true}, error_digits{3, true}, seconds{3, false};

    // A ring radius as written in the parameter file, e.g. "0.2".
    std::string ring_name(const double rho)
    {
      std::ostringstream name;
      name << "ring " << rho << " b^2/a";
      return name.str();
    }

    // Sum over the ranks of the peak resident set size (MB).
    double peak_memory(MPI_Comm communicator)
    {
      Utilities::System::MemoryStats stats;
      Utilities::System::get_memory_stats(stats);
      return Utilities::MPI::sum(static_cast<double>(stats.VmHWM), communicator) / 1024;
    }

    Table front_table(const EllipticalGapParameters &gap, const EllipticalGapResults &solved)
    {
      std::vector<Table::Column> columns = {{"phi (rad)", Table::Format{6, false}},
                                            {"x (m)", Table::Format{6, false}},
                                            {"y (m)", Table::Format{6, false}},
                                            {"K_I exact (Pa m^1/2)", digits}};
      for (const double rho : solved.ring_radii)
        {
          const std::string ring = ring_name(rho);
          columns.push_back({"K_I signed FE " + ring + " (Pa m^1/2)", digits});
          columns.push_back({"relative error " + ring, error_digits});
        }
      Table        table(columns);
      const double a = gap.semi_axis_a, b = gap.aspect_ratio * a;
      for (unsigned int i = 0; i < solved.angles.size(); ++i)
        {
          const double             phi = solved.angles[i];
          std::vector<Table::Cell> row = {phi, a * std::cos(phi), b * std::sin(phi), solved.exact_sifs[i]};
          for (const auto &ring : solved.signed_sifs)
            {
              row.emplace_back(ring[i]);
              row.emplace_back(relative_error(ring[i], solved.exact_sifs[i]));
            }
          table.add_row(row);
        }
      return table;
    }

    Table summary_table(const Parameters &parameters, const EllipticalGapResults &solved,
                        const TimerOutput &timer)
    {
      const auto &gap     = *parameters.elliptical_gap;
      Table       summary = Table::summary();
      const auto  row     = [&](const std::string &name, const double value, const Table::Format format) {
        summary.add_row({name, Table::Cell(value, format)});
      };
      row("b/a", gap.aspect_ratio, Table::Format{6, false});
      summary.add_row({"cells", solved.n_cells});
      summary.add_row({"DoFs", solved.n_dofs});
      summary.add_row({"degree", parameters.finite_element->degree});
      summary.add_row({"MPI ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
      summary.add_row({"solver", solved.solver});
      summary.add_row({"CG iterations", solved.iterations});
      row("relative residual", solved.relative_residual, digits);
      for (unsigned int r = 0; r < solved.ring_radii.size(); ++r)
        {
          double worst = 0;
          for (unsigned int i = 0; i < solved.angles.size(); ++i)
            worst = std::max(worst, relative_error(solved.signed_sifs[r][i], solved.exact_sifs[i]));
          row("largest K_I relative error, " + ring_name(solved.ring_radii[r]), worst, error_digits);
        }
      row("w(0) FE (m)", solved.opening_at_centre, digits);
      row("w(0) exact (m)", solved.exact_opening_at_centre, digits);
      row("w(0) relative error", relative_error(solved.opening_at_centre, solved.exact_opening_at_centre),
          error_digits);
      row("gap volume relative error", relative_error(solved.gap_volume, solved.exact_gap_volume),
          error_digits);
      row("peak memory, all ranks (MB)", solved.peak_memory, Table::Format{5, false});
      add_phase_times(summary, timer);
      return summary;
    }
  } // namespace

  EllipticalGapModelParameters elliptical_gap_model(const Parameters &parameters)
  {
    const auto                 &gap = *parameters.elliptical_gap;
    EllipticalGapMeshParameters mesh;
    mesh.semi_axis_a        = gap.semi_axis_a;
    mesh.semi_axis_b        = gap.aspect_ratio * gap.semi_axis_a;
    mesh.domain_width       = gap.box_width;
    mesh.domain_height      = gap.box_height;
    mesh.cells_along_front  = gap.cells_along_front;
    mesh.cells_around_front = gap.sectors;
    mesh.front_cell_size    = gap.front_cell_size;
    mesh.ring_ratio         = gap.ring_ratio;
    return {mesh, gap.global_refinements, *parameters.material, parameters.finite_element->degree,
            *parameters.linear_solver};
  }

  EllipticalGapResults run_elliptical_gap_scene(const Parameters &parameters, const ResultFolder &results,
                                                std::ostream &log)
  {
    const auto &gap = *parameters.elliptical_gap;
    TimerOutput timer(log, TimerOutput::never, TimerOutput::wall_times);
    log << "Building the quarter model of the gap b/a = " << gap.aspect_ratio << "...\n" << std::flush;
    EllipticalGapModel model(elliptical_gap_model(parameters), timer);
    const auto        &system = model.get_system();
    log << system.get_triangulation().n_global_active_cells() << " cells, "
        << system.get_dof_handler().n_dofs() << " DoFs, " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
        << " MPI rank(s); solving...\n"
        << std::flush;
    const double                       p        = gap.pressure;
    const EllipticalGapModel::Traction pressure = [p](const Point<3> &) { return p; };
    const DisplacementVector           u        = model.solve(pressure);

    EllipticalGapResults solved;
    solved.angles     = front_point_angles(gap.front_points);
    solved.ring_radii = gap.ring_radii;
    {
      TimerOutput::Scope scope(timer, "J-integral");
      log << "K_I at " << solved.angles.size() << " front points on " << solved.ring_radii.size()
          << " ring(s)...\n"
          << std::flush;
      // The signed K_I takes the unit pressure as reference; by linearity its
      // displacement is u/p, no second solve.
      DisplacementVector u_unit = u;
      u_unit /= p;
      const EllipticalGapModel::Traction unit = [](const Point<3> &) { return 1.; };
      const FrontStressIntensity front(model, solved.angles, gap.weight_half_width, solved.ring_radii);
      solved.signed_sifs = front.signed_sifs(u, pressure, u_unit, unit);
    }
    const double               e_prime = model.material().plane_strain_modulus();
    const GreenSneddonSolution exact(model.front().semi_axis_a(), model.front().semi_axis_b(), p, e_prime);
    solved.largest_error = 0;
    for (const double phi : solved.angles)
      solved.exact_sifs.push_back(exact.stress_intensity_factor(phi));
    for (const auto &ring : solved.signed_sifs)
      for (unsigned int i = 0; i < ring.size(); ++i)
        solved.largest_error = std::max(solved.largest_error, relative_error(ring[i], solved.exact_sifs[i]));
    solved.opening_at_centre       = model.opening_at_centre(u);
    solved.exact_opening_at_centre = exact.opening(0, 0);
    solved.gap_volume              = model.gap_volume(u);
    solved.exact_gap_volume        = exact.gap_volume();
    solved.n_cells                 = system.get_triangulation().n_global_active_cells();
    solved.n_dofs                  = system.get_dof_handler().n_dofs();
    solved.iterations              = system.last_solve().iterations;
    solved.relative_residual       = system.last_solve().relative_residual;
    solved.solver                  = system.solver_name();

    if (parameters.fields && parameters.fields->write_fields)
      {
        TimerOutput::Scope    scope(timer, "output");
        std::vector<Point<3>> points;
        for (const double phi : solved.angles)
          points.push_back(model.front().point(phi));
        FrontData data = {{"K_I exact", solved.exact_sifs}};
        for (unsigned int r = 0; r < solved.ring_radii.size(); ++r)
          data.emplace_back("K_I FE " + ring_name(solved.ring_radii[r]), solved.signed_sifs[r]);
        write_elliptical_fields(system, u, points, data, results);
      }
    solved.wall_time   = total_wall_time(timer);
    solved.peak_memory = peak_memory(MPI_COMM_WORLD);

    const Table front   = front_table(gap, solved);
    const Table summary = summary_table(parameters, solved, timer);
    log << "\nElliptical gap b/a = " << gap.aspect_ratio
        << " under uniform pressure: K_I(phi) beside p sqrt(pi b)/E(k) (sin^2 phi + (b/a)^2 cos^2 "
           "phi)^(1/4)\n";
    front.print(log);
    log << '\n';
    summary.print(log);
    results.write_csv("front.csv", front);
    results.write_csv("summary.csv", summary);
    return solved;
  }
} // namespace penny
