#include "problems/penny_gap.h"

#include "fe/problem_size.h"
#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"
#include "input/input_error.h"
#include "numerics/relative_error.h"
#include "output/field_output.h"
#include "output/phase_times.h"
#include "problems/fe_sections.h"
#include "problems/solid.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // R/c and H/c.
    constexpr double largest_aspect = 1e12;

    void geometry_section(Sections &sections, GeometryParameters &geometry)
    {
      sections.subsection("Geometry", [&](Entries &entries) {
        entries.number("Gap radius c", geometry.gap_radius, 1, magnitude("m"),
                       "Radius of the penny-shaped gap (crack); a scene that searches over c scales the "
                       "model to each c it tries, so there it fixes only R/c and H/c. Units: m.");
        entries.number(
            "Domain radius R", geometry.domain_radius, 1000, {"(c, 1e12 c]", [](double) { return true; }},
            "Radius of the truncated cylinder. Its effect on K_I shrinks roughly like (c/R)^3 with a free "
            "far boundary, (c/R)^5 under the far field. Units: m.");
        entries.number("Domain height H", geometry.domain_height, 1000,
                       {"(0, 1e12 c]", [](double) { return true; }},
                       "Height of the half model z >= 0. Units: m.");
        if (entries.reading())
          {
            const double      c    = geometry.gap_radius;
            const std::string with = " with Gap radius c = " + shortest(c) + " m";
            entries.require(geometry.domain_radius > c, "Domain radius R", geometry.domain_radius,
                            "(Gap radius c = " + shortest(c) + ", inf)");
            entries.require(geometry.domain_radius <= largest_aspect * c, "Domain radius R",
                            geometry.domain_radius, "(c, 1e12 c]" + with);
            entries.require(geometry.domain_height > 0 && geometry.domain_height <= largest_aspect * c,
                            "Domain height H", geometry.domain_height, "(0, 1e12 c]" + with);
          }
        entries.choice("Far boundary", geometry.far_boundary, FarBoundary::free,
                       EnumNames<FarBoundary>{{"free", FarBoundary::free},
                                              {"clamped", FarBoundary::clamped},
                                              {"far field", FarBoundary::far_field}},
                       "Condition on r = R and z = H: traction free, clamped (u = 0), or the traction of "
                       "the gap's far field, a point source of the gap's own volume, which makes the "
                       "truncated solid answer the infinite one up to about (c/R)^5 (two or three "
                       "solves, each from the last: about 5 % more CG iterations).");
      });
    }

    void mesh_section(Sections &sections, MeshParameters &mesh)
    {
      using Generator = MeshParameters::Generator;
      sections.subsection("Mesh", [&](Entries &entries) {
        entries.choice(
            "Generator", mesh.generator, Generator::builtin,
            EnumNames<Generator>{{"builtin", Generator::builtin}, {"gmsh", Generator::gmsh}},
            "builtin: quadtree of square cells, the tip at a vertex, graded geometrically (ratio 2) "
            "towards the tip and growing to R and H. gmsh: read 'Mesh file'.");
        entries.integer("Tip refinement levels", mesh.tip_levels, 30u, 0u, 40u,
                        "builtin only: cells at the tip are c / 2^levels wide. Units: none.");
        entries.integer("Gap face levels", mesh.gap_face_levels, 3u, 0u, 10u,
                        "builtin only: cells over the gap face, within c of it, are at most c/2^levels "
                        "wide; they resolve the face opening w(r). Units: none.");
        entries.number("Grading distance", mesh.grading_distance, 2, interval("[]", 0.5, 100),
                       "builtin only: a cell is refined while it lies closer to the tip than this many of "
                       "its own widths; larger values give more cells per ring. Units: cell widths.");
        entries.number("Cell aspect ratio", mesh.cell_aspect_ratio, 1, interval("[]", 1, 1000),
                       "builtin only: cells above z = min(c, H/2) are stretched along z to this many times "
                       "their width; the tip zone keeps square cells. A stress test of the mesh and the J "
                       "rings. Units: none.");
        entries.integer("Global refinements", mesh.global_refinements, 0u, 0u, 10u,
                        "Uniform refinements after the grading (h-convergence). Units: none.");
        entries.file("Mesh file", mesh.mesh_file, "../meshes/penny-gap.geo",
                     "gmsh .geo or .msh file (relative paths start at the parameter file's folder). "
                     "Physical tags: surface 1 = solid; curves 1 = axis r = 0, 2 = gap face z = 0 r < c, 3 "
                     "= ligament z = 0 r > c, 4 = far boundary.");
      });
    }

    // The entries that define the load, with their values, for messages.
    std::string load_entries(const LoadParameters &load)
    {
      const std::string P = "Load/Peak tension P = " + shortest(load.peak_tension);
      switch (load.type)
        {
        case LoadParameters::Type::uniform:
          return P;
        case LoadParameters::Type::parabolic:
          return P + " with Load/Tension radius a = " + shortest(load.tension_radius);
        case LoadParameters::Type::expression:
          return "Load/Expression = " + in_quotes(load.expression);
        }
      return "";
    }

    // On the midpoints of a fine grid of the open face 0 < r < c (an
    // integrable singularity at r = 0 is allowed) and at the tip r = c, where
    // a singular load would make K_I infinite. Every rank checks the same
    // points, so the error reaches them all.
    void check_on_face(const LoadParameters &load, const double c)
    {
      std::unique_ptr<FaceLoad> face;
      try
        {
          face = std::make_unique<FaceLoad>(load, c);
        }
      catch (const InputError &error)
        {
          throw InputError("Load/Expression = " + std::string(error.what()));
        }
      constexpr unsigned int n_points = 1000;
      double                 largest  = 0;
      for (unsigned int k = 0; k < n_points; ++k)
        {
          const double r = c * (k + 0.5) / n_points;
          const double p = (*face)(r);
          if (!std::isfinite(p))
            throw InputError(load_entries(load) + " gives p(" + shortest(r) + " m) = " + shortest(p) +
                             "; the load must be finite on 0 < r < c");
          largest = std::max(largest, std::abs(p));
        }
      // The axis too, where a parabola peaks (a load singular there is left to the points above).
      if (std::isfinite((*face)(0)))
        largest = std::max(largest, std::abs((*face)(0)));
      if (!std::isfinite((*face)(c)))
        throw InputError(load_entries(load) + " gives p(c) = " + shortest((*face)(c)) +
                         " at the tip r = c = " + shortest(c) + " m; the load must be finite up to the tip");
      if (largest == 0)
        throw InputError(load_entries(load) +
                         " vanishes on the gap face 0 < r < c: a zero load opens nothing");
      if (!magnitude("Pa").contains(largest))
        throw InputError(load_entries(load) + " gives |p| up to " + shortest(largest) +
                         " Pa on the gap face; the largest |p| must lie in the allowed range " +
                         magnitude("Pa").text);
    }

    // 'Parabola given by' a or R_p (a^2 = 2 R_p P), 'Tension radius a' and 'Summit radius R_p'.
    void parabola_entries(Entries &entries, LoadParameters &load)
    {
      bool by_summit_radius = false;
      entries.choice("Parabola given by", by_summit_radius, false,
                     EnumNames<bool>{{"a", false}, {"R_p", true}},
                     "Parabolic load only: whether the parabola is fixed by its tensile radius a or by "
                     "the pressure summit radius R_p, with a^2 = 2 R_p P.");
      entries.number("Tension radius a", load.tension_radius, 1.25, magnitude("m"),
                     "Parabolic load only: radius where the tension vanishes. Units: m.");
      entries.number("Summit radius R_p", load.summit_radius, 7.8125e-7, magnitude("m^2/Pa"),
                     "Parabolic load only: radius of the pressure summit, p = P - r^2/(2 R_p). Units: "
                     "m^2/Pa.");
      if (!by_summit_radius || !entries.reading() || load.type != LoadParameters::Type::parabolic)
        return;
      entries.require(load.peak_tension > 0, "Peak tension P", load.peak_tension,
                      "(0, 1e30] Pa when the parabola is given by R_p");
      load.tension_radius = std::sqrt(2 * load.summit_radius * load.peak_tension);
      entries.require(magnitude("m").contains(load.tension_radius), "Tension radius a", load.tension_radius,
                      magnitude("m").text + " (a^2 = 2 R_p P)");
    }

    void peak_tension_entry(Entries &entries, double &peak_tension,
                            const Range &range = signed_magnitude("Pa"))
    {
      entries.number("Peak tension P", peak_tension, 1e6, range,
                     "P: the uniform value, or the peak of the parabola at r = 0. Units: Pa.");
    }
  } // namespace

  void penny_gap_model_sections(Sections &sections, PennyGapModelParameters &model)
  {
    geometry_section(sections, model.geometry);
    mesh_section(sections, model.mesh);
    elastic_model_sections(sections, model, ModelDimension::two);
    sections.check([&] {
      check_model_size(model, model_cells(model));
      if (model.mesh.generator == MeshParameters::Generator::gmsh)
        sections.input_file(model.mesh.mesh_file);
    });
  }

  void PennyGapInput::sections(Sections &sections, LoadParameters *face_load)
  {
    penny_gap_model_sections(sections, model);
    if (face_load)
      face_load_section(sections, *face_load, model.geometry);
    ring_section(sections, ring_radii, model.geometry);
  }

  void AdhesiveGapInput::sections(Sections &sections, double *peak_tension)
  {
    gap.sections(sections);
    summit.sections(sections, gap.model.material, peak_tension);
  }

  void AdhesiveSummit::sections(Sections &sections, const MaterialParameters &material, double *peak_tension)
  {
    sections.subsection("Load", [&](Entries &entries) {
      if (peak_tension)
        peak_tension_entry(entries, *peak_tension);
      entries.number("Summit radius R_p", summit_radius, 7.8125e-7, magnitude("m^2/Pa"),
                     "Radius of the pressure summit, p = P - r^2/(2 R_p). Units: m^2/Pa.");
    });
    adhesion_section(sections, critical_stress_intensity, material);
  }

  double model_cells(const PennyGapModelParameters &model)
  {
    const auto &mesh = model.mesh;
    if (mesh.generator == MeshParameters::Generator::gmsh &&
        !std::filesystem::is_regular_file(mesh.mesh_file))
      throw InputError("Mesh/Mesh file = " + in_quotes(mesh.mesh_file) +
                       " does not exist or is not a file (expected a gmsh .geo or .msh file)");
    try
      {
        return penny_gap_mesh_cells(model.geometry, mesh, model.communicator);
      }
    catch (const InputError &error)
      {
        throw InputError("Mesh/Mesh file = " + std::string(error.what()));
      }
  }

  void check_model_size(const PennyGapModelParameters &model, const double cells, const std::string &more)
  {
    const auto        &mesh = model.mesh;
    std::ostringstream entries;
    entries.precision(3);
    if (mesh.generator == MeshParameters::Generator::builtin)
      entries << "Mesh/Tip refinement levels = " << mesh.tip_levels
              << ", Grading distance = " << mesh.grading_distance << ", ";
    else
      entries << "Mesh/Mesh file = " << in_quotes(mesh.mesh_file) << ", ";
    entries << "Global refinements = " << mesh.global_refinements
            << ", Finite element/Polynomial degree = " << model.degree << more;
    if (mesh.generator == MeshParameters::Generator::builtin)
      entries << " (R = " << model.geometry.domain_radius / model.geometry.gap_radius
              << " c, H = " << model.geometry.domain_height / model.geometry.gap_radius << " c)";
    check_problem_size(problem_size(cells, model.degree, model.linear_solver.type,
                                    Utilities::MPI::n_mpi_processes(model.communicator)),
                       entries.str(), model.communicator);
  }

  void face_load_section(Sections &sections, LoadParameters &load, const GeometryParameters &geometry)
  {
    using Type = LoadParameters::Type;
    sections.subsection("Load", [&](Entries &entries) {
      entries.choice("Type", load.type, Type::uniform,
                     EnumNames<Type>{{"uniform", Type::uniform},
                                     {"parabolic", Type::parabolic},
                                     {"expression", Type::expression}},
                     "Face traction p(r) opening the gap: uniform p = P; parabolic (Bueckner) p = P (1 - "
                     "r^2/a^2); expression: any p(r) in 'Expression'.");
      peak_tension_entry(entries, load.peak_tension);
      parabola_entries(entries, load);
      entries.text("Expression", load.expression, "1e6 * (r/c)^4",
                   "p(r) for Type = expression, in muparser syntax; variable r (m), constants c (gap "
                   "radius, m), P (peak tension, Pa) and pi. Units: Pa.");
    });
    sections.check([&] { check_on_face(load, geometry.gap_radius); });
  }

  void parabola_section(Sections &sections, LoadParameters &load)
  {
    load.type = LoadParameters::Type::parabolic;
    sections.subsection("Load", [&](Entries &entries) {
      // The scenes of the parabola alone scale their errors by P: a tension.
      peak_tension_entry(entries, load.peak_tension, magnitude("Pa"));
      parabola_entries(entries, load);
    });
  }

  void ring_section(Sections &sections, std::vector<double> &ring_radii, const GeometryParameters &geometry)
  {
    sections.subsection("J-integral", [&](Entries &entries) {
      entries.increasing_numbers(
          "Ring radii", ring_radii, {0.25, 0.5, 0.75}, 1, interval("()", 0, 1),
          "Outer radii of the J-integral domains around the tip, weight q = (1 - (d/rho)^2)^4; the "
          "searches use the last. Units: c.");
      if (!entries.reading())
        return;
      const double c          = geometry.gap_radius;
      const double room       = std::min(geometry.domain_height, geometry.domain_radius - c);
      const double max_radius = ring_radii.back();
      entries.require(max_radius * c < room, "Ring radii", max_radius,
                      "(0, min(H, R - c)/c = " + Utilities::to_string(room / c) + ")");
    });
  }

  double report_rings(const std::vector<RingResult> &rings, const double exact, const std::string &ring_unit,
                      const Table &summary, const ResultFolder &results, std::ostream &log)
  {
    Table  table({{"ring (" + ring_unit + ")", Table::digits},
                  {"J (J/m^2)", Table::digits},
                  {"|K_I| FE (Pa m^1/2)", Table::digits},
                  {"K_I signed FE (Pa m^1/2)", Table::digits},
                  {"K_I exact (Pa m^1/2)", Table::digits},
                  {"|K_I| relative error", Table::error_digits},
                  {"signed K_I relative error", Table::error_digits}});
    double worst = 0;
    for (const auto &ring : rings)
      {
        const double modulus_error = relative_error(ring.stress_intensity_factor, std::abs(exact));
        const double signed_error  = relative_error(ring.signed_stress_intensity_factor, exact);
        worst                      = worse(worse(worst, modulus_error), signed_error);
        table.add_row({ring.radius, ring.energy_release_rate, ring.stress_intensity_factor,
                       ring.signed_stress_intensity_factor, exact, modulus_error, signed_error});
      }
    publish(table, "rings.csv", results, log);
    if (rings.back().signed_stress_intensity_factor < 0)
      log << "K_I < 0: the faces would interpenetrate; no open gap of this size carries this load.\n";
    log << '\n';
    publish(summary, "summary.csv", results, log);
    return worst;
  }

  PennyGapMeasurement measure_penny_gap(PennyGapModel &model, const FaceLoad &load,
                                        const std::vector<double> &ring_radii, TimerOutput &timer,
                                        const ResultFolder *fields)
  {
    const double             c         = model.gap_radius();
    const DisplacementVector u         = model.solve(load);
    const FaceLoad           reference = FaceLoad::unit_uniform();
    const double             residual  = model.last_solve().relative_residual;
    const DisplacementVector u_ref     = model.solve(reference);

    PennyGapMeasurement results;
    {
      TimerOutput::Scope                 scope(timer, "J-integral");
      const double                       e_prime = model.material().plane_strain_modulus();
      const DomainIntegral<Axisymmetric> j_integral(model.get_system(), e_prime);
      // All rings in one pass over the cells.
      std::vector<RingExtension<2>> rings;
      for (const double rho : ring_radii)
        rings.emplace_back(model.crack_tip(), rho * c, c);
      std::vector<const CrackExtension<2> *> extensions;
      for (const auto &ring : rings)
        extensions.push_back(&ring);
      const DomainIntegral<Axisymmetric>::Traction t = face_traction(load), t_ref = face_traction(reference);
      const auto K = j_integral.stress_intensities({{&u, &t}}, {&u_ref, &t_ref}, extensions, true);
      for (unsigned int i = 0; i < ring_radii.size(); ++i)
        {
          const double G = K.energy_release_rates[0][i];
          results.rings.push_back(
              {ring_radii[i], G, j_integral.stress_intensity_factor(G), K.signed_sifs[0][i]});
        }
      results.opening_at_centre = model.opening_at_centre(u);
      results.gap_volume        = model.gap_volume(u);
    }
    {
      TimerOutput::Scope    scope(timer, "closed form");
      const SneddonSolution exact(load, c, model.material().plane_strain_modulus());
      results.exact_stress_intensity_factor = exact.stress_intensity_factor();
      results.exact_opening_at_centre       = exact.opening_at_centre();
      results.exact_gap_volume              = exact.gap_volume();
    }
    results.n_cells            = model.get_system().get_triangulation().n_global_active_cells();
    results.n_dofs             = model.get_system().get_dof_handler().n_dofs();
    results.relative_residual  = std::max(residual, model.last_solve().relative_residual);
    results.condition_estimate = model.last_solve().condition_estimate;
    results.solver             = model.get_system().solver_name();

    if (fields)
      {
        TimerOutput::Scope scope(timer, "output");
        const double       largest = *std::max_element(ring_radii.begin(), ring_radii.end());
        write_fields(model.get_system(), u, RingExtension<2>(model.crack_tip(), largest * c, c),
                     model.crack_tip(), *fields);
        write_opening_profile(model.get_system(), u, load, c, model.material().plane_strain_modulus(),
                              *fields);
      }
    return results;
  }

  PennyGapMeasurement solve_penny_gap(const PennyGapModelParameters &model, const LoadParameters &load,
                                      const std::vector<double> &ring_radii, TimerOutput &timer)
  {
    PennyGapModel gap(model, timer);
    return measure_penny_gap(gap, FaceLoad(load, model.geometry.gap_radius), ring_radii, timer);
  }

  PennyGapSearch::PennyGapSearch(const PennyGapInput &gap, std::ostream &log)
      : timer(std::cout, TimerOutput::never, TimerOutput::wall_times),
        gaps({gap.model, gap.ring_radii.back()}, timer), progress(log, "gap radii solved")
  {
    gaps.observe([this](const double c) {
      std::ostringstream state;
      state.precision(10);
      state << "last c = " << c << " m";
      progress.step(state.str());
    });
  }

  void PennyGapSearch::add_cost(Table &summary) const
  {
    summary.add_row({"FE solves", Utilities::MPI::sum(gaps.n_solves(), MPI_COMM_WORLD)});
    add_phase_times(summary, timer);
  }
} // namespace penny
