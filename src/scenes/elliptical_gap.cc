// elliptical-gap: one 3D FE solve (distributed) of an elliptical gap under
// uniform pressure or a quadratic face traction: K_I(phi) at the front points
// from front-localised J-integrals (signed), beside the closed form
// (Green-Sneddon/Irwin, Galin), and for the circle under uniform pressure
// beside the axisymmetric model. PASS when K_I at every front point and ring
// lies within Verification/Tolerance of the closed form.
#include "problems/elliptical_gap.h"
#include "numerics/relative_error.h"
#include "output/phase_times.h"
#include "output/table.h"
#include "scenes/scene.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

namespace penny
{
  namespace
  {
    using namespace dealii;

    Table front_table(const EllipticalGap &gap, const EllipticalGapMeasurement &solved)
    {
      std::vector<Table::Column> columns = {{"phi (rad)", Table::Format{6, false}},
                                            {"x (m)", Table::Format{6, false}},
                                            {"y (m)", Table::Format{6, false}},
                                            {"K_I exact (Pa m^1/2)", Table::digits}};
      if (!solved.axisymmetric_sifs.empty())
        {
          columns.push_back({"K_I axisymmetric FE (Pa m^1/2)", Table::digits});
          columns.push_back({"relative difference 3D - axisymmetric, last ring", Table::error_digits});
        }
      for (const double rho : solved.ring_radii)
        {
          const std::string ring = ring_name(rho);
          columns.push_back({"K_I signed FE " + ring + " (Pa m^1/2)", Table::digits});
          columns.push_back({"relative error " + ring, Table::error_digits});
        }
      Table        table(columns);
      const double a = gap.semi_axis_a, b = gap.aspect_ratio * a;
      for (unsigned int i = 0; i < solved.angles.size(); ++i)
        {
          const double             phi = solved.angles[i];
          std::vector<Table::Cell> row = {phi, a * std::cos(phi), b * std::sin(phi), solved.exact_sifs[i]};
          if (!solved.axisymmetric_sifs.empty())
            {
              row.emplace_back(solved.axisymmetric_sifs[i]);
              row.emplace_back((solved.signed_sifs.back()[i] - solved.axisymmetric_sifs[i]) /
                               solved.axisymmetric_sifs[i]);
            }
          for (const auto &ring : solved.signed_sifs)
            {
              row.emplace_back(ring[i]);
              row.emplace_back(relative_error(ring[i], solved.exact_sifs[i]));
            }
          table.add_row(row);
        }
      return table;
    }

    Table summary_table(const EllipticalGap &gap, const unsigned int degree,
                        const EllipticalGapMeasurement &solved, const TimerOutput &timer)
    {
      Table      summary = Table::summary();
      const auto row     = [&](const std::string &name, const double value, const Table::Format format) {
        summary.add_row({name, Table::Cell(value, format)});
      };
      row("b/a", gap.aspect_ratio, Table::Format{6, false});
      row("traction x^2 term c_x", gap.x_term, Table::Format{6, false});
      row("traction y^2 term c_y", gap.y_term, Table::Format{6, false});
      summary.add_row({"cells", solved.n_cells});
      summary.add_row({"DoFs", solved.n_dofs});
      summary.add_row({"degree", degree});
      summary.add_row({"MPI ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
      summary.add_row({"solver", solved.solver});
      summary.add_row({"CG iterations", solved.iterations});
      row("relative residual", solved.relative_residual, Table::digits);
      for (unsigned int r = 0; r < solved.ring_radii.size(); ++r)
        row("largest K_I relative error, " + ring_name(solved.ring_radii[r]),
            largest_relative_error(solved.signed_sifs[r], solved.exact_sifs), Table::error_digits);
      row("w(0) FE (m)", solved.opening_at_centre, Table::digits);
      row("w(0) exact (m)", solved.exact_opening_at_centre, Table::digits);
      row("w(0) relative error", relative_error(solved.opening_at_centre, solved.exact_opening_at_centre),
          Table::error_digits);
      row("gap volume relative error", relative_error(solved.gap_volume, solved.exact_gap_volume),
          Table::error_digits);
      row("peak memory, all ranks (MB)", solved.peak_memory, Table::Format{5, false});
      add_phase_times(summary, timer);
      return summary;
    }
    struct EllipticalGapScene : Scene
    {
      void inputs(Sections &sections) override
      {
        elliptical_model_sections(sections, model);
        elliptical_gap_section(sections, gap, model);
        fields_section(sections, write_fields);
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        TimerOutput                    timer(log, TimerOutput::never, TimerOutput::wall_times);
        const EllipticalGapMeasurement solved =
            measure_elliptical_gap(model, gap, timer, log, write_fields ? &results : nullptr);
        const Table front   = front_table(gap, solved);
        const Table summary = summary_table(gap, model.model.degree, solved, timer);
        log << "\nElliptical gap b/a = " << gap.aspect_ratio
            << (gap.uniform() ? " under uniform pressure: K_I(phi) beside p sqrt(pi b)/E(k) (sin^2 phi + "
                                "(b/a)^2 cos^2 phi)^(1/4)\n"
                              : " under the traction p (1 + c_x x^2/a^2 + c_y y^2/b^2): K_I(phi) beside "
                                "Galin's closed form\n");
        publish(front, "front.csv", results, log);
        log << '\n';
        publish(summary, "summary.csv", results, log);
        return verdict(solved.largest_error);
      }

      EllipticalModel model;
      EllipticalGap   gap;
      bool            write_fields;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      EllipticalGapScene, "elliptical-gap", "",
      "one 3D FE solve (distributed) of an elliptical gap under uniform pressure or a quadratic face "
      "traction: K_I(phi) at the front points from front-localised J-integrals (signed), beside the "
      "closed form (Green-Sneddon/Irwin, Galin)",
      "largest relative error of K_I over the front points and rings")
} // namespace penny
