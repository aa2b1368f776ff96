#include "input/parameters.h"

#include "input/input_error.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <typeinfo>

namespace penny
{
  using dealii::ParameterHandler;

  namespace
  {
    // One row per section: its subsection name, and how it is declared and
    // parsed into its member of Parameters.
    struct SectionEntry
    {
      Section     section;
      const char *name;
      void (*declare)(ParameterHandler &);
      void (*parse)(ParameterHandler &, Parameters &);
    };

    template <auto member, typename Struct> void parse_into(ParameterHandler &prm, Parameters &parameters)
    {
      Struct section;
      section.parse(prm);
      parameters.*member = section;
    }

    void parse_adhesion(ParameterHandler &prm, Parameters &parameters)
    {
      if (!parameters.material)
        throw std::logic_error("the Adhesion section needs the Material section");
      AdhesionParameters adhesion;
      adhesion.parse(prm, *parameters.material);
      parameters.adhesion = adhesion;
    }

#define PENNY_SECTION(enumerator, name, Struct)                                                              \
  SectionEntry                                                                                               \
  {                                                                                                          \
    Section::enumerator, name, &Struct::declare, &parse_into<&Parameters::enumerator, Struct>                \
  }

    const std::vector<SectionEntry> &section_table()
    {
      static const std::vector<SectionEntry> table = {
          PENNY_SECTION(geometry, "Geometry", GeometryParameters),
          PENNY_SECTION(material, "Material", MaterialParameters),
          PENNY_SECTION(load, "Load", LoadParameters),
          PENNY_SECTION(mesh, "Mesh", MeshParameters),
          PENNY_SECTION(finite_element, "Finite element", FiniteElementParameters),
          PENNY_SECTION(linear_solver, "Linear solver", LinearSolverParameters),
          PENNY_SECTION(j_integral, "J-integral", JIntegralParameters),
          SectionEntry{Section::adhesion, "Adhesion", &AdhesionParameters::declare, &parse_adhesion},
          PENNY_SECTION(gap_tension_curve, "Gap-tension curve", GapTensionCurveParameters),
          PENNY_SECTION(convergence, "Convergence", ConvergenceParameters),
          PENNY_SECTION(stability, "Stability", StabilityParameters),
          PENNY_SECTION(verification, "Verification", VerificationParameters),
          PENNY_SECTION(roughness, "Roughness", RoughnessParameters),
          PENNY_SECTION(area_load, "Area-load", AreaLoadParameters),
          PENNY_SECTION(zero_load_gap_area, "Zero-load gap area", ZeroLoadGapAreaParameters),
          PENNY_SECTION(fe_gap_area, "FE gap area", FeGapAreaParameters),
          PENNY_SECTION(magnification_scaling, "Magnification scaling", MagnificationScalingParameters),
          PENNY_SECTION(sinusoid, "Sinusoid", SinusoidParameters),
          PENNY_SECTION(periodic_gap, "Periodic gap", PeriodicGapParameters),
          PENNY_SECTION(gap_and_load, "Gap and load", GapAndLoadParameters),
          PENNY_SECTION(depth_study, "Depth study", DepthStudyParameters),
          PENNY_SECTION(westergaard_curve, "Westergaard curve", WestergaardCurveParameters),
          PENNY_SECTION(johnson_curves, "Johnson curves", JohnsonCurvesParameters),
          PENNY_SECTION(jump_into_contact, "Jump into contact", JumpIntoContactParameters),
          PENNY_SECTION(elliptical_gap, "Elliptical gap", EllipticalGapParameters),
          PENNY_SECTION(fields, "Fields", FieldParameters),
          PENNY_SECTION(output, "Output", OutputParameters)};
      return table;
    }
#undef PENNY_SECTION

    bool contains(const std::vector<Section> &sections, const Section section)
    {
      return std::find(sections.begin(), sections.end(), section) != sections.end();
    }

    // Relative paths in a parameter file start at the file's folder.
    void resolve(std::string &path, const std::string &folder)
    {
      if (std::filesystem::path(path).is_relative())
        path = (std::filesystem::path(folder) / path).lexically_normal().string();
    }
  } // namespace

