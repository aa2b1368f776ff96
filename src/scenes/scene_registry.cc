#include "scenes/scene_registry.h"

#include "fracture/adhesive_gap.h"
#include "fracture/periodic_array.h"
#include "input/input_error.h"
#include "scenes/adhesion_scenes.h"
#include "scenes/convergence_scene.h"
#include "scenes/elliptical_scenes.h"
#include "scenes/fe_gap_area_scene.h"
#include "scenes/penny_gap_scene.h"
#include "scenes/random_surface_scenes.h"
#include "scenes/sinusoid_scenes.h"
#include "scenes/stability_scene.h"
#include "scenes/statistics_scenes.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

namespace penny
{
  using dealii::ParameterHandler;

  namespace
  {
    using S = Section;

    // The sections of every penny-gap FE model, and more.
    std::vector<Section> fe_and(std::vector<Section> more)
    {
      std::vector<Section> sections = {S::geometry,       S::material,      S::load,       S::mesh,
                                       S::finite_element, S::linear_solver, S::j_integral, S::output};
      sections.insert(sections.end(), more.begin(), more.end());
      return sections;
    }

    // The sections of every periodic-gap FE model of the sinusoid, and more.
    std::vector<Section> periodic_and(std::vector<Section> more)
    {
      std::vector<Section> sections = {S::material, S::periodic_gap, S::finite_element, S::linear_solver,
                                       S::output};
      sections.insert(sections.end(), more.begin(), more.end());
      return sections;
    }

    // An entry point whose results carry no verdict of their own.
    template <typename Run>
    std::function<Verdict(const Parameters &, const ResultFolder &, std::ostream &)> without_verdict(Run run)
    {
      return [run](const Parameters &parameters, const ResultFolder &results, std::ostream &log) {
        run(parameters, results, log);
        return Verdict{};
      };
    }

