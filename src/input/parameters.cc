#include "input/parameters.h"

#include "input/input_error.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
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
          PENNY_SECTION(random_surfaces, "Random surfaces", RandomSurfaceParameters),
          PENNY_SECTION(summit_statistics, "Summit statistics", SummitStatisticsParameters),
          PENNY_SECTION(bem_westergaard, "BEM Westergaard", BemWestergaardParameters),
          PENNY_SECTION(random_contact, "Random contact", RandomContactParameters),
          PENNY_SECTION(elliptical_model, "Elliptical model", EllipticalModelParameters),
          PENNY_SECTION(elliptical_gap, "Elliptical gap", EllipticalGapParameters),
          PENNY_SECTION(elliptical_summits, "Elliptical summits", EllipticalSummitsParameters),
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

    // One statement of a .prm file: its keyword (set, subsection, end,
    // include, in any case) and the rest of the line.
    std::pair<std::string, std::string> statement(const std::string &line)
    {
      const std::string trimmed = dealii::Utilities::trim(line);
      const std::size_t blank   = trimmed.find_first_of(" \t");
      std::string       keyword = trimmed.substr(0, blank);
      std::transform(keyword.begin(), keyword.end(), keyword.begin(),
                     [](const unsigned char ch) { return std::tolower(ch); });
      return {keyword, blank == std::string::npos ? "" : dealii::Utilities::trim(trimmed.substr(blank))};
    }

    // What deal.II's reader does not check: it follows `include FILE` (at
    // the current subsection, relative to the working folder) without end,
    // and lets the last of two `set` statements of one entry win silently.
    // A cycle of includes and an entry set twice are errors naming the lines.
    class StatementCheck
    {
    public:
      void check(const std::string &filename)
      {
        const std::string file = std::filesystem::weakly_canonical(filename).string();
        if (std::find(open_files.begin(), open_files.end(), file) != open_files.end())
          throw InputError("parameter file " + in_quotes(filename) +
                           " includes itself (a cycle of include statements)");
        if (open_files.size() == 16)
          throw InputError("parameter file " + in_quotes(filename) +
                           ": include statements nest deeper than 16 files");
        // A FIFO, a device or a folder would hang, spin or read as empty.
        if (!std::filesystem::is_regular_file(filename))
          throw InputError("parameter file " + in_quotes(filename) + " does not exist or is not a file");
        std::ifstream in(filename);
        if (!in)
          throw InputError("parameter file " + in_quotes(filename) + " cannot be read");
        open_files.push_back(file);
        files_read.push_back(filename);
        std::string  line;
        unsigned int number = 0;
        while (std::getline(in, line))
          {
            const unsigned int first = ++number;
            // A backslash at the end continues the line.
            for (std::string next; !line.empty() && line.back() == '\\' && std::getline(in, next); ++number)
              line = line.substr(0, line.size() - 1) + next;
            const std::size_t comment = line.find('#');
            if (comment != std::string::npos)
              line.erase(comment);
            const auto [keyword, rest] = statement(line);
            any_statement              = any_statement || !keyword.empty();
            // Lines of an included file name the file.
            const std::string where =
                (open_files.size() > 1 ? in_quotes(filename) + ", " : "") + "line " + std::to_string(first);
            if (keyword == "subsection")
              path.push_back(rest);
            else if (keyword == "end" && !path.empty())
              path.pop_back();
            else if (keyword == "include")
              check(rest);
            else if (keyword == "set" && rest.find('=') != std::string::npos)
              {
                std::string entry;
                for (const std::string &subsection : path)
                  entry += subsection + "/";
                entry += dealii::Utilities::trim(rest.substr(0, rest.find('=')));
                const auto [earlier, first_time] = set_at.emplace(entry, where);
                if (!first_time)
                  throw InputError(where + ": " + entry + " is set a second time (first on " +
                                   earlier->second + "); set each entry once");
              }
          }
        open_files.pop_back();
      }

      // The files read, the first one and every file it includes.
      const std::vector<std::string> &files() const { return files_read; }
      // Whether the files hold any statement.
      bool sets_any() const { return any_statement; }

    private:
      std::vector<std::string>           files_read;
      std::vector<std::string>           open_files; // the chain of includes being read
      std::vector<std::string>           path;       // subsections entered
      std::map<std::string, std::string> set_at;     // entry -> where it was set
      bool                               any_statement = false;
    };

    // deal.II writes names in XML (and may in JSON) with every character
    // other than a letter or digit as _XX, its code in hex.
    std::string demangled(const std::string &name)
    {
      std::string plain;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size() && std::isxdigit(static_cast<unsigned char>(name[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(name[i + 2])))
          {
            plain += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          plain += name[i];
      return plain;
    }

    // deal.II reads JSON and XML parameter files without naming the entry
    // whose value it rejects, and lets a repeated key win silently. Each
    // entry is set once here first, so that an error names it.
    void check_entries(ParameterHandler &prm, const boost::property_tree::ptree &node,
                       const std::vector<std::string> &path, const std::string &scene)
    {
      std::set<std::string> seen;
      for (const auto &[key, child] : node)
        {
          const std::string name = demangled(key);
          std::string       full;
          for (const std::string &subsection : path)
            full += subsection + "/";
          full += name;
          if (!seen.insert(name).second)
            throw InputError(full + " appears twice; set each entry once");
          if (!child.empty() && !child.get_child_optional("value"))
            {
              std::vector<std::string> subsection_path = path;
              subsection_path.push_back(name);
              if (!prm.subsection_path_exists(subsection_path))
                throw InputError("subsection '" + full + "' is " +
                                 (scene.empty()
                                      ? "not a subsection of penny"
                                      : "not read by Scene = " + scene + " ('penny --print-parameters " +
                                            scene + "' lists what it reads)"));
              check_entries(prm, child, subsection_path, scene);
              continue;
            }
          const std::string value = child.empty() ? child.data() : child.get<std::string>("value");
          for (const std::string &subsection : path)
            prm.enter_subsection(subsection);
          try
            {
              prm.set(name, value);
            }
          catch (const ParameterHandler::ExcEntryUndeclared &)
            {
              throw InputError(full + " is not an entry of penny ('penny --print-parameters' lists them)");
            }
          catch (const dealii::ExceptionBase &exception)
            {
              throw InputError(full + " = " + in_quotes(value) + ": " + one_line(exception));
            }
          for (std::size_t i = 0; i < path.size(); ++i)
            prm.leave_subsection();
        }
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
    if (parameters.finite_element && !parameters.geometry && !parameters.periodic_gap)
      require(parameters.finite_element->levels_per_degree == 0, "Finite element/Degree grading",
              parameters.finite_element->levels_per_degree,
              "0 (only the penny-gap and periodic-gap models grade the degree)");
    if (parameters.periodic_gap && parameters.depth_study)
      {
        const auto        &radii      = parameters.periodic_gap->ring_radii;
        const double       max_radius = *std::max_element(radii.begin(), radii.end());
        std::ostringstream smallest;
        smallest << max_radius / 4;
        for (const double depth : parameters.depth_study->depths)
          require(max_radius < 4 * depth, "Depth study/Depths", depth,
                  "(largest ring radius/4 = " + smallest.str() + ", 100] lambda");
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

  std::vector<std::string> parse_parameter_file(ParameterHandler &prm, const std::string &filename,
                                                const std::string &scene)
  {
    if (!std::filesystem::is_regular_file(filename))
      throw InputError("parameter file " + in_quotes(filename) + " does not exist or is not a file");
    const std::string        extension = std::filesystem::path(filename).extension();
    std::vector<std::string> files     = {filename};
    bool                     sets_any;
    if (extension == ".prm")
      {
        StatementCheck statements;
        statements.check(filename);
        files    = statements.files();
        sets_any = statements.sets_any();
      }
    else if (extension == ".json" || extension == ".xml")
      {
        boost::property_tree::ptree tree;
        try
          {
            if (extension == ".json")
              boost::property_tree::read_json(filename, tree);
            else
              {
                boost::property_tree::read_xml(filename, tree);
                tree = tree.get_child("ParameterHandler");
              }
          }
        catch (const boost::property_tree::ptree_error &error)
          {
            throw InputError("parameter file " + in_quotes(filename) + " is not valid " +
                             extension.substr(1) + ": " + one_line(error.what()));
          }
        check_entries(prm, tree, {}, scene);
        sets_any = !tree.empty();
      }
    else
      throw InputError("parameter file " + in_quotes(filename) + " is neither .prm, .json nor .xml");
    // An empty file would run the default scene unasked.
    if (!sets_any)
      throw InputError("parameter file " + in_quotes(filename) +
                       " sets no parameter (add 'set Scene = NAME'; 'penny --help' lists the scenes)");
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
    return files;
  }
} // namespace penny
