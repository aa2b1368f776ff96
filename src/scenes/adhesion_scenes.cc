#include "scenes/adhesion_scenes.h"

#include "fracture/adhesive_gap.h"
#include "fracture/gap_searches.h"
#include "input/input_error.h"
#include "output/table.h"
#include "scenes/scene_support.h"

#include <cmath>

namespace penny
{
  using namespace dealii;

  namespace
  {
    const Table::Format all_digits{16, false}, error_digits{3, true};

    // The closing rows of every search: its cost.
    void add_cost(Table &summary, const GapSearch &search)
    {
      summary.add_row({"FE solves", search.n_solves()});
      add_phase_times(summary, search.timer);
    }

    void report(const Table &summary, const std::string &title, const std::string &file,
                const ResultFolder &results, std::ostream &log)
    {
      log << title << '\n';
      summary.print(log);
      results.write_csv(file, summary);
    }
  } // namespace

  GapSizeResult run_gap_size_scene(const Parameters &parameters, const ResultFolder &results,
                                   std::ostream &log)
  {
    GapSearch    search(parameters, log);
    const double a = parameters.load->tension_radius;
    const double c =
        fe_adhesionless_gap_radius(search.gaps, parameters.load->peak_tension, a, MPI_COMM_WORLD);

    Table summary = Table::summary();
    summary.add_row({"c/a FE", Table::Cell(c / a, all_digits)});
    summary.add_row({"c/a exact, sqrt(3/2)", Table::Cell(closed_form::adhesionless_c_over_a, all_digits)});
    summary.add_row({"relative error",
                     Table::Cell(relative_error(c / a, closed_form::adhesionless_c_over_a), error_digits)});
    add_cost(summary, search);
    report(summary, "Adhesionless gap size: FE K_I(c) = 0 for the parabola P (1 - r^2/a^2)", "gap-size.csv",
           results, log);
    return {c / a, search.n_solves()};
  }

  AdhesiveMinimumResult run_adhesive_minimum_scene(const Parameters &parameters, const ResultFolder &results,
                                                   std::ostream &log)
  {
    GapSearch             search(parameters, log);
    const double          R_p     = search.summit_radius;
    const double          K_Ic    = search.critical_stress_intensity;
    const AdhesiveMinimum minimum = fe_adhesive_minimum(search.gaps, R_p, K_Ic, MPI_COMM_WORLD);
    const double          psi     = minimum.tension / adhesion_tension(R_p, K_Ic);
    const double          c_hat   = minimum.gap_radius / adhesion_length(R_p, K_Ic);

    Table summary = Table::summary();
    summary.add_row({"p0 FE (Pa)", Table::Cell(minimum.tension, all_digits)});
    summary.add_row({"c_min FE (m)", Table::Cell(minimum.gap_radius, all_digits)});
    summary.add_row({"psi FE", Table::Cell(psi, all_digits)});
    summary.add_row({"psi exact", Table::Cell(closed_form::psi, all_digits)});
    summary.add_row({"c_min/(R_p K_Ic)^(2/5) FE", Table::Cell(c_hat, all_digits)});
    summary.add_row({"c_min/(R_p K_Ic)^(2/5) exact", Table::Cell(closed_form::c_min_factor, all_digits)});
    summary.add_row({"psi relative error", Table::Cell(relative_error(psi, closed_form::psi), error_digits)});
    summary.add_row({"c_min relative error",
                     Table::Cell(relative_error(c_hat, closed_form::c_min_factor), error_digits)});
    add_cost(summary, search);
    report(summary, "Adhesive minimum: min over c of P(c) = [K_Ic + K_2(c)/(2 R_p)] / K_1(c), FE",
           "adhesive-minimum.csv", results, log);
    return {psi, c_hat, search.n_solves()};
  }

