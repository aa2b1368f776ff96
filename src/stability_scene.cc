#include "stability_scene.h"

#include "output_files.h"
#include "penny_scene.h"

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <functional>
#include <iomanip>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    struct Case
    {
      std::string                       name, setting;
      std::function<void(Parameters &)> modify;
      // Why the case may miss the target; empty: it must pass.
      std::string                       expected_miss = {};
    };

    PennySceneResults solve(Parameters parameters, const Case &c)
    {
      parameters.output.write_fields = false;
      c.modify(parameters);
      TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
      return solve_penny_gap(parameters, timer);
    }

    // Largest relative deviation of the signed K_I on any ring from `reference`.
    double relative_error(const PennySceneResults &results, const double reference)
    {
      double worst = 0;
      for (const auto &ring : results.rings)
        worst = std::max(worst, std::abs(ring.signed_stress_intensity_factor / reference - 1));
      return worst;
    }

    std::string status(const double error, const double tolerance, const std::string &expected_miss)
    {
      if (error <= tolerance)
        return "pass";
      return expected_miss.empty() ? "FAIL: error above tolerance" : "flagged: " + expected_miss;
    }

    std::string setting(const char *format, const double value)
    {
      std::ostringstream text;
      text << format << value;
      return text.str();
    }
  } // namespace

  std::vector<StabilityRow> run_stability_scene(const Parameters &parameters, std::ostream &log)
  {
    const double              target = parameters.stability.target_accuracy;
    std::vector<StabilityRow> rows;
    const auto add = [&](const Case &c, const PennySceneResults &results, const double error,
                         const std::string &measure, const double tolerance, const std::string &miss) {
      rows.push_back({c.name, c.setting, error, measure, tolerance, results.relative_residual,
                      results.condition_estimate, status(error, tolerance, miss)});
    };
    // Relative error of the signed K_I against the closed form.
    const auto run_relative = [&](const Case &c) {
      const PennySceneResults results = solve(parameters, c);
      add(c, results, relative_error(results, results.exact_stress_intensity_factor), "relative", target, c.expected_miss);
      return results;
    };

    // 1. Near-incompressibility: degree 1 locks; degree 4 stays accurate.
    for (const double nu : {0.3, 0.45, 0.49, 0.499, 0.4999})
      for (const unsigned int degree : {1u, 4u})
        run_relative({"incompressibility",
                      setting("degree ", degree) + setting(", nu = ", nu),
                      [=](Parameters &p) {
                        p.material.poissons_ratio = nu;
                        p.finite_element.degree   = degree;
                      },
                      degree == 1 ? "degree-1 elements lock as nu -> 1/2" : ""});

    // 2. Extreme scales: the same relative error as the unit case, to 1e-9.
    const Case              unit_case{"scales", "E = 1 GPa, c = 1 m", [](Parameters &) {}};
    const PennySceneResults unit      = solve(parameters, unit_case);
    const double unit_ratio = unit.rings.back().signed_stress_intensity_factor / unit.exact_stress_intensity_factor;
    for (const double E : {1e-3, 1e12})
      for (const double c : {1e-9, 1e3})
        {
          const Case scaled{"scales", setting("E = ", E) + setting(" Pa, c = ", c) + " m", [=](Parameters &p) {
                              const double factor = c / p.geometry.gap_radius;
                              p.material.youngs_modulus = E;
                              p.geometry.gap_radius     = c;
                              p.geometry.domain_radius *= factor;
                              p.geometry.domain_height *= factor;
                            }};
          const PennySceneResults results = solve(parameters, scaled);
          const double ratio = results.rings.back().signed_stress_intensity_factor / results.exact_stress_intensity_factor;
          add(scaled, results, std::abs(ratio / unit_ratio - 1), "vs unit case", 1e-9, "");
        }

    // 3. Geometry: the finite domain, the parabola's width, the root and beyond.
    for (const double c_over_R : {1e-5, 1e-3, 1e-2, 1e-1, 0.5})
      run_relative({"finite domain",
                    setting("c/R = c/H = ", c_over_R),
                    [=](Parameters &p) {
                      p.geometry.domain_radius = p.geometry.gap_radius / c_over_R;
                      p.geometry.domain_height = p.geometry.gap_radius / c_over_R;
                    },
                    "finite domain: the closed form is for an infinite solid"});
    for (const double a_over_c : {0.5, 1., 2., 10., 100.})
      {
        const Case parabola{"parabola width", setting("a/c = ", a_over_c), [=](Parameters &p) {
                              p.load.type           = LoadParameters::Type::parabolic;
                              p.load.tension_radius = a_over_c * p.geometry.gap_radius;
                            }};
        const PennySceneResults results = solve(parameters, parabola);
        const double            error   = relative_error(results, results.exact_stress_intensity_factor);
        const bool negative = results.rings.back().signed_stress_intensity_factor < 0;
        add(parabola, results, error, "relative", target, "");
        if (negative && rows.back().status == "pass")
          rows.back().status = "flagged: K_I < 0: the faces would interpenetrate";
      }
    // At the root K_I is nearly zero: an absolute error in units of 2 P sqrt(c/pi).
    for (const double offset : {-1e-8, 1e-8})
      {
        const Case near_root{"near the root", setting("c/a = sqrt(3/2) (1 + ", offset) + ")", [=](Parameters &p) {
                               p.load.type           = LoadParameters::Type::parabolic;
                               p.load.tension_radius = p.geometry.gap_radius / (std::sqrt(1.5) * (1 + offset));
                             }};
        const PennySceneResults results = solve(parameters, near_root);
        const double scale = 2 * parameters.load.peak_tension * std::sqrt(parameters.geometry.gap_radius / M_PI);
        double       error = 0;
        for (const auto &ring : results.rings)
          error = std::max(error, std::abs(ring.signed_stress_intensity_factor - results.exact_stress_intensity_factor) / scale);
        add(near_root, results, error, "absolute / (2 P sqrt(c/pi))", target, "");
      }

    // 4. Mesh extremes.
    run_relative({"mesh", "40 tip levels (cells 1e-12 c)", [](Parameters &p) { p.mesh.tip_levels = 40; }});
    for (const double ratio : {10., 100.})
      {
        const Case stretched{"mesh", setting("cell aspect ratio ", ratio) + " above z = c",
                             [=](Parameters &p) { p.mesh.cell_aspect_ratio = ratio; }};
        const PennySceneResults results = solve(parameters, stretched);
        double spread = 0;
        for (const auto &ring : results.rings)
          spread = std::max(spread, std::abs(ring.signed_stress_intensity_factor / results.rings.front().signed_stress_intensity_factor - 1));
        add(stretched, results, relative_error(results, results.exact_stress_intensity_factor), "relative", target,
            setting("stretched far cells under-resolve the far field; the rings agree to ", spread));
      }

    // 5. Solvers: CG with AMG against the direct solver on the same system.
    for (const unsigned int levels : {20u, 30u})
      {
        const auto on_same_system = [=](Parameters &p) {
          p.finite_element.degree = 2;
          p.mesh.tip_levels       = levels;
        };
        const Case direct{"solvers", "UMFPACK", on_same_system};
        const Case iterative{"solvers", setting("CG + AMG vs UMFPACK, tip levels ", levels), [=](Parameters &p) {
                               on_same_system(p);
                               p.linear_solver.type           = LinearSolverParameters::Type::cg_amg;
                               p.linear_solver.tolerance      = 1e-12;
                               p.linear_solver.max_iterations = 20000;
                             }};
        const PennySceneResults reference = solve(parameters, direct);
        const PennySceneResults results   = solve(parameters, iterative);
        double difference = 0;
        for (unsigned int i = 0; i < results.rings.size(); ++i)
          difference = std::max(difference, std::abs(results.rings[i].signed_stress_intensity_factor /
                                                        reference.rings[i].signed_stress_intensity_factor - 1));
        add(iterative, results, difference, "vs direct, ring by ring", 1e-8, "");
      }

    log << std::left << std::setw(20) << "case" << std::setw(42) << "setting" << std::right << std::setw(10)
        << "K_I error" << "  " << std::setw(9) << "residual" << "  " << std::setw(9) << "condition" << "  status\n";
    for (const auto &row : rows)
      log << std::left << std::setw(20) << row.case_name << std::setw(42) << row.setting << std::right
          << std::scientific << std::setprecision(2) << std::setw(10) << row.error << "  " << std::setw(9)
          << row.residual << "  " << std::setw(9) << row.condition << std::defaultfloat << "  " << row.status << '\n';

    std::ostringstream table;
    table << "case,setting,error,measure,tolerance,relative residual,condition estimate,status\n"
          << std::setprecision(6);
    for (const auto &row : rows)
      table << row.case_name << ",\"" << row.setting << "\"," << row.error << ',' << row.measure << ','
            << row.tolerance << ',' << row.residual << ',' << row.condition << ",\"" << row.status << "\"\n";
    write_atomically(std::filesystem::path(parameters.output.directory) / "stability.csv",
                     [&](std::ostream &out) { out << table.str(); });

    const auto failures = std::count_if(rows.begin(), rows.end(), [](const StabilityRow &row) {
      return row.status.rfind("FAIL", 0) == 0;
    });
    if (failures > 0)
      throw std::runtime_error("stability: " + std::to_string(failures) + " case(s) failed; see stability.csv");
    return rows;
  }
} // namespace penny
