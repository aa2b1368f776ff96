#include "adhesion_scenes.h"

#include "adhesive_gap.h"
#include "output_files.h"

#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    double relative_error(const double value, const double exact)
    {
      return std::abs(value / exact - 1);
    }

    // Prints `text` and writes it to `file` in the output folder.
    void report(const Parameters &parameters, const std::string &file, const std::string &text, std::ostream &log)
    {
      log << text;
      write_atomically(std::filesystem::path(parameters.output.directory) / file,
                       [&](std::ostream &out) { out << text; });
    }
  } // namespace

  GapSizeResult run_gap_size_scene(const Parameters &parameters, std::ostream &log)
  {
    TimerOutput  timer(log, TimerOutput::never, TimerOutput::wall_times);
    GapFamily    gaps(parameters, timer);
    const double a = parameters.load.tension_radius;
    const double c = fe_adhesionless_gap_radius(gaps, parameters.load.peak_tension, a);

    std::ostringstream text;
    text << std::setprecision(16) << "Adhesionless gap size: FE K_I(c) = 0 for the parabola P (1 - r^2/a^2)\n"
         << "  c/a FE            " << c / a << '\n'
         << "  c/a exact         " << closed_form::adhesionless_c_over_a << "  (sqrt(3/2))\n"
         << std::setprecision(3) << std::scientific
         << "  relative error    " << relative_error(c / a, closed_form::adhesionless_c_over_a) << '\n'
         << std::defaultfloat << "  FE solves         " << gaps.n_solves() << '\n'
         << "  wall time         " << gaps.wall_time() << " s\n";
    report(parameters, "gap-size.txt", text.str(), log);
    return {c / a, gaps.n_solves()};
  }

  AdhesiveMinimumResult run_adhesive_minimum_scene(const Parameters &parameters, std::ostream &log)
  {
    TimerOutput           timer(log, TimerOutput::never, TimerOutput::wall_times);
    GapFamily             gaps(parameters, timer);
    const double          R_p     = parameters.load.summit_radius;
    const double          K_Ic    = parameters.adhesion.critical_stress_intensity;
    const AdhesiveMinimum minimum = fe_adhesive_minimum(gaps, R_p, K_Ic);
    const double          psi     = minimum.tension / adhesion_tension(R_p, K_Ic);
    const double          c_hat   = minimum.gap_radius / adhesion_length(R_p, K_Ic);

    std::ostringstream text;
    text << std::setprecision(16) << "Adhesive minimum: min over c of P(c) = [K_Ic + K_2(c)/(2 R_p)] / K_1(c), FE\n"
         << "  p0 FE (Pa)                " << minimum.tension << '\n'
         << "  c_min FE (m)              " << minimum.gap_radius << '\n'
         << "  psi FE                    " << psi << '\n'
         << "  psi exact                 " << closed_form::psi << '\n'
         << "  c_min/(R_p K_Ic)^(2/5) FE " << c_hat << '\n'
         << "  ... exact                 " << closed_form::c_min_factor << '\n'
         << std::setprecision(3) << std::scientific
         << "  psi relative error        " << relative_error(psi, closed_form::psi) << '\n'
         << "  c_min relative error      " << relative_error(c_hat, closed_form::c_min_factor) << '\n'
         << std::defaultfloat << "  FE solves                 " << gaps.n_solves() << '\n'
         << "  wall time                 " << gaps.wall_time() << " s\n";
    report(parameters, "adhesive-minimum.txt", text.str(), log);
    return {psi, c_hat, gaps.n_solves()};
  }

  // p_hat = P/p0 and c_hat = c/c_min, normalised by the closed-form p0 and c_min
  // so that FE and closed form share one axis.
  double run_gap_tension_curve_scene(const Parameters &parameters, std::ostream &log)
  {
    TimerOutput  timer(log, TimerOutput::never, TimerOutput::wall_times);
    GapFamily    gaps(parameters, timer);
    const double R_p   = parameters.load.summit_radius;
    const double K_Ic  = parameters.adhesion.critical_stress_intensity;
    const double c_min = closed_form::c_min_factor * adhesion_length(R_p, K_Ic);
    const double p0    = closed_form::psi * adhesion_tension(R_p, K_Ic);
    const auto  &range = parameters.adhesion;

    std::ostringstream table;
    table << "c_hat,p_hat FE,p_hat exact,p_hat linear,relative error\n" << std::setprecision(12);
    double worst = 0;
    for (unsigned int i = 0; i < range.n_curve_points; ++i)
      {
        const double       c_hat = range.smallest_c_hat + i * (range.largest_c_hat - range.smallest_c_hat) / (range.n_curve_points - 1);
        const UnitLoadSifs K     = gaps.unit_load_sifs(c_hat * c_min);
        const double       p_fe  = (K_Ic + K.quadratic / (2 * R_p)) / K.uniform / p0;
        const double       exact = (c_hat * c_hat + 4 / std::sqrt(c_hat)) / 5;
        const double       linear = c_hat * c_hat > 2.5 ? c_hat * c_hat / 5 + 0.5 : 1.;
        worst = std::max(worst, relative_error(p_fe, exact));
        table << c_hat << ',' << p_fe << ',' << exact << ',' << linear << ',' << relative_error(p_fe, exact) << '\n';
      }
    write_atomically(std::filesystem::path(parameters.output.directory) / "gap-tension-curve.csv",
                     [&](std::ostream &out) { out << table.str(); });
    log << table.str() << std::setprecision(3) << std::scientific << "largest relative error " << worst << '\n'
        << std::defaultfloat << "FE solves " << gaps.n_solves() << ", wall time " << gaps.wall_time() << " s\n";
    return worst;
  }

  std::optional<double> run_adhesive_equilibrium_scene(const Parameters &parameters, std::ostream &log)
  {
    TimerOutput           timer(log, TimerOutput::never, TimerOutput::wall_times);
    GapFamily             gaps(parameters, timer);
    const double          P       = parameters.load.peak_tension;
    const double          R_p     = parameters.load.summit_radius;
    const double          K_Ic    = parameters.adhesion.critical_stress_intensity;
    const AdhesiveMinimum minimum = fe_adhesive_minimum(gaps, R_p, K_Ic);
    const auto            c_t     = fe_stable_gap_radius(gaps, P, R_p, K_Ic, minimum);

    std::ostringstream text;
    text << std::setprecision(16) << "Adhesive equilibrium on the stable branch (K_I = K_Ic, c >= c_min), FE\n"
         << "  peak tension P (Pa)   " << P << '\n'
         << "  p0 FE (Pa)            " << minimum.tension << '\n';
    if (c_t)
      {
        const double exact = *closed_form::stable_gap_radius(P, R_p, K_Ic);
        text << "  gap radius c_t FE (m) " << *c_t << '\n'
             << "  c_t closed form (m)   " << exact << '\n'
             << std::setprecision(3) << std::scientific
             << "  relative error        " << relative_error(*c_t, exact) << '\n';
      }
    else
      text << "  P < p0: no gap survives; the gap closes (full contact).\n";
    text << std::defaultfloat << std::setprecision(3) << "  FE solves             " << gaps.n_solves() << '\n'
         << "  wall time             " << gaps.wall_time() << " s\n";
    report(parameters, "adhesive-equilibrium.txt", text.str(), log);
    return c_t;
  }
} // namespace penny
