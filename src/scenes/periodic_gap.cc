// periodic-gap: one FE solve of a gap of the sinusoid's periodic array (plane
// strain), K_I from J-integrals and the signed K_I on every ring, beside
// sqrt(lambda) [p* cos^2(pi c/lambda) - p_bar] sqrt(tan(pi c/lambda)), and
// the unit cosine and uniform tensions beside theirs. PASS when |K_I| and the
// signed K_I on every ring lie within Verification/Tolerance of it.
#include "problems/periodic_gap.h"
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
    using dealii::TimerOutput;

    struct PeriodicGapScene : Scene
    {
      void inputs(Sections &sections) override
      {
        periodic.sections(sections);
        gap_and_load_section(sections, gap);
        fields_section(sections, write_fields);
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        TimerOutput timer(log, TimerOutput::never, TimerOutput::wall_times);
        periodic.model.gap_half_width = gap.gap_ratio * periodic.model.wavelength;
        const BuecknerTension        load{periodic.model.wavelength, gap.peak_tension,
                                   gap.load_ratio * gap.peak_tension};
        const PeriodicGapMeasurement solved = solve_periodic_gap(periodic.model, load, periodic.ring_radii,
                                                                 timer, write_fields ? &results : nullptr);

        log << "Periodic gap of Johnson's sinusoid (plane strain): K_I beside sqrt(lambda) [p* cos^2(pi "
               "c/lambda) - p_bar] sqrt(tan(pi c/lambda))\n";
        const double worst = report_rings(solved.rings, solved.exact_stress_intensity_factor,
                                          "min(c, lambda/2 - c)", summary_table(solved, timer), results, log);
        return verdict(worst);
      }

      Table summary_table(const PeriodicGapMeasurement &results, const TimerOutput &timer) const
      {
        Table      summary = Table::summary();
        const auto row     = [&](const std::string &name, const double value, const Table::Format format) {
          summary.add_row({name, Table::Cell(value, format)});
        };
        row("c/lambda", gap.gap_ratio, Table::all_digits);
        row("contact half-width a/lambda", 0.5 - gap.gap_ratio, Table::all_digits);
        row("p_bar/p*", gap.load_ratio, Table::all_digits);
        row("depth D/lambda", periodic.model.depth / periodic.model.wavelength, Table::all_digits);
        summary.add_row({"cells", results.n_cells});
        summary.add_row({"DoFs", results.n_dofs});
        summary.add_row({"degree", periodic.model.degree});
        summary.add_row({"MPI ranks", dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
        summary.add_row({"solver", results.solver});
        row("relative residual", results.relative_residual, Table::digits);
        row("K_I of cos(2 pi x/lambda) Pa FE (Pa m^1/2)", results.cosine_sif, Table::digits);
        row("K_I of cos(2 pi x/lambda) Pa exact (Pa m^1/2)", results.exact_cosine_sif, Table::digits);
        row("K_I of cos(2 pi x/lambda) Pa relative error",
            relative_error(results.cosine_sif, results.exact_cosine_sif), Table::error_digits);
        row("K_I of 1 Pa uniform FE (Pa m^1/2)", results.uniform_sif, Table::digits);
        row("K_I of 1 Pa uniform, Koiter (Pa m^1/2)", results.exact_uniform_sif, Table::digits);
        row("K_I of 1 Pa uniform relative error",
            relative_error(results.uniform_sif, results.exact_uniform_sif), Table::error_digits);
        add_phase_times(summary, timer);
        return summary;
      }

      PeriodicGapInput periodic;
      GapAndLoad       gap;
      bool             write_fields;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      PeriodicGapScene, "periodic-gap", "",
      "one FE solve of a gap of the sinusoid's periodic array (plane strain): K_I from J-integrals and the "
      "signed K_I on every ring, beside sqrt(lambda) [p* cos^2(pi c/lambda) - p_bar] sqrt(tan(pi c/lambda))",
      "largest relative error of |K_I| and the signed K_I on every ring")
} // namespace penny
