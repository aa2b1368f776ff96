// stability-3d: the stiff and extreme cases of the 3D elliptical-gap model
// around the scene's own parameters, in one table: near-incompressibility,
// slender gaps, the box from 10 a to 1000 a, extreme scales and the iterative
// against the direct solver. K_I at every front point and ring is held to
// Green-Sneddon/Irwin; each case passes, or is flagged with the reason it is
// expected to miss, or fails the scene. Each model is shared by all ranks.
#include "input/input_error.h"
#include "numerics/relative_error.h"
#include "problems/elliptical_gap.h"
#include "problems/stability_cases.h"
#include "scenes/scene.h"

#include <deal.II/base/timer.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <sstream>

namespace penny
{
  namespace
  {
    using dealii::TimerOutput;

    // The model and the gap of one case.
    struct EllipticalSetting
    {
      EllipticalModel model;
      EllipticalGap   gap;
    };

    EllipticalGapMeasurement solve(EllipticalSetting                               setting,
                                   const std::function<void(EllipticalSetting &)> &modify)
    {
      modify(setting);
      TimerOutput        timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
      std::ostringstream model_log; // the cases' progress is the scene's log
      return measure_elliptical_gap(setting.model, setting.gap, timer, model_log, nullptr);
    }

    // The slender gaps' aspect ratios and the boxes (R/a = H/a) of the cases.
    const std::vector<double> aspect_ratios = {1., 0.5, 0.25, 0.1, 0.05};
    const std::vector<double> boxes         = {10., 100., 1000.};

    // Refuses, before any case is solved, a case's model too large for the
    // memory, naming the case.
    void check_size(EllipticalSetting setting, const std::string &name,
                    const std::function<void(EllipticalSetting &)> &modify)
    {
      modify(setting);
      try
        {
          check_elliptical_model_size(setting.model.with_semi_axes(
              setting.gap.semi_axis_a, setting.gap.aspect_ratio * setting.gap.semi_axis_a));
        }
      catch (const InputError &error)
        {
          throw InputError("the case " + name + ": " + error.what());
        }
    }

    StabilityOutcome outcome(const EllipticalGapMeasurement &solved, const double error,
                             const double extra = 0)
    {
      return {error, solved.relative_residual, 0, extra};
    }

    // K_FE/K_exact at every front point and ring, in that order.
    std::vector<double> ratios_to_exact(const EllipticalGapMeasurement &solved)
    {
      std::vector<double> ratios;
      for (const auto &ring : solved.signed_sifs)
        for (unsigned int i = 0; i < ring.size(); ++i)
          ratios.push_back(ring[i] / solved.exact_sifs[i]);
      return ratios;
    }

    struct Stability3dScene : Scene
    {
      void inputs(Sections &sections) override
      {
        elliptical_model_sections(sections, setting.model);
        elliptical_gap_section(sections, setting.gap, setting.model);
      }