  std::string section_names(const std::vector<Section> &sections)
  {
    std::string names;
    for (const auto &entry : section_table())
      if (contains(sections, entry.section))
        names += (names.empty() ? "" : ", ") + std::string(entry.name);
    return names;
  }

  void Parameters::declare(ParameterHandler &prm, const std::vector<std::string> &scene_names,
                           const std::string &scene_documentation, const std::vector<Section> &sections)
  {
    std::string names;
    for (const auto &name : scene_names)
      names += (names.empty() ? "" : "|") + name;
    prm.declare_entry("Scene", scene_names.front(), dealii::Patterns::Selection(names), scene_documentation);
    for (const auto &entry : section_table())
      if (contains(sections, entry.section))
        entry.declare(prm);
  }

  Parameters Parameters::parse(ParameterHandler &prm, const std::vector<Section> &sections,
                               const std::string &folder)
  {
    Parameters parameters;
    parameters.scene = prm.get("Scene");
    for (const auto &entry : section_table())
      if (contains(sections, entry.section))
        entry.parse(prm, parameters);

    if (parameters.geometry && parameters.j_integral)
      {
        const auto  &geometry   = *parameters.geometry;
        const auto  &radii      = parameters.j_integral->ring_radii;
        const double c          = geometry.gap_radius;
        const double room       = std::min(geometry.domain_height, geometry.domain_radius - c);
        const double max_radius = *std::max_element(radii.begin(), radii.end());
        require(max_radius * c < room, "J-integral/Ring radii", max_radius,
                "(0, min(H, R - c)/c = " + dealii::Utilities::to_string(room / c) + ")");
      }
    if (parameters.periodic_gap && parameters.depth_study)
      {
        const auto        &radii      = parameters.periodic_gap->ring_radii;
        const double       max_radius = *std::max_element(radii.begin(), radii.end());
        std::ostringstream smallest;
        smallest << max_radius / 4;
        for (const double depth : parameters.depth_study->depths)
          require(max_radius < 4 * depth, "Depth study/Depths", depth,
                  "(largest ring radius/4 = " + smallest.str() + ", inf)");
      }
    if (parameters.mesh)
      {
        resolve(parameters.mesh->mesh_file, folder);
        if (parameters.mesh->generator == MeshParameters::Generator::gmsh &&
            !std::filesystem::is_regular_file(parameters.mesh->mesh_file))
          throw InputError("Mesh/Mesh file = '" + parameters.mesh->mesh_file +
                           "' does not exist (expected a gmsh .geo or .msh file)");
      }
    if (parameters.roughness)
      {
        resolve(parameters.roughness->spectrum_file, folder);
        if (parameters.roughness->spectrum == RoughnessParameters::Spectrum::file &&
            !std::filesystem::is_regular_file(parameters.roughness->spectrum_file))
          throw InputError("Roughness/Spectrum file = '" + parameters.roughness->spectrum_file +
                           "' does not exist (expected two columns q (1/m), C(q) (m^4))");
      }
    return parameters;
  }

  void parse_parameter_file(ParameterHandler &prm, const std::string &filename, const std::string &scene)
  {
    if (!std::filesystem::is_regular_file(filename))
      throw InputError("parameter file '" + filename + "' does not exist or is not a file");
    try
      {
        prm.parse_input(filename);
      }
    catch (const dealii::ExceptionBase &exception)
      {
        std::string message = one_line(exception);
        // With only the scene's sections declared, any other subsection is
        // one the scene does not read.
        std::smatch match;
        if (!scene.empty() && typeid(exception) == typeid(ParameterHandler::ExcNoSubsection) &&
            std::regex_search(message, match,
                              std::regex("Line <([0-9]+)> of file <.*: There is no such "
                                         "subsection to be entered: (.*)$")))
          message = "line " + match[1].str() + ": subsection '" + match[2].str() +
                    "' is not read by Scene = " + scene + " ('penny --print-parameters " + scene +
                    "' lists what it reads)";
        throw InputError(message);
      }
  }
} // namespace penny
