// gap-size-adhesionless: the gap radius at which the FE K_I of the parabola
// P (1 - r^2/a^2) vanishes, a root over c of FE solves alone; PASS when c/a
// lies within Verification/Tolerance of sqrt(3/2).
#include "closed_forms/adhesive_gap.h"
#include "numerics/relative_error.h"
#include "problems/penny_gap.h"
#include "scenes/scene.h"
#include "searches/gap_searches.h"

namespace penny
{
  namespace
  {
    class GapSizeScene : public Scene
    {
    public:
      void parameters(Sections &sections) override
      {
        penny_gap_model_sections(sections, model);
        parabola_section(sections, load);
        ring_section(sections, ring_radii, model.geometry);
        tolerance_section(sections, tolerance, "the relative error of c/a");
      }

      std::vector<std::string> input_files() const override { return model_input_files(model); }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PennyGapSearch search(model, ring_radii.back(), log);
        const double   a = load.tension_radius;
        const double   c = fe_adhesionless_gap_radius(search.gaps, load.peak_tension, a, MPI_COMM_WORLD);

        const Table::Format all_digits{16, false}, error_digits{3, true};
        const double        error   = relative_error(c / a, closed_form::adhesionless_c_over_a);
        Table               summary = Table::summary();
        summary.add_row({"c/a FE", Table::Cell(c / a, all_digits)});
        summary.add_row(
            {"c/a exact, sqrt(3/2)", Table::Cell(closed_form::adhesionless_c_over_a, all_digits)});
        summary.add_row({"relative error", Table::Cell(error, error_digits)});
        search.add_cost(summary);
        log << "Adhesionless gap size: FE K_I(c) = 0 for the parabola P (1 - r^2/a^2)\n";
        summary.print(log);
        results.write_csv("gap-size.csv", summary);
        return verdict("relative error of c/a", error, tolerance);
      }

    private:
      PennyGapModelParameters model;
      LoadParameters          load;
      std::vector<double>     ring_radii;
      double                  tolerance;
    };
  } // namespace

  PENNY_REGISTER_SCENE(GapSizeScene, "gap-size-adhesionless",
                       "the gap radius where the FE K_I of the parabola (P, a) vanishes: c/a = sqrt(3/2)")
} // namespace penny
