#include "problems/elliptical_gap.h"

#include "closed_forms/elliptical_crack.h"
#include "fe/problem_size.h"
#include "fracture/front_stress_intensity.h"
#include "numerics/relative_error.h"
#include "output/elliptical_fields.h"
#include "problems/fe_sections.h"
#include "problems/penny_gap.h"
#include "problems/solid.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // Sum over the ranks of the peak resident set size (MB).
    double peak_memory(MPI_Comm communicator)
    {
      Utilities::System::MemoryStats stats;
      Utilities::System::get_memory_stats(stats);
      return Utilities::MPI::sum(static_cast<double>(stats.VmHWM), communicator) / 1024;
    }

    // The axisymmetric model of the circle of radius a at its defaults, in a
    // cylinder of radius R and height H with the box's far boundary.
    PennyGapModelParameters axisymmetric_circle(const EllipticalModel &settings, const EllipticalGap &gap)
    {
      auto model                   = default_values<PennyGapModelParameters>(penny_gap_model_sections);
      model.material               = settings.model.material;
      model.geometry.gap_radius    = gap.semi_axis_a;
      model.geometry.domain_radius = settings.model.mesh.domain_width * gap.semi_axis_a;
      model.geometry.domain_height = settings.model.mesh.domain_height * gap.semi_axis_a;
      model.geometry.far_boundary  = settings.model.far_boundary;
      return model;
    }

    // K_I of the circle under the pressure p from that model.
    double axisymmetric_stress_intensity_factor(const PennyGapModelParameters &model, const double pressure)
    {
      const auto rings =
          default_values<std::vector<double>>([&](Sections &sections, std::vector<double> &radii) {
            ring_section(sections, radii, model.geometry);
          });
      const LoadParameters load{LoadParameters::Type::uniform, pressure, 1, "", 1};
      TimerOutput          timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
      return solve_penny_gap(model, load, rings, timer).rings.back().signed_stress_intensity_factor;
    }
  } // namespace

  EllipticalGapModelParameters EllipticalModel::with_semi_axes(const double a, const double b) const
  {
    EllipticalGapModelParameters shaped = model;
    shaped.mesh.semi_axis_a             = a;
    shaped.mesh.semi_axis_b             = b;
    return shaped;
  }

  void elliptical_model_sections(Sections &sections, EllipticalModel &model)
  {
    auto &mesh = model.model.mesh;
    elastic_model_sections(sections, model.model, ModelDimension::three);
    sections.subsection("Elliptical model", [&](Entries &entries) {
      entries.number("Box width R/a", mesh.domain_width, 40, interval("[]", 2.8, largest_box),
                     "The quarter model reaches x = R and y = R. Units: a.");
      entries.number("Box height H/a", mesh.domain_height, 40, interval("[]", 2.8, largest_box),
                     "The model reaches z = H (with free far faces K_I of the circle moves by 1e-4 between "
                     "20 and 40). Units: a.");
      entries.choice("Far boundary", model.model.far_boundary, FarBoundary::free,
                     EnumNames<FarBoundary>{{"free", FarBoundary::free},
                                            {"clamped", FarBoundary::clamped},
                                            {"far field", FarBoundary::far_field}},
                     "Condition on the faces x = R, y = R and z = H: traction free, clamped (u = 0), or the "
                     "traction of the gap's far field, a point source of the gap's own volume, which makes "
                     "the box answer the infinite solid up to about (a/R)^5 (two or three solves, each from "
                     "the last: about 5 % more CG iterations).");
      entries.integer(
          "Cells along front", mesh.cells_along_front, 16u, 2u, 256u,
          "Edges of the quarter front 0 <= phi <= pi/2, evenly spaced in the front coordinate (phi + "
          "alpha)/2, alpha the angle of the front's normal: finer where the front turns fastest; even. "
          "Units: none.");
      entries.require(mesh.cells_along_front % 2 == 0, "Cells along front", mesh.cells_along_front,
                      "{2, 4, 6, ..., 256}");
      entries.integer("Sectors around front", mesh.cells_around_front, 8u, 4u, 64u,
                      "Sectors of the half-plane around the front in every normal plane; a multiple of 4. "
                      "Units: none.");
      entries.require(mesh.cells_around_front % 4 == 0, "Sectors around front", mesh.cells_around_front,
                      "{4, 8, 12, ..., 64}");
      entries.number(
          "Front cell size", mesh.front_cell_size, 1e-3, interval("()", 0, 0.33),
          "Radius of the innermost ring of cells around the front, in the front's normal plane, over "
          "min(b, the front's radius of curvature) (b^2/a at phi = 0, b at pi/2); it grows by at most "
          "Ring ratio from one column of front cells to the next. Units: none.");
      entries.number("Ring ratio", mesh.ring_ratio, 1.6, interval("(]", 1, 4),
                     "Nominal ratio of successive ring radii around the front. Units: none.");
      entries.number(
          "Outer shell aspect", mesh.outer_shell_aspect, 3, interval("[]", 1, 6),
          "Radial thickness over angular width of the shells of cells between the tube around the front "
          "and the box (they thicken geometrically outwards): 2 costs half again the shells of 3 and "
          "takes K_I at degree 4 from about 1e-6 to a few 1e-7 (doc/elliptical.md), where the far "
          "field's cells limit. Units: none.");
      entries.integer(
          "Global refinements", model.model.global_refinements, 0u, 0u, 3u,
          "Uniform refinements of the graded coarse mesh (each multiplies the DoFs by about 8); new front "
          "points lie on the ellipse. Units: none.");
      entries.integer(
          "Tip refinements", model.model.tip_refinements, 0u, 0u, 2u,
          "Refinements, after the uniform ones, of the cells within Tip refinement radius of the tip (a, 0, "
          "0), the end of the major axis, that do not touch the front (its cells and points stay), for "
          "slender gaps, whose tip's radius of curvature b^2/a is small against the cells around it: at b/a "
          "= 0.1 one refinement within 0.3 a lowers K_I's largest error 8 times at degree 2 and 14 times at "
          "degree 3 for 3 times the DoFs, no more than one degree higher gains (doc/elliptical.md). Units: "
          "none.");
      entries.number("Tip refinement radius", model.model.tip_refinement_radius, 0.3,
                     interval("(]", 0, 1, "a"),
                     "Radius of the ball around the tip whose cells Tip refinements refines. Units: a.");
      entries.number(
          "Front weight half-width", model.front_weight.half_width_cells, 2, above(0),
          "Half-width of the weight along the front of each domain integral, in front cells of the refined "
          "mesh: a whole number, so that the weight's support ends on column boundaries (inside a cell the "
          "quadrature misses its end: errors of a few 1e-4 in K_I); up to Cells along front x 2^Global "
          "refinements. Units: front cells.");
      const unsigned int front_cells = model.front_cells();
      const double       half_width  = model.front_weight.half_width_cells;
      entries.require(
          half_width == std::round(half_width) && half_width <= front_cells, "Front weight half-width",
          half_width,
          "{1, 2, ..., Cells along front x 2^Global refinements = " + std::to_string(front_cells) + "}");
      entries.choice(
          "Front weight moments", model.front_weight.vanishing_moments, 5u,
          EnumNames<unsigned int>{{"5", 5u}, {"7", 7u}},
          "Highest order of the front weight's moments that vanish: 5, the bump (1 - t^2)^4 (1 - 10 t^2 + "
          "17 t^4), whose bias against the point value falls like h^6 in its half-width h; or 7, (1 - "
          "t^2)^4 (1 - 17 t^2 + (323/5) t^4 (1 - t^2)), bias h^8 (3e-6 against 6e-8 at b/a = 0.25 over two "
          "front cells: postprocess/front_weight_bias.py), whose three sign changes on each side need "
          "finer meshes (at degree 2 with 16 cells along the front the error of K_I is about 10 % larger): "
          "for six digits. Units: none.");
      entries.increasing_numbers(
          "Ring radii", model.ring_radii, {0.1, 0.2, 0.4}, 1, interval("()", 0, 1),
          "Radii rho of the J-integral tubes around the front, q = (1 - (d/rho)^2)^4 across "
          "it; below the smallest radius of curvature b^2/a of the front; elliptical-summits uses the "
          "last. Units: b^2/a.");
    });
  }

  void elliptical_gap_section(Sections &sections, EllipticalGap &gap, const EllipticalModel &model)
  {
    sections.subsection("Elliptical gap", [&](Entries &entries) {
      entries.number("Semi-axis a", gap.semi_axis_a, 1, magnitude("m"),
                     "The larger semi-axis of the gap x^2/a^2 + y^2/b^2 < 1 on z = 0, along x. Units: m.");
      entries.number("Aspect ratio b/a", gap.aspect_ratio, 0.5, interval("[]", smallest_aspect_ratio, 1),
                     "The smaller semi-axis b along y over a; below the allowed range the cells around "
                     "the tip degenerate, and slender gaps need finer meshes than round ones "
                     "(doc/elliptical.md). Units: none.");
      entries.number(
          "Pressure p", gap.pressure, 1e6, signed_magnitude("Pa"),
          "Normal traction opening the gap faces at their centre (everywhere, unless a traction term "
          "below is set). Units: Pa.");
      entries.require(gap.pressure != 0, "Pressure p", gap.pressure,
                      "|p| in [1e-30, 1e30] Pa: a zero load opens nothing");
      const std::string traction =
          "in the face traction p (1 + c_x x^2/a^2 + c_y y^2/b^2): 0 for both c_x and "
          "c_y is the uniform pressure p (Green-Sneddon/Irwin), otherwise a quadratic "
          "traction like the summits' tension (Galin's closed form); at least -1, so "
          "that the traction keeps the sign of p on the gap face and K_I vanishes "
          "nowhere on the front. Units: none.";
      entries.number("Traction x^2 term c_x", gap.x_term, 0, interval("[]", -1, 1e6), "c_x " + traction);
      entries.number("Traction y^2 term c_y", gap.y_term, 0, interval("[]", -1, 1e6), "c_y " + traction);
      entries.integer(
          "Front points", gap.front_points, 17u, 2u, 1000u,
          "K_I is reported at n points from phi = 0 to pi/2 evenly spaced in the front coordinate "
          "(phi + alpha)/2 (alpha the normal's angle), as the mesh's front cells are (on their "
          "vertices), one domain integral each; n - 1 must divide Cells along front x 2^Global refinements, "
          "as a point between vertices puts its weight's ends inside cells. Units: none.");
    });
    sections.check([&] {
      const unsigned int front_cells = model.front_cells();
      require(front_cells % (gap.front_points - 1) == 0, "Elliptical gap/Front points", gap.front_points,
              "n with n - 1 dividing Cells along front x 2^Global refinements = " +
                  std::to_string(front_cells));
    });
  }

  void check_elliptical_model_size(const EllipticalGapModelParameters &model)
  {
    std::ostringstream entries;
    entries << "Elliptical model/Cells along front = " << model.mesh.cells_along_front
            << ", Sectors around front = " << model.mesh.cells_around_front
            << ", Front cell size = " << model.mesh.front_cell_size
            << ", Ring ratio = " << model.mesh.ring_ratio
            << ", Global refinements = " << model.global_refinements
            << ", Tip refinements = " << model.tip_refinements
            << ", Finite element/Polynomial degree = " << model.degree
            << ", Linear solver/Type: " << solver_name(model.linear_solver, MPI_COMM_WORLD);
    check_problem_size(elliptical_problem_size(elliptical_model_cells(model), model.degree,
                                               model.linear_solver.type,
                                               Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)),
                       entries.str(), MPI_COMM_WORLD);
  }

  QuadraticTraction EllipticalGap::traction() const
  {
    const double a = semi_axis_a, b = aspect_ratio * semi_axis_a;
    return {pressure, pressure * x_term / (a * a), pressure * y_term / (b * b)};
  }

  std::string ring_name(const double rho)
  {
    std::ostringstream name;
    name << "ring " << rho << " b^2/a";
    return name.str();
  }

  EllipticalGapMeasurement measure_elliptical_gap(const EllipticalModel &settings, const EllipticalGap &gap,
                                                  TimerOutput &timer, std::ostream &log,
                                                  const ResultFolder *fields)
  {
    log << "Building the quarter model of the gap b/a = " << gap.aspect_ratio << "...\n" << std::flush;
    const auto parameters = settings.with_semi_axes(gap.semi_axis_a, gap.aspect_ratio * gap.semi_axis_a);
    check_elliptical_model_size(parameters);
    // The circle under uniform pressure is compared with the axisymmetric model.
    std::optional<PennyGapModelParameters> circle;
    if (gap.aspect_ratio == 1 && gap.uniform())
      {
        circle = axisymmetric_circle(settings, gap);
        check_model_size(*circle, model_cells(*circle),
                         " of the axisymmetric model the circle is compared with");
      }
    EllipticalGapModel model(parameters, timer);
    const auto        &system = model.get_system();
    log << system.get_triangulation().n_global_active_cells() << " cells, "
        << system.get_dof_handler().n_dofs() << " DoFs, " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
        << " MPI rank(s); solving...\n"
        << std::flush;
    const QuadraticTraction            t        = gap.traction();
    const EllipticalGapModel::Traction traction = [t](const Point<3> &x) { return t(x[0], x[1]); };
    const DisplacementVector           u        = model.solve(traction);

    EllipticalGapMeasurement solved;
    solved.angles     = front_point_angles(gap.front_points, model.front());
    solved.ring_radii = settings.ring_radii;
    {
      TimerOutput::Scope scope(timer, "J-integral");
      log << "K_I at " << solved.angles.size() << " front points on " << solved.ring_radii.size()
          << " ring(s)...\n"
          << std::flush;
      // The signed K_I takes the traction over p (1 at the centre, of one
      // sign on the face) as reference; by linearity its displacement is u/p,
      // no second solve.
      const double       p         = gap.pressure;
      DisplacementVector reference = u;
      reference /= p;
      const EllipticalGapModel::Traction per_p = [&traction, p](const Point<3> &x) {
        return traction(x) / p;
      };
      const FrontStressIntensity front(model, solved.angles, settings.front_weight, solved.ring_radii);
      solved.signed_sifs = front.signed_sifs({{&u, &traction}}, reference, per_p).front();
    }
    const double        e_prime = model.material().plane_strain_modulus();
    const GalinSolution exact(model.front().semi_axis_a(), model.front().semi_axis_b(), t, e_prime);
    solved.largest_error = 0;
    for (const double phi : solved.angles)
      solved.exact_sifs.push_back(exact.stress_intensity_factor(phi));
    for (const auto &ring : solved.signed_sifs)
      solved.largest_error = worse(solved.largest_error, largest_relative_error(ring, solved.exact_sifs));
    if (circle)
      {
        TimerOutput::Scope scope(timer, "axisymmetric model");
        log << "The circle: K_I of the axisymmetric model...\n" << std::flush;
        solved.axisymmetric_sifs.assign(solved.angles.size(),
                                        axisymmetric_stress_intensity_factor(*circle, gap.pressure));
      }
    solved.opening_at_centre       = model.opening_at_centre(u);
    solved.exact_opening_at_centre = exact.opening(0, 0);
    solved.gap_volume              = model.gap_volume(u);
    solved.exact_gap_volume        = exact.gap_volume();
    solved.n_cells                 = system.get_triangulation().n_global_active_cells();
    solved.n_dofs                  = system.get_dof_handler().n_dofs();
    solved.iterations              = model.last_solve().iterations;
    solved.relative_residual       = model.last_solve().relative_residual;
    solved.solver                  = system.solver_name();

    if (fields)
      {
        TimerOutput::Scope    scope(timer, "output");
        std::vector<Point<3>> points;
        for (const double phi : solved.angles)
          points.push_back(model.front().point(phi));
        FrontData data = {{"K_I exact", solved.exact_sifs}};
        for (unsigned int r = 0; r < solved.ring_radii.size(); ++r)
          data.emplace_back("K_I FE " + ring_name(solved.ring_radii[r]), solved.signed_sifs[r]);
        write_elliptical_fields(system, u, points, data, *fields);
      }
    solved.peak_memory = peak_memory(MPI_COMM_WORLD);
    return solved;
  }
} // namespace penny