      void entries(Entries &entries) override
      {
        entries.number("Target accuracy", target_accuracy, 1e-3, interval("()", 0, 1),
                       "Largest relative K_I error over the front points and rings a case must reach to "
                       "pass; a case expected to miss it is flagged with the reason. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        const EllipticalSetting base   = setting;
        const double            target = target_accuracy;
        // The largest models: the slenderest gap (the most rings), the
        // largest box (the most shells), the solver case's direct and AMG.
        using Type = LinearSolverParameters::Type;
        check_size(base, setting_text("slender gap b/a = ", aspect_ratios.back()),
                   [](EllipticalSetting &s) { s.gap.aspect_ratio = aspect_ratios.back(); });
        check_size(base, setting_text("box R/a = H/a = ", boxes.back()), [](EllipticalSetting &s) {
          s.model.model.mesh.domain_width = s.model.model.mesh.domain_height = boxes.back();
        });
        for (const auto &[type, name] :
             {std::pair{Type::direct, "direct"}, std::pair{Type::cg_amg, "CG + AMG"}})
          check_size(base, std::string("solvers, ") + name,
                     [type = type](EllipticalSetting &s) { s.model.model.linear_solver.type = type; });
        std::vector<StabilityCase> cases;
        const auto                 relative = [&](const std::string &name, const std::string &text,
                                  const std::function<void(EllipticalSetting &)> &modify,
                                  const std::string                              &miss) {
          cases.push_back({name, text, "relative, every point and ring", target, [&base, modify] {
                             const EllipticalGapMeasurement solved = solve(base, modify);
                             return outcome(solved, solved.largest_error);
                           }});
          cases.back().expected_miss = [miss](const StabilityOutcome &) { return miss; };
        };

        // 1. Near-incompressibility at the scene's degree.
        for (const double nu : {0.3, 0.45, 0.49, 0.499})
          relative(
              "incompressibility", setting_text("nu = ", nu),
              [=](EllipticalSetting &s) { s.model.model.material.poissons_ratio = nu; },
              nu >= 0.45 ? "nu -> 1/2: the volumetric stiffness dominates and low degrees lock" : "");

        // 2. Slender gaps: the light mesh's cells around the tip are coarse
        //    for its radius of curvature b^2/a, and the rings, sized in
        //    b^2/a, span few cells (doc/elliptical.md); the weight along the
        //    front, in psi, is biased by at most 5e-4 at b/a = 0.05
        //    (front_weight_bias.py).
        for (const double aspect_ratio : aspect_ratios)
          relative(
              "slender gap", setting_text("b/a = ", aspect_ratio),
              [=](EllipticalSetting &s) { s.gap.aspect_ratio = aspect_ratio; },
              aspect_ratio < 0.5 ? "slender gap: the cells around the tip are coarse for its radius of "
                                   "curvature b^2/a, and rings in b^2/a span few cells"
                                 : "");

        // 3. The box: the closed form is for an infinite solid.
        for (const double box : boxes)
          relative(
              "box", setting_text("R/a = H/a = ", box),
              [=](EllipticalSetting &s) {
                s.model.model.mesh.domain_width  = box;
                s.model.model.mesh.domain_height = box;
              },
              box < base.model.model.mesh.domain_width
                  ? "finite box: the closed form is for an infinite solid"
                  : "");

        // 4. Extreme scales: the same K_FE/K_exact as the unit case, to 1e-8.
        const std::vector<double> unit = ratios_to_exact(solve(base, [](EllipticalSetting &) {}));
        for (const double E : {1e-3, 1e12})
          for (const double a : {1e-9, 1e3})
            cases.push_back({"scales", setting_text("E = ", E) + setting_text(" Pa, a = ", a) + " m",
                             "vs unit case", 1e-8, [&base, &unit, E, a] {
                               const EllipticalGapMeasurement solved = solve(base, [=](EllipticalSetting &s) {
                                 s.model.model.material.youngs_modulus = E;
                                 s.gap.semi_axis_a                     = a;
                               });
                               return outcome(solved, largest_relative_error(ratios_to_exact(solved), unit));
                             }});

        // 5. CG with AMG against the direct solver on the same system.
        cases.push_back(
            {"solvers", "CG + AMG (1e-12) vs direct", "vs direct, every point and ring", 1e-8, [&base] {
               const auto with = [](const LinearSolverParameters::Type type) {
                 return [=](EllipticalSetting &s) {
                   s.model.model.linear_solver.type      = type;
                   s.model.model.linear_solver.tolerance = 1e-12;
                 };
               };
               const auto direct = solve(base, with(LinearSolverParameters::Type::direct));
               const auto cg     = solve(base, with(LinearSolverParameters::Type::cg_amg));
               return outcome(cg, largest_relative_error(ratios_to_exact(cg), ratios_to_exact(direct)));
             }});

        const unsigned int failures = run_stability_cases(cases, CaseSharing::all_ranks, results, log);
        if (failures == 0)
          return {true, "every 3D stability case passes or is flagged with its reason"};
        return {false, std::to_string(failures) + " 3D stability case(s) failed; see stability.csv"};
      }

      EllipticalSetting setting;
      double            target_accuracy;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      Stability3dScene, "stability-3d", "Stability",
      "stiff and extreme cases of the 3D elliptical-gap model around the scene's parameters, "
      "each passing or flagged, in one table",
      "")
} // namespace penny
