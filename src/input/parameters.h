// All parameters of a run: the scene's name and the subsections it reads.
// A scene names the sections it needs; only those are declared, parsed,
// checked and written back, and a subsection it does not read is an error.
#pragma once

#include "input/elliptical_parameters.h"
#include "input/fe_parameters.h"
#include "input/random_surface_parameters.h"
#include "input/scene_parameters.h"
#include "input/sinusoid_parameters.h"
#include "input/statistics_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <optional>
#include <string>
#include <vector>

namespace penny
{
  // One subsection of the parameter file each.
  enum class Section
  {
    geometry,
    material,
    load,
    mesh,
    finite_element,
    linear_solver,
    j_integral,
    adhesion, // after material: K_Ic may come from E' and G_c
    gap_tension_curve,
    convergence,
    stability,
    verification,
    roughness,
    area_load,
    zero_load_gap_area,
    fe_gap_area,
    magnification_scaling,
    sinusoid,
    periodic_gap,
    gap_and_load,
    depth_study,
    westergaard_curve,
    johnson_curves,
    jump_into_contact,
    random_surfaces,
    summit_statistics,
    bem_westergaard,
    random_contact,
    elliptical_model,
    elliptical_gap,
    elliptical_summits,
    fields,
    output
  };

  // The subsection names of `sections`, e.g. "Geometry, Material".
  std::string section_names(const std::vector<Section> &sections);

  struct Parameters
  {
    std::string scene;

    std::optional<GeometryParameters>             geometry;
    std::optional<MaterialParameters>             material;
    std::optional<LoadParameters>                 load;
    std::optional<MeshParameters>                 mesh;
    std::optional<FiniteElementParameters>        finite_element;
    std::optional<LinearSolverParameters>         linear_solver;
    std::optional<JIntegralParameters>            j_integral;
    std::optional<AdhesionParameters>             adhesion;
    std::optional<GapTensionCurveParameters>      gap_tension_curve;
    std::optional<ConvergenceParameters>          convergence;
    std::optional<StabilityParameters>            stability;
    std::optional<VerificationParameters>         verification;
    std::optional<RoughnessParameters>            roughness;
    std::optional<AreaLoadParameters>             area_load;
    std::optional<ZeroLoadGapAreaParameters>      zero_load_gap_area;
    std::optional<FeGapAreaParameters>            fe_gap_area;
    std::optional<MagnificationScalingParameters> magnification_scaling;
    std::optional<SinusoidParameters>             sinusoid;
    std::optional<PeriodicGapParameters>          periodic_gap;
    std::optional<GapAndLoadParameters>           gap_and_load;
    std::optional<DepthStudyParameters>           depth_study;
    std::optional<WestergaardCurveParameters>     westergaard_curve;
    std::optional<JohnsonCurvesParameters>        johnson_curves;
    std::optional<JumpIntoContactParameters>      jump_into_contact;
    std::optional<RandomSurfaceParameters>        random_surfaces;
    std::optional<SummitStatisticsParameters>     summit_statistics;
    std::optional<BemWestergaardParameters>       bem_westergaard;
    std::optional<RandomContactParameters>        random_contact;
    std::optional<EllipticalModelParameters>      elliptical_model;
    std::optional<EllipticalGapParameters>        elliptical_gap;
    std::optional<EllipticalSummitsParameters>    elliptical_summits;
    std::optional<FieldParameters>                fields;
    std::optional<OutputParameters>               output;

    // The 'Scene' entry, a selection of `scene_names`, and the sections.
    static void declare(dealii::ParameterHandler &prm, const std::vector<std::string> &scene_names,
                        const std::string &scene_documentation, const std::vector<Section> &sections);

    // Parses and checks the declared sections; relative file names are
    // taken from `folder`.
    static Parameters parse(dealii::ParameterHandler &prm, const std::vector<Section> &sections,
                            const std::string &folder = "");
  };

  // Reads and checks `filename` with `prm`, in which the scene entry and
  // `sections` have been declared. Throws InputError (one line) for any
  // problem, naming the line of a subsection the scene does not read, and
  // for a file that does not set Scene. Returns the files read: `filename`
  // and every file it includes.
  std::vector<std::string> parse_parameter_file(dealii::ParameterHandler &prm, const std::string &filename,
                                                const std::string &scene);
} // namespace penny