  // p_hat = P/p0 and c_hat = c/c_min, normalised by the closed-form p0 and c_min
  // so that FE and closed form share one axis.
  double run_gap_tension_curve_scene(const Parameters &parameters, const ResultFolder &results,
                                     std::ostream &log)
  {
    GapSearch    search(parameters, log);
    const double R_p   = search.summit_radius;
    const double K_Ic  = search.critical_stress_intensity;
    const double c_min = closed_form::c_min_factor * adhesion_length(R_p, K_Ic);
    const double p0    = closed_form::psi * adhesion_tension(R_p, K_Ic);
    const auto  &range = *parameters.gap_tension_curve;

    const Table::Format digits{12, false};
    Table               table({{"c_hat", digits},
                               {"p_hat FE", digits},
                               {"p_hat exact", digits},
                               {"p_hat linear", digits},
                               {"relative error", digits}});
    const auto          c_hat_at = [&](const unsigned int i) {
      return range.smallest_c_hat + i * (range.largest_c_hat - range.smallest_c_hat) / (range.n_points - 1);
    };
    std::vector<double> radii;
    for (unsigned int i = 0; i < range.n_points; ++i)
      radii.push_back(c_hat_at(i) * c_min);
    const std::vector<UnitLoadSifs> sifs  = search.gaps.unit_load_sifs(radii, MPI_COMM_WORLD);
    double                          worst = 0;
    for (unsigned int i = 0; i < range.n_points; ++i)
      {
        const double       c_hat  = c_hat_at(i);
        const UnitLoadSifs K      = sifs[i];
        const double       p_fe   = (K_Ic + K.quadratic / (2 * R_p)) / K.uniform / p0;
        const double       exact  = (c_hat * c_hat + 4 / std::sqrt(c_hat)) / 5;
        const double       linear = c_hat * c_hat > 2.5 ? c_hat * c_hat / 5 + 0.5 : 1.;
        worst                     = std::max(worst, relative_error(p_fe, exact));
        table.add_row({c_hat, p_fe, exact, linear, relative_error(p_fe, exact)});
      }
    results.write_csv("gap-tension-curve.csv", table);
    table.print(log);
    Table summary = Table::summary();
    summary.add_row({"largest relative error", Table::Cell(worst, error_digits)});
    add_cost(summary, search);
    summary.print(log);
    return worst;
  }

  std::optional<double> run_adhesive_equilibrium_scene(const Parameters   &parameters,
                                                       const ResultFolder &results, std::ostream &log)
  {
    GapSearch    search(parameters, log);
    const double P    = parameters.load->peak_tension;
    const double R_p  = search.summit_radius;
    const double K_Ic = search.critical_stress_intensity;
    // The stable gap's search widens its bracket from c_min to at most 2^21
    // c_min: a tension whose gap lies beyond is refused before any solve.
    const double largest = closed_form::adhesive_tension(
        std::pow(2., 20) * closed_form::c_min_factor * adhesion_length(R_p, K_Ic), R_p, K_Ic);
    const double shown = std::pow(10., std::floor(std::log10(largest)) - 2); // three digits, rounded down
    require(P <= largest, "Load/Peak tension P", P,
            "[-1e30, " + shortest(std::floor(largest / shown) * shown) +
                "] Pa for this Summit radius R_p and Critical stress intensity K_Ic (the stable gap "
                "radius would exceed 2^20 c_min)");
    const AdhesiveMinimum minimum = fe_adhesive_minimum(search.gaps, R_p, K_Ic, MPI_COMM_WORLD);
    const auto            c_t     = fe_stable_gap_radius(search.gaps, P, R_p, K_Ic, minimum, MPI_COMM_WORLD);

    Table summary = Table::summary();
    summary.add_row({"peak tension P (Pa)", Table::Cell(P, all_digits)});
    summary.add_row({"p0 FE (Pa)", Table::Cell(minimum.tension, all_digits)});
    if (c_t)
      {
        const double exact = *closed_form::stable_gap_radius(P, R_p, K_Ic);
        summary.add_row({"gap radius c_t FE (m)", Table::Cell(*c_t, all_digits)});
        summary.add_row({"c_t closed form (m)", Table::Cell(exact, all_digits)});
        summary.add_row({"relative error", Table::Cell(relative_error(*c_t, exact), error_digits)});
      }
    else
      summary.add_row({"gap", "closed: P < p0, no gap survives (full contact)"});
    add_cost(summary, search);
    report(summary, "Adhesive equilibrium on the stable branch (K_I = K_Ic, c >= c_min), FE",
           "adhesive-equilibrium.csv", results, log);
    return c_t;
  }
} // namespace penny
