// stability: one table of stiff and extreme cases around the scene's own
// parameters (near-incompressibility, extreme scales, the finite domain, the
// parabola's width and its root, mesh extremes, the iterative against the
// direct solver), each either passing its accuracy check or flagged with the
// reason it is expected to miss it. A case that misses without such a reason
// fails the scene.
#include "numerics/relative_error.h"
#include "problems/penny_gap.h"
#include "problems/stability_cases.h"
#include "scenes/scene.h"

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>

namespace penny
{
  namespace
  {
    using dealii::TimerOutput;

    // The model and the load of one case.
    struct Setting
    {
      PennyGapModelParameters model;
      LoadParameters          load;
    };

    // One case's model on this rank alone, refused if it would not fit.
    PennyGapMeasurement solve(Setting setting, const std::vector<double> &ring_radii,
                              const std::function<void(Setting &)> &modify)
    {
      modify(setting);
      check_model_size(setting.model, model_cells(setting.model));
      TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
      return solve_penny_gap(setting.model, setting.load, ring_radii, timer);
    }

    // Largest relative deviation of the signed K_I on any ring from `reference`.
    double largest_error(const PennyGapMeasurement &results, const double reference)
    {
      double worst = 0;
      for (const auto &ring : results.rings)
        worst = worse(worst, relative_error(ring.signed_stress_intensity_factor, reference));
      return worst;
    }

    struct StabilityScene : Scene
    {
      void inputs(Sections &sections) override { gap.sections(sections, &load); }

