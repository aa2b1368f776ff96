// periodic-gap-depth: the truncation study of the periodic gap. Each depth D
// of the solid is a full solve of the scene's gap; the error of the last ring
// against the closed form of the infinitely deep solid, and those of the unit
// cosine and uniform tensions.
#include "numerics/relative_error.h"
#include "output/phase_times.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "problems/periodic_gap.h"
#include "scenes/scene.h"

#include <algorithm>

namespace penny
{
  namespace
  {
    using dealii::TimerOutput;

    struct PeriodicGapDepthScene : Scene
    {
      void inputs(Sections &sections) override
      {
        periodic.sections(sections, false);
        gap_and_load_section(sections, gap);
        sections.check([&] {
          const double largest_ring =
              *std::max_element(periodic.ring_radii.begin(), periodic.ring_radii.end());
          for (const double depth : depths)
            sections.require(largest_ring < 4 * depth, "Depth study/Depths", depth,
                             "(largest ring radius/4 = " + shortest(largest_ring / 4) + ", 100] lambda");
        });
      }

      void entries(Entries &entries) override
      {
        entries.increasing_numbers(
            "Depths", depths, {0.25, 0.5, 0.75, 1, 1.5, 2, 3}, 1,
            interval("[]", smallest_depth, 100, "lambda"),
            "Depths D of the truncated solid, one solve each; every ring of 'Periodic gap/Ring radii' must "
            "lie below 4 D/lambda. Units: lambda.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        TimerOutput timer(log, TimerOutput::never, TimerOutput::wall_times);
        Table       table({{"D/lambda", Table::Format{4, false}},
                           "cells",
                           "DoFs",
                           {"K_I signed FE (Pa m^1/2)", Table::digits},
                           {"K_I exact (Pa m^1/2)", Table::digits},
                           {"K_I relative error", Table::error_digits},
                           {"K_cosine relative error", Table::error_digits},
                           {"K_uniform relative error", Table::error_digits}});
        // Each depth a model on one rank, the depths spread over the ranks.
        struct Row
        {
          double cells, dofs, signed_sif, exact_sif, error, cosine_error, uniform_error;
        };
        const BuecknerTension load{periodic.model.wavelength, gap.peak_tension,
                                   gap.load_ratio * gap.peak_tension};
        const auto solved = spread_over_ranks<Row>(MPI_COMM_WORLD, depths.size(), [&](const unsigned int i) {
          PeriodicGapModelParameters deeper = periodic.model;
          deeper.gap_half_width             = gap.gap_ratio * periodic.model.wavelength;
          deeper.depth                      = depths[i] * periodic.model.wavelength;
          deeper.communicator               = MPI_COMM_SELF;
          const PeriodicGapMeasurement m    = solve_periodic_gap(deeper, load, periodic.ring_radii, timer);
          const double                 K    = m.rings.back().signed_stress_intensity_factor;
          return Row{double(m.n_cells),
                     double(m.n_dofs),
                     K,
                     m.exact_stress_intensity_factor,
                     relative_error(K, m.exact_stress_intensity_factor),
                     relative_error(m.cosine_sif, m.exact_cosine_sif),
                     relative_error(m.uniform_sif, m.exact_uniform_sif)};
        });
        for (unsigned int i = 0; i < depths.size(); ++i)
          {
            const Row &row = solved[i];
            table.add_row({depths[i], static_cast<unsigned int>(row.cells),
                           static_cast<unsigned int>(row.dofs), row.signed_sif, row.exact_sif, row.error,
                           row.cosine_error, row.uniform_error});
          }
        log << "Truncation study: K_I of the periodic gap (c/lambda = " << gap.gap_ratio
            << ", p_bar/p* = " << gap.load_ratio
            << ", last ring) against the depth D of the solid, free at z = D\n";
        publish(table, "depth-study.csv", results, log);
        log << "wall time total (s): " << total_wall_time(timer) << '\n';
        return {};
      }

      PeriodicGapInput    periodic;
      GapAndLoad          gap;
      std::vector<double> depths;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      PeriodicGapDepthScene, "periodic-gap-depth", "Depth study",
      "the periodic-gap K_I against the depth D/lambda of the truncated solid: the truncation study", "")
} // namespace penny