    Verdict stability_verdict(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
    {
      const auto rows     = run_stability_scene(parameters, results, log);
      const auto failures = std::count_if(
          rows.begin(), rows.end(), [](const StabilityRow &row) { return row.status.rfind("FAIL", 0) == 0; });
      if (failures == 0)
        return {true, "every stability case passes or is flagged with its reason"};
      return {false, std::to_string(failures) + " stability case(s) failed; see stability.csv"};
    }

    // K_I on every ring, w(0) and the gap volume against the closed forms.
    Verdict penny_gap_verdict(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
    {
      const PennySceneResults solved = run_penny_gap_scene(parameters, results, log);
      double worst = std::max(relative_error(solved.opening_at_centre, solved.exact_opening_at_centre.value),
                              relative_error(solved.gap_volume, solved.exact_gap_volume.value));
      for (const auto &ring : solved.rings)
        worst = std::max(worst, relative_error(ring.signed_stress_intensity_factor,
                                               solved.exact_stress_intensity_factor.value));
      return verdict("largest relative error of K_I, w(0) and the volume", worst,
                     parameters.verification->tolerance);
    }

    Verdict gap_size_verdict(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
    {
      const double c_over_a = run_gap_size_scene(parameters, results, log).c_over_a;
      return verdict("relative error of c/a", relative_error(c_over_a, closed_form::adhesionless_c_over_a),
                     parameters.verification->tolerance);
    }

    // psi is the value of a minimum, c_min its place: c_min carries the square
    // root of the FE error and is reported, not judged.
    Verdict adhesive_minimum_verdict(const Parameters &parameters, const ResultFolder &results,
                                     std::ostream &log)
    {
      const double psi = run_adhesive_minimum_scene(parameters, results, log).psi;
      return verdict("relative error of psi", relative_error(psi, closed_form::psi),
                     parameters.verification->tolerance);
    }

    Verdict gap_tension_verdict(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
    {
      return verdict("largest relative error of p_hat", run_gap_tension_curve_scene(parameters, results, log),
                     parameters.verification->tolerance);
    }

    Verdict equilibrium_verdict(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
    {
      const auto fe = run_adhesive_equilibrium_scene(parameters, results, log);
      const auto exact =
          closed_form::stable_gap_radius(parameters.load->peak_tension, parameters.load->summit_radius,
                                         parameters.adhesion->critical_stress_intensity);
      if (fe.has_value() != exact.has_value())
        return {false, std::string("FE and closed form disagree on whether the gap closes (FE: ") +
                           (fe ? "open" : "closed") + ")"};
      if (!fe)
        return {true, "FE and closed form agree: the gap closes"};
      return verdict("relative error of c_t", relative_error(*fe, *exact),
                     parameters.verification->tolerance);
    }

    // K_I at every front point on every ring against Green-Sneddon/Irwin.
    Verdict elliptical_gap_verdict(const Parameters &parameters, const ResultFolder &results,
                                   std::ostream &log)
    {
      return verdict("largest relative error of K_I over the front points and rings",
                     run_elliptical_gap_scene(parameters, results, log).largest_error,
                     parameters.verification->tolerance);
    }

    // The gaps' shapes, gap-area ratios and psi against Galin's closed form.
    Verdict elliptical_summits_verdict(const Parameters &parameters, const ResultFolder &results,
                                       std::ostream &log)
    {
      return verdict("largest relative error of b/a, the gap-area ratio and psi",
                     run_elliptical_summits_scene(parameters, results, log).largest_error,
                     parameters.verification->tolerance);
    }

    std::vector<std::string> scene_names()
    {
      std::vector<std::string> names;
      for (const auto &scene : scene_registry())
        names.push_back(scene.name);
      return names;
    }

    std::string scene_documentation()
    {
      std::string doc = "What the run computes:";
      for (const auto &scene : scene_registry())
        doc += " " + scene.name + ": " + scene.description + ".";
      return doc;
    }

    // K_I (|K_I| and signed) on every ring against the closed form.
    Verdict periodic_gap_verdict(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
    {
      const PeriodicGapResults solved = run_periodic_gap_scene(parameters, results, log);
      double                   worst  = 0;
      for (const auto &ring : solved.rings)
        worst = std::max(
            {worst,
             relative_error(ring.stress_intensity_factor, std::abs(solved.exact_stress_intensity_factor)),
             relative_error(ring.signed_stress_intensity_factor, solved.exact_stress_intensity_factor)});
      return verdict("largest relative error of K_I", worst, parameters.verification->tolerance);
    }

    template <CurveErrors (*run)(const Parameters &, const ResultFolder &, std::ostream &)>
    Verdict curve_verdict(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
    {
      return verdict("largest error of p_bar/p*", run(parameters, results, log).largest_load_error,
                     parameters.verification->tolerance);
    }

    Verdict jump_verdict(const Parameters &parameters, const ResultFolder &results, std::ostream &log)
    {
      const JumpIntoContactResults fe = run_jump_into_contact_scene(parameters, results, log);
      return verdict(
          "largest of the relative error of alpha_c and the error of 1 - p_bar_max/p*",
          std::max(relative_error(fe.critical_alpha, periodic_array::critical_alpha), fe.largest_jump_error),
          parameters.verification->tolerance);
    }
  } // namespace

  // clang-format off
  const std::vector<Scene> &scene_registry()
  {
    static const std::vector<Scene> registry = {
      {"penny-gap",
       "one FE solve of the Load; K_I from J-integrals (and the signed K_I) on every ring, the face opening "
       "and the gap volume, beside Sneddon's closed forms",
       fe_and({S::fields, S::verification}), penny_gap_verdict},
      {"gap-size-adhesionless",
       "the gap radius where the FE K_I of the parabola (P, a) vanishes: c/a = sqrt(3/2)",
       fe_and({S::verification}), gap_size_verdict},
      {"adhesive-minimum",
       "the minimum over c of the FE peak tension P(c) at K_I = K_Ic: psi and c_min",
       fe_and({S::adhesion, S::verification}), adhesive_minimum_verdict},
      {"gap-tension-curve",
       "p_hat(c_hat) from FE beside (c_hat^2 + 4/sqrt(c_hat))/5 (paper Fig. 2)",
       fe_and({S::adhesion, S::gap_tension_curve, S::verification}), gap_tension_verdict},
      {"adhesive-equilibrium",
       "the FE gap radius on the stable branch for the peak tension P (the paper's g)",
       fe_and({S::adhesion, S::verification}), equilibrium_verdict},
      {"stability",
       "stiff and extreme cases around the scene's parameters, each passing or flagged, in one table",
       fe_and({S::stability}), stability_verdict},
      {"convergence",
       "the penny-gap solve over the sequence of discretisations in 'Convergence'",
       fe_and({S::convergence}), without_verdict(run_convergence_scene)},
      {"sinusoid-contact",
       "Johnson's adhesive 1D sinusoid from its closed form (paper Fig. 1)",
       {S::sinusoid, S::output}, without_verdict(run_sinusoid_contact_scene)},
      { "periodic-gap",
        "one FE solve of a gap of the sinusoid's periodic array (plane strain): K_I from J-integrals and the "
        "signed K_I on every ring, beside sqrt(lambda) [p* cos^2(pi c/lambda) - p_bar] sqrt(tan(pi "
        "c/lambda))",
        periodic_and({ S::gap_and_load, S::verification }),
        periodic_gap_verdict },
      { "periodic-gap-depth",
        "the periodic-gap K_I against the depth D/lambda of the truncated solid: the truncation study",
        periodic_and({ S::gap_and_load, S::depth_study }),
        without_verdict(run_periodic_gap_depth_scene) },
      { "westergaard-curve",
        "the adhesionless sinusoid: contact half-width a from FE roots of K_I = 0 beside "
        "p_bar/p* = sin^2(pi a/lambda)",
        periodic_and({ S::westergaard_curve, S::verification }),
        curve_verdict<run_westergaard_curve_scene> },
      { "johnson-curves",
        "Johnson's adhesive curves p_bar/p*(a/lambda) from FE roots of K_I = K_Ic beside the closed form "
        "(paper Fig. 1 from FE)",
        periodic_and({ S::johnson_curves, S::verification }),
        curve_verdict<run_johnson_curves_scene> },
      { "jump-into-contact",
        "from FE: the critical alpha of spontaneous full contact at zero load, and the jump-into-contact "
        "load "
        "1 - p_bar_max/p* against alpha beside 5 (alpha/4)^(4/5)",
        periodic_and({ S::jump_into_contact, S::verification }),
        jump_verdict },
      {"elliptical-gap",
       "one 3D FE solve (distributed) of an elliptical gap under uniform pressure: K_I(phi) at the front "
       "points from front-localised J-integrals (signed), beside the Green-Sneddon/Irwin closed form",
       {S::material, S::elliptical_model, S::elliptical_gap, S::finite_element, S::linear_solver, S::fields,
        S::verification, S::output},
       elliptical_gap_verdict},
      {"elliptical-summits",
       "3D FE searches (distributed) for the gaps of summits P (1 - x^2/Ax^2 - y^2/Ay^2): without adhesion "
       "K_I = 0, with adhesion K_I = K_Ic at the ends of the front at the least P (psi), beside Galin's "
       "closed form",
       {S::material, S::elliptical_model, S::elliptical_summits, S::finite_element, S::linear_solver,
        S::verification, S::output},
       elliptical_summits_verdict},
      {"zero-load-gap-area",
       "A_nc/A_0 at zero mean pressure against p0/sqrt(V) (paper Fig. 3)",
       {S::material, S::adhesion, S::roughness, S::area_load, S::zero_load_gap_area, S::output},
       without_verdict(run_zero_load_gap_area_scene)},
      {"area-load",
       "A_nc/A_0 and A_c/A_0 against p_bar/sqrt(V) for each H and zeta (paper Figs. 4 and 5)",
       {S::material, S::adhesion, S::roughness, S::area_load, S::output}, without_verdict(run_area_load_scene)},
      {"rough-surface",
       "moments, summit statistics and p0 of the Roughness spectrum in both conventions, and its area-load curve",
       {S::material, S::adhesion, S::roughness, S::area_load, S::output}, without_verdict(run_rough_surface_scene)},
      {"magnification-scaling",
       "theta of p0/sqrt(V) ~ zeta^theta fitted from the moments, for each H",
       {S::area_load, S::magnification_scaling, S::output}, without_verdict(run_magnification_scaling_scene)},
      {"fe-gap-area",
       "the area-load curve with the FE gap function g beside the closed-form g's",
       fe_and({S::adhesion, S::area_load, S::fe_gap_area}), without_verdict(run_fe_gap_area_scene)},
      {"summit-statistics",
       "summits of the full-contact pressure of sampled Gaussian surfaces over realisations: moments, eta, "
       "summit heights and mean curvature 1/R_p beside the lattice expectation and both conventions",
       {S::material, S::roughness, S::random_surfaces, S::summit_statistics, S::output},
       run_summit_statistics_scene},
      {"bem-westergaard",
       "the FFT boundary-element contact solver on Westergaard's sinusoid: half-width and pressure against "
       "grid size",
       {S::material, S::bem_westergaard, S::output}, run_bem_westergaard_scene},
      {"random-contact",
       "A_nc/A_0 of sampled random surfaces by FFT boundary elements against p_bar/sqrt(V), beside the "
       "isolated-gap law in both conventions and Persson's erfc",
       {S::material, S::roughness, S::random_surfaces, S::random_contact, S::output},
       without_verdict(run_random_contact_scene)}};
    return registry;
  }
  // clang-format on

  const Scene &find_scene(const std::string &name)
  {
    for (const auto &scene : scene_registry())
      if (scene.name == name)
        return scene;
    throw InputError("Scene = '" + name + "' is not a scene (penny --help lists them)");
  }

  void declare_scene(ParameterHandler &prm, const Scene &scene)
  {
    Parameters::declare(prm, scene_names(), scene_documentation(), scene.sections);
    prm.set("Scene", scene.name);
  }

  SceneFile read_scene_file(const std::string &filename)
  {
    std::vector<Section> every_section;
    for (const auto &scene : scene_registry())
      for (const Section section : scene.sections)
        if (std::find(every_section.begin(), every_section.end(), section) == every_section.end())
          every_section.push_back(section);
    ParameterHandler all;
    Parameters::declare(all, scene_names(), scene_documentation(), every_section);
    parse_parameter_file(all, filename, "");
    const Scene &scene = find_scene(all.get("Scene"));

    ParameterHandler prm;
    declare_scene(prm, scene);
    const std::vector<std::string> parameter_files = parse_parameter_file(prm, filename, scene.name);
    const std::string              folder          = std::filesystem::path(filename).parent_path().string();
    SceneFile                      file{&scene,
                   Parameters::parse(prm, scene.sections, folder),
                   "",
                   {parameter_files.begin(), parameter_files.end()}};
    if (file.parameters.mesh && file.parameters.mesh->generator == MeshParameters::Generator::gmsh)
      file.input_files.push_back(file.parameters.mesh->mesh_file);
    if (file.parameters.roughness &&
        file.parameters.roughness->spectrum == RoughnessParameters::Spectrum::file)
      file.input_files.push_back(file.parameters.roughness->spectrum_file);
    std::ostringstream used;
    prm.print_parameters(used, ParameterHandler::PRM);
    file.used_parameters = used.str();
    return file;
  }

  // The output folder is checked (and locked) before the scene runs, and the
  // parameters are recorded last: a run that fails leaves the previous
  // results as they were. Replacing the folder must not remove an input.
  Verdict run_scene_file(const std::string &filename, std::ostream &log)
  {
    const SceneFile file = read_scene_file(filename);
    log << "penny: scene " << file.scene->name << " (" << filename << "): " << file.scene->description
        << "\n\n";
    ResultFolder  results(file.parameters.output.value().directory, file.input_files);
    const Verdict verdict = file.scene->run(file.parameters, results, log);
    results.write("parameters.prm", file.used_parameters);
    results.commit();

    std::set<std::string> files;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      for (const auto &entry : std::filesystem::directory_iterator(results.directory()))
        if (entry.path().filename().string().front() != '.')
          files.insert(entry.path().filename().string());
    log << "\nResults in " << results.directory().string() << "/:";
    for (const auto &file : files)
      log << ' ' << file;
    log << '\n';
    return verdict;
  }
} // namespace penny