      void entries(Entries &entries) override
      {
        entries.number(
            "Target accuracy", target_accuracy, 1e-5, interval("()", 0, 1),
            "Relative K_I error a case of the stability scene must reach to pass; a case expected to "
            "miss it is flagged with the reason. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        const double target = target_accuracy;
        // Every model on one rank: the cases are spread over the ranks.
        Setting base{gap.model, load};
        base.model.communicator            = MPI_COMM_SELF;
        const std::vector<double> &radii   = gap.ring_radii;
        const auto                 outcome = [](const PennyGapMeasurement &solved, const double error,
                                const double extra = 0) {
          return StabilityOutcome{error, solved.relative_residual, solved.condition_estimate, extra};
        };
        std::vector<StabilityCase> cases;
        // Relative error of the signed K_I against the closed form.
        const auto relative = [&](const std::string &name, const std::string &setting,
                                  const std::function<void(Setting &)> &modify,
                                  const std::string                    &miss = "") {
          cases.push_back({name, setting, "relative", target, [&, modify] {
                             const PennyGapMeasurement solved = solve(base, radii, modify);
                             return outcome(
                                 solved, largest_error(solved, solved.exact_stress_intensity_factor.value));
                           }});
          cases.back().expected_miss = [miss](const StabilityOutcome &) { return miss; };
        };

        // 1. Near-incompressibility: degree 1 locks; degree 4 stays accurate.
        for (const double nu : {0.3, 0.45, 0.49, 0.499, 0.4999})
          for (const unsigned int degree : {1u, 4u})
            relative(
                "incompressibility", setting_text("degree ", degree) + setting_text(", nu = ", nu),
                [=](Setting &s) {
                  s.model.material.poissons_ratio = nu;
                  s.model.degree                  = degree;
                },
                degree == 1 ? "degree-1 elements lock as nu -> 1/2" : "");

        // 2. Extreme scales: the same relative error as the unit case, to 1e-9.
        const auto ratio_to_exact = [](const PennyGapMeasurement &solved) {
          return solved.rings.back().signed_stress_intensity_factor /
                 solved.exact_stress_intensity_factor.value;
        };
        const double unit_ratio = ratio_to_exact(solve(base, radii, [](Setting &) {}));
        for (const double E : {1e-3, 1e12})
          for (const double c : {1e-9, 1e3})
            cases.push_back({"scales", setting_text("E = ", E) + setting_text(" Pa, c = ", c) + " m",
                             "vs unit case", 1e-9, [&, E, c] {
                               const PennyGapMeasurement solved = solve(base, radii, [=](Setting &s) {
                                 s.model                         = s.model.scaled_to(c);
                                 s.model.material.youngs_modulus = E;
                               });
                               return outcome(solved, relative_error(ratio_to_exact(solved), unit_ratio));
                             }});

        // 3. Geometry: the finite domain, the parabola's width, the root and beyond.
        for (const double c_over_R : {1e-5, 1e-3, 1e-2, 1e-1, 0.5})
          relative(
              "finite domain", setting_text("c/R = c/H = ", c_over_R),
              [=](Setting &s) {
                s.model.geometry.domain_radius = s.model.geometry.gap_radius / c_over_R;
                s.model.geometry.domain_height = s.model.geometry.gap_radius / c_over_R;
              },
              "finite domain: the closed form is for an infinite solid");
        for (const double a_over_c : {0.5, 1., 2., 10., 100.})
          {
            // extra: 1 where K_I < 0.
            cases.push_back(
                {"parabola width", setting_text("a/c = ", a_over_c), "relative", target, [&, a_over_c] {
                   const PennyGapMeasurement solved = solve(base, radii, [=](Setting &s) {
                     s.load.type           = LoadParameters::Type::parabolic;
                     s.load.tension_radius = a_over_c * s.model.geometry.gap_radius;
                   });
                   return outcome(solved, largest_error(solved, solved.exact_stress_intensity_factor.value),
                                  solved.rings.back().signed_stress_intensity_factor < 0);
                 }});
            cases.back().pass_flag = [](const StabilityOutcome &o) {
              return std::string(o.extra ? "K_I < 0: the faces would interpenetrate" : "");
            };
          }
        // At the root K_I is nearly zero: an absolute error in units of 2 P sqrt(c/pi).
        for (const double offset : {-1e-8, 1e-8})
          cases.push_back({"near the root", setting_text("c/a = sqrt(3/2) (1 + ", offset) + ")",
                           "absolute / (2 P sqrt(c/pi))", target, [&, offset] {
                             const PennyGapMeasurement solved = solve(base, radii, [=](Setting &s) {
                               s.load.type = LoadParameters::Type::parabolic;
                               s.load.tension_radius =
                                   s.model.geometry.gap_radius / (std::sqrt(1.5) * (1 + offset));
                             });
                             const double              scale  = 2 * base.load.peak_tension *
                                                  std::sqrt(base.model.geometry.gap_radius / M_PI);
                             double error = 0;
                             for (const auto &ring : solved.rings)
                               error = worse(error, std::abs(ring.signed_stress_intensity_factor -
                                                             solved.exact_stress_intensity_factor.value) /
                                                        scale);
                             return outcome(solved, error);
                           }});

        // 4. Mesh extremes.
        relative("mesh", "40 tip levels (cells 1e-12 c)", [](Setting &s) { s.model.mesh.tip_levels = 40; });
        for (const double ratio : {10., 100.})
          {
            // extra: the largest difference between the rings.
            cases.push_back(
                {"mesh", setting_text("cell aspect ratio ", ratio) + " above z = c", "relative", target,
                 [&, ratio] {
                   const PennyGapMeasurement solved =
                       solve(base, radii, [=](Setting &s) { s.model.mesh.cell_aspect_ratio = ratio; });
                   double spread = 0;
                   for (const auto &ring : solved.rings)
                     spread = std::max(spread,
                                       relative_error(ring.signed_stress_intensity_factor,
                                                      solved.rings.front().signed_stress_intensity_factor));
                   return outcome(solved, largest_error(solved, solved.exact_stress_intensity_factor.value),
                                  spread);
                 }});
            cases.back().expected_miss = [](const StabilityOutcome &o) {
              return setting_text("stretched far cells under-resolve the far field; the rings agree to ",
                                  o.extra);
            };
          }

        // 5. Solvers: CG with AMG against the direct solver on the same system.
        for (const unsigned int levels : {20u, 30u})
          cases.push_back({"solvers", setting_text("CG + AMG vs direct, tip levels ", levels),
                           "vs direct, ring by ring", 1e-8, [&, levels] {
                             const auto on_same_system = [=](Setting &s) {
                               s.model.degree          = 2;
                               s.model.mesh.tip_levels = levels;
                             };
                             const PennyGapMeasurement reference  = solve(base, radii, on_same_system);
                             const PennyGapMeasurement solved     = solve(base, radii, [=](Setting &s) {
                               on_same_system(s);
                               s.model.linear_solver.type           = LinearSolverParameters::Type::cg_amg;
                               s.model.linear_solver.tolerance      = 1e-12;
                               s.model.linear_solver.max_iterations = 20000;
                             });
                             double                    difference = 0;
                             for (unsigned int i = 0; i < solved.rings.size(); ++i)
                               difference = std::max(
                                   difference,
                                   relative_error(solved.rings[i].signed_stress_intensity_factor,
                                                  reference.rings[i].signed_stress_intensity_factor));
                             return outcome(solved, difference);
                           }});

        const unsigned int failures = run_stability_cases(cases, CaseSharing::one_rank_each, results, log);
        if (failures == 0)
          return {true, "every stability case passes or is flagged with its reason"};
        return {false, std::to_string(failures) + " stability case(s) failed; see stability.csv"};
      }

      PennyGapInput  gap;
      LoadParameters load;
      double         target_accuracy;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      StabilityScene, "stability", "Stability",
      "stiff and extreme cases around the scene's parameters, each passing or flagged, in one table", "")
} // namespace penny
