// penny-gap: one FE solve of the load, the J-integral on every ring, and the
// FE figures beside Sneddon's closed forms. PASS when K_I on every ring, w(0)
// and the gap volume lie within Verification/Tolerance of them.
#include "problems/penny_gap.h"
#include "numerics/relative_error.h"
#include "output/phase_times.h"
#include "output/table.h"
#include "scenes/scene.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace penny
{
  namespace
  {
    using dealii::TimerOutput;

    // Where a closed form comes from a quadrature whose error estimate exceeds
    // the FE's difference to it, that difference says only that the FE is
    // right to within the estimate.
    std::string closed_form_verdict(const PennyGapMeasurement &results)
    {
      double ring_error = 0;
      for (const auto &ring : results.rings)
        ring_error = worse(ring_error, relative_error(ring.stress_intensity_factor,
                                                      std::abs(results.exact_stress_intensity_factor.value)));
      const std::vector<std::tuple<std::string, ClosedForm, double>> quantities = {
          {"K_I", results.exact_stress_intensity_factor, ring_error},
          {"w(0)", results.exact_opening_at_centre,
           relative_error(results.opening_at_centre, results.exact_opening_at_centre.value)},
          {"gap volume", results.exact_gap_volume,
           relative_error(results.gap_volume, results.exact_gap_volume.value)}};
      if (std::all_of(quantities.begin(), quantities.end(),
                      [](const auto &q) { return std::get<1>(q).exact; }))
        return "exact formulas";
      std::string limited;
      for (const auto &[name, closed_form, fe_error] : quantities)
        if (!(closed_form.relative_error_estimate() < fe_error))
          limited += (limited.empty() ? "" : ", ") + name;
      if (limited.empty())
        return "quadrature; every error estimate is below the FE's difference to it";
      return "quadrature error estimate above the FE's difference for " + limited +
             ": there the FE is verified only to the estimate";
    }

    Table summary_table(const PennyGapMeasurement &results, const unsigned int degree,
                        const TimerOutput &timer)
    {
      Table table = Table::summary();
      table.add_row({"cells", results.n_cells});
      table.add_row({"DoFs", results.n_dofs});
      table.add_row({"degree", degree});
      table.add_row({"MPI ranks", dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
      table.add_row({"solver", results.solver});
      table.add_row({"relative residual", Table::Cell(results.relative_residual, Table::digits)});
      const auto row = [&](const std::string &name, const double value) {
        table.add_row({name, Table::Cell(value, Table::digits)});
      };
      const auto estimate = [&](const std::string &name, const ClosedForm &closed_form) {
        table.add_row({name + " exact: quadrature error estimate (relative)",
                       Table::Cell(closed_form.relative_error_estimate(), Table::Format{2, true})});
      };
      row("opening w(0) FE (m)", results.opening_at_centre);
      row("opening w(0) exact (m)", results.exact_opening_at_centre.value);
      row("opening relative error",
          relative_error(results.opening_at_centre, results.exact_opening_at_centre.value));
      row("gap volume FE (m^3)", results.gap_volume);
      row("gap volume exact (m^3)", results.exact_gap_volume.value);
      row("volume relative error", relative_error(results.gap_volume, results.exact_gap_volume.value));
      estimate("K_I", results.exact_stress_intensity_factor);
      estimate("w(0)", results.exact_opening_at_centre);
      estimate("gap volume", results.exact_gap_volume);
      table.add_row({"closed forms", closed_form_verdict(results)});
      add_phase_times(table, timer);
      return table;
    }

    struct PennyGapScene : Scene
    {
      void inputs(Sections &sections) override
      {
        gap.sections(sections, &load);
        fields_section(sections, write_fields);
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        TimerOutput               timer(log, TimerOutput::never, TimerOutput::wall_times);
        PennyGapModel             model(gap.model, timer);
        const PennyGapMeasurement solved =
            measure_penny_gap(model, FaceLoad(load, gap.model.geometry.gap_radius), gap.ring_radii, timer,
                              write_fields ? &results : nullptr);

        const Table  summary = summary_table(solved, gap.model.degree, timer);
        const double worst =
            worse(worse(report_rings(solved.rings, solved.exact_stress_intensity_factor.value, "c", summary,
                                     results, log),
                        relative_error(solved.opening_at_centre, solved.exact_opening_at_centre.value)),
                  relative_error(solved.gap_volume, solved.exact_gap_volume.value));
        return verdict(worst);
      }

      PennyGapInput  gap;
      LoadParameters load;
      bool           write_fields;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      PennyGapScene, "penny-gap", "",
      "one FE solve of the Load; K_I from J-integrals (and the signed K_I) on every ring, the face opening "
      "and the gap volume, beside Sneddon's closed forms",
      "largest relative error of K_I, w(0) and the volume")
} // namespace penny
