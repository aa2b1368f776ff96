#include "scenes/elliptical_scenes.h"

#include "fracture/elliptical_crack.h"
#include "fracture/elliptical_gap_family.h"
#include "fracture/front_stress_intensity.h"
#include "input/input_error.h"
#include "output/elliptical_fields.h"
#include "output/progress.h"
#include "output/table.h"
#include "scenes/penny_gap_scene.h"
#include "scenes/scene_support.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <tuple>

namespace penny
{
  using namespace dealii;

  namespace
  {
    const Table::Format digits{10, true}, error_digits{3, true}, seconds{3, false};

    // A ring radius as written in the parameter file, e.g. "0.2".
    std::string ring_name(const double rho)
    {
      std::ostringstream name;
      name << "ring " << rho << " b^2/a";
      return name.str();
    }

    // Sum over the ranks of the peak resident set size (MB).
    double peak_memory(MPI_Comm communicator)
    {
      Utilities::System::MemoryStats stats;
      Utilities::System::get_memory_stats(stats);
      return Utilities::MPI::sum(static_cast<double>(stats.VmHWM), communicator) / 1024;
    }

    // K_I of the circle of radius a under the pressure p from the axisymmetric
    // model at its defaults (degree, tip grading, rings), in a cylinder of
    // radius R and height H: the 3D model's circle checked against a second model.
    double axisymmetric_stress_intensity_factor(const Parameters &parameters)
    {
      using S                             = Section;
      const std::vector<Section> sections = {S::geometry,       S::material,      S::load,      S::mesh,
                                             S::finite_element, S::linear_solver, S::j_integral};
      dealii::ParameterHandler   prm;
      Parameters::declare(prm, {"penny-gap"}, "", sections);
      Parameters  penny             = Parameters::parse(prm, sections);
      const auto &gap               = *parameters.elliptical_gap;
      const auto &model             = *parameters.elliptical_model;
      penny.material                = parameters.material;
      penny.geometry->gap_radius    = gap.semi_axis_a;
      penny.geometry->domain_radius = model.box_width * gap.semi_axis_a;
      penny.geometry->domain_height = model.box_height * gap.semi_axis_a;
      penny.load->type              = LoadParameters::Type::uniform;
      penny.load->peak_tension      = gap.pressure;
      TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
      return solve_penny_gap(penny_gap_model(penny), *penny.load, penny.j_integral->ring_radii, timer)
          .rings.back()
          .signed_stress_intensity_factor;
    }

    Table front_table(const EllipticalGapParameters &gap, const EllipticalGapResults &solved)
    {
      std::vector<Table::Column> columns = {{"phi (rad)", Table::Format{6, false}},
                                            {"x (m)", Table::Format{6, false}},
                                            {"y (m)", Table::Format{6, false}},
                                            {"K_I exact (Pa m^1/2)", digits}};
      if (!solved.axisymmetric_sifs.empty())
        {
          columns.push_back({"K_I axisymmetric FE (Pa m^1/2)", digits});
          columns.push_back({"relative difference 3D - axisymmetric, last ring", error_digits});
        }
      for (const double rho : solved.ring_radii)
        {
          const std::string ring = ring_name(rho);
          columns.push_back({"K_I signed FE " + ring + " (Pa m^1/2)", digits});
          columns.push_back({"relative error " + ring, error_digits});
        }
      Table        table(columns);
      const double a = gap.semi_axis_a, b = gap.aspect_ratio * a;
      for (unsigned int i = 0; i < solved.angles.size(); ++i)
        {
          const double             phi = solved.angles[i];
          std::vector<Table::Cell> row = {phi, a * std::cos(phi), b * std::sin(phi), solved.exact_sifs[i]};
          if (!solved.axisymmetric_sifs.empty())
            {
              row.emplace_back(solved.axisymmetric_sifs[i]);
              row.emplace_back((solved.signed_sifs.back()[i] - solved.axisymmetric_sifs[i]) /
                               solved.axisymmetric_sifs[i]);
            }
          for (const auto &ring : solved.signed_sifs)
            {
              row.emplace_back(ring[i]);
              row.emplace_back(relative_error(ring[i], solved.exact_sifs[i]));
            }
          table.add_row(row);
        }
      return table;
    }

    Table summary_table(const Parameters &parameters, const EllipticalGapResults &solved,
                        const TimerOutput &timer)
    {
      const auto &gap     = *parameters.elliptical_gap;
      Table       summary = Table::summary();
      const auto  row     = [&](const std::string &name, const double value, const Table::Format format) {
        summary.add_row({name, Table::Cell(value, format)});
      };
      row("b/a", gap.aspect_ratio, Table::Format{6, false});
      summary.add_row({"cells", solved.n_cells});
      summary.add_row({"DoFs", solved.n_dofs});
      summary.add_row({"degree", parameters.finite_element->degree});
      summary.add_row({"MPI ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
      summary.add_row({"solver", solved.solver});
      summary.add_row({"CG iterations", solved.iterations});
      row("relative residual", solved.relative_residual, digits);
      for (unsigned int r = 0; r < solved.ring_radii.size(); ++r)
        {
          double worst = 0;
          for (unsigned int i = 0; i < solved.angles.size(); ++i)
            worst = std::max(worst, relative_error(solved.signed_sifs[r][i], solved.exact_sifs[i]));
          row("largest K_I relative error, " + ring_name(solved.ring_radii[r]), worst, error_digits);
        }
      row("w(0) FE (m)", solved.opening_at_centre, digits);
      row("w(0) exact (m)", solved.exact_opening_at_centre, digits);
      row("w(0) relative error", relative_error(solved.opening_at_centre, solved.exact_opening_at_centre),
          error_digits);
      row("gap volume relative error", relative_error(solved.gap_volume, solved.exact_gap_volume),
          error_digits);
      row("peak memory, all ranks (MB)", solved.peak_memory, Table::Format{5, false});
      add_phase_times(summary, timer);
      return summary;
    }
  } // namespace

  EllipticalGapModelParameters elliptical_gap_model(const Parameters &parameters, const double a,
                                                    const double b)
  {
    const auto                 &model = *parameters.elliptical_model;
    EllipticalGapMeshParameters mesh;
    mesh.semi_axis_a        = a;
    mesh.semi_axis_b        = b;
    mesh.domain_width       = model.box_width;
    mesh.domain_height      = model.box_height;
    mesh.cells_along_front  = model.cells_along_front;
    mesh.cells_around_front = model.sectors;
    mesh.front_cell_size    = model.front_cell_size;
    mesh.ring_ratio         = model.ring_ratio;
    return {mesh, model.global_refinements, *parameters.material, parameters.finite_element->degree,
            *parameters.linear_solver};
  }

  EllipticalGapResults run_elliptical_gap_scene(const Parameters &parameters, const ResultFolder &results,
                                                std::ostream &log)
  {
    const auto &gap = *parameters.elliptical_gap;
    TimerOutput timer(log, TimerOutput::never, TimerOutput::wall_times);
    log << "Building the quarter model of the gap b/a = " << gap.aspect_ratio << "...\n" << std::flush;
    EllipticalGapModel model(
        elliptical_gap_model(parameters, gap.semi_axis_a, gap.aspect_ratio * gap.semi_axis_a), timer);
    const auto &system = model.get_system();
    log << system.get_triangulation().n_global_active_cells() << " cells, "
        << system.get_dof_handler().n_dofs() << " DoFs, " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
        << " MPI rank(s); solving...\n"
        << std::flush;
    const double                       p        = gap.pressure;
    const EllipticalGapModel::Traction pressure = [p](const Point<3> &) { return p; };
    const DisplacementVector           u        = model.solve(pressure);

    EllipticalGapResults solved;
    solved.angles     = front_point_angles(gap.front_points);
    solved.ring_radii = parameters.elliptical_model->ring_radii;
    {
      TimerOutput::Scope scope(timer, "J-integral");
      log << "K_I at " << solved.angles.size() << " front points on " << solved.ring_radii.size()
          << " ring(s)...\n"
          << std::flush;
      // The signed K_I takes the unit pressure as reference; by linearity its
      // displacement is u/p, no second solve.
      DisplacementVector u_unit = u;
      u_unit /= p;
      const EllipticalGapModel::Traction unit = [](const Point<3> &) { return 1.; };
      const FrontStressIntensity front(model, solved.angles, parameters.elliptical_model->weight_half_width,
                                       solved.ring_radii);
      solved.signed_sifs = front.signed_sifs({{&u, &pressure}}, u_unit, unit).front();
    }
    const double               e_prime = model.material().plane_strain_modulus();
    const GreenSneddonSolution exact(model.front().semi_axis_a(), model.front().semi_axis_b(), p, e_prime);
    solved.largest_error = 0;
    for (const double phi : solved.angles)
      solved.exact_sifs.push_back(exact.stress_intensity_factor(phi));
    for (const auto &ring : solved.signed_sifs)
      for (unsigned int i = 0; i < ring.size(); ++i)
        solved.largest_error = std::max(solved.largest_error, relative_error(ring[i], solved.exact_sifs[i]));
    if (gap.aspect_ratio == 1)
      {
        TimerOutput::Scope scope(timer, "axisymmetric model");
        log << "The circle: K_I of the axisymmetric model...\n" << std::flush;
        solved.axisymmetric_sifs.assign(solved.angles.size(),
                                        axisymmetric_stress_intensity_factor(parameters));
      }
    solved.opening_at_centre       = model.opening_at_centre(u);
    solved.exact_opening_at_centre = exact.opening(0, 0);
    solved.gap_volume              = model.gap_volume(u);
    solved.exact_gap_volume        = exact.gap_volume();
    solved.n_cells                 = system.get_triangulation().n_global_active_cells();
    solved.n_dofs                  = system.get_dof_handler().n_dofs();
    solved.iterations              = system.last_solve().iterations;
    solved.relative_residual       = system.last_solve().relative_residual;
    solved.solver                  = system.solver_name();

    if (parameters.fields && parameters.fields->write_fields)
      {
        TimerOutput::Scope    scope(timer, "output");
        std::vector<Point<3>> points;
        for (const double phi : solved.angles)
          points.push_back(model.front().point(phi));
        FrontData data = {{"K_I exact", solved.exact_sifs}};
        for (unsigned int r = 0; r < solved.ring_radii.size(); ++r)
          data.emplace_back("K_I FE " + ring_name(solved.ring_radii[r]), solved.signed_sifs[r]);
        write_elliptical_fields(system, u, points, data, results);
      }
    solved.wall_time   = total_wall_time(timer);
    solved.peak_memory = peak_memory(MPI_COMM_WORLD);

    const Table front   = front_table(gap, solved);
    const Table summary = summary_table(parameters, solved, timer);
    log << "\nElliptical gap b/a = " << gap.aspect_ratio
        << " under uniform pressure: K_I(phi) beside p sqrt(pi b)/E(k) (sin^2 phi + (b/a)^2 cos^2 "
           "phi)^(1/4)\n";
    front.print(log);
    log << '\n';
    summary.print(log);
    results.write_csv("front.csv", front);
    results.write_csv("summary.csv", summary);
    return solved;
  }
} // namespace penny

namespace penny
{
  namespace
  {
    const Table::Format ratio_digits{8, false}, estimate_digits{2, true};

    // The searches and the front of the gaps found, by one method: one call
    // of `sifs` per shape found, along the front from phi = 0 to pi/2.
    SummitGaps summit_gaps(const EllipticalGapSifs &sifs, const double rho, const std::vector<double> &angles)
    {
      SummitGaps   gaps;
      const double s0     = adhesionless_summit_shape(sifs, rho);
      const auto   front0 = sifs(s0, angles);
      gaps.adhesionless   = adhesionless_gap(s0, {{front0.front(), front0.back()}});
      const double s1     = adhesive_summit_shape(sifs, rho, s0);
      const auto   front1 = sifs(s1, angles);
      gaps.adhesive       = adhesive_gap(s1, rho, {{front1.front(), front1.back()}});
      for (const auto &K : front0)
        gaps.adhesionless_front.push_back(gaps.adhesionless.relative_sif(K));
      for (const auto &K : front1)
        gaps.adhesive_front.push_back(gaps.adhesive.relative_sif(K));
      return gaps;
    }

    double largest_magnitude(const std::vector<double> &values)
    {
      double largest = 0;
      for (const double v : values)
        largest = std::max(largest, std::abs(v));
      return largest;
    }

    double spread(const std::vector<double> &values)
    {
      return *std::max_element(values.begin(), values.end()) -
             *std::min_element(values.begin(), values.end());
    }

    // A quantity of the gaps: its FE value, the closed form, the FE error and
    // the estimate |FE - coarse FE|, in four columns.
    struct Quantity
    {
      std::string                               name;
      std::function<double(const SummitGaps &)> of;
    };

    Table quantity_table(const std::vector<Quantity> &quantities, const EllipticalSummitsResults &solved)
    {
      std::vector<Table::Column> columns = {{"Ay/Ax", Table::Format{4, false}}};
      for (const auto &q : quantities)
        {
          columns.push_back({q.name + " FE", ratio_digits});
          columns.push_back({q.name + " exact", ratio_digits});
          columns.push_back({q.name + " FE error", estimate_digits});
          columns.push_back({q.name + " FE error estimate", estimate_digits});
        }
      Table table(columns);
      for (unsigned int k = 0; k < solved.tension_aspect_ratios.size(); ++k)
        {
          std::vector<Table::Cell> row = {solved.tension_aspect_ratios[k]};
          for (const auto &q : quantities)
            {
              const double fe = q.of(solved.fe[k]), exact = q.of(solved.exact[k]);
              row.emplace_back(fe);
              row.emplace_back(exact);
              row.emplace_back(fe - exact);
              row.emplace_back(std::abs(fe - q.of(solved.coarse_fe[k])));
            }
          table.add_row(row);
        }
      return table;
    }

    Table summit_front_table(const EllipticalSummitsResults &solved)
    {
      Table table({{"Ay/Ax", Table::Format{4, false}},
                   {"phi (rad)", Table::Format{6, false}},
                   {"adhesionless K_I/(P K_uniform) FE", estimate_digits},
                   {"adhesionless K_I/(P K_uniform) exact", estimate_digits},
                   {"adhesive K_I/K_Ic FE", ratio_digits},
                   {"adhesive K_I/K_Ic exact", ratio_digits}});
      for (unsigned int k = 0; k < solved.tension_aspect_ratios.size(); ++k)
        for (unsigned int i = 0; i < solved.angles.size(); ++i)
          table.add_row({solved.tension_aspect_ratios[k], solved.angles[i],
                         solved.fe[k].adhesionless_front[i], solved.exact[k].adhesionless_front[i],
                         solved.fe[k].adhesive_front[i], solved.exact[k].adhesive_front[i]});
      return table;
    }
  } // namespace

  EllipticalSummitsResults run_elliptical_summits_scene(const Parameters   &parameters,
                                                        const ResultFolder &results, std::ostream &log)
  {
    const auto &summits = *parameters.elliptical_summits;
    const auto &model   = *parameters.elliptical_model;
    // The coarse model halves the cells along and around the front.
    require(model.cells_along_front % 4 == 0, "Elliptical model/Cells along front", model.cells_along_front,
            "{4, 8, 12, ..., 256} for this scene (its coarse model halves it)");
    require(model.sectors % 8 == 0, "Elliptical model/Sectors around front", model.sectors,
            "{8, 16, 24, ..., 64} for this scene (its coarse model halves it)");
    require(
        model.weight_half_width <= (model.cells_along_front / 2) << model.global_refinements,
        "Elliptical model/Front weight half-width", model.weight_half_width,
        "(0, Cells along front x 2^Global refinements/2] for this scene (its coarse model halves the cells)");

    TimerOutput                  timer(log, TimerOutput::never, TimerOutput::wall_times);
    EllipticalGapModelParameters fine   = elliptical_gap_model(parameters, 1, 1);
    EllipticalGapModelParameters coarse = fine;
    coarse.mesh.cells_along_front /= 2;
    coarse.mesh.cells_around_front /= 2;
    const double ring = model.ring_radii.back();

    EllipticalSummitsResults solved;
    solved.tension_aspect_ratios = summits.tension_aspect_ratios;
    solved.angles                = front_point_angles(summits.front_points);
    solved.fe_models             = 0;
    {
      // First, as it takes milliseconds: a summit the closed form cannot answer stops the scene here.
      TimerOutput::Scope scope(timer, "closed form");
      for (const double ratio : solved.tension_aspect_ratios)
        solved.exact.push_back(summit_gaps(galin_unit_load_sifs, ratio, solved.angles));
    }
    Progress progress(log, "3D models");
    for (const auto &[discretisation, name, gaps] :
         {std::tuple{&fine, "FE", &solved.fe}, std::tuple{&coarse, "coarse FE", &solved.coarse_fe}})
      {
        EllipticalGapFamily family(*discretisation, model.weight_half_width, ring, timer);
        double              rho = 0;
        family.observe([&](const double s) {
          std::ostringstream state;
          state << name << ", Ay/Ax = " << rho << ": b/a = " << s;
          progress.step(state.str());
        });
        const EllipticalGapSifs sifs = [&family](const double s, const std::vector<double> &angles) {
          return family.unit_load_sifs(s, angles);
        };
        for (const double ratio : solved.tension_aspect_ratios)
          {
            rho = ratio;
            gaps->push_back(summit_gaps(sifs, ratio, solved.angles));
          }
        solved.fe_models += family.n_models();
      }

    const auto adhesionless = [](const auto member) {
      return [member](const SummitGaps &g) { return g.adhesionless.*member; };
    };
    const auto adhesive = [](const auto member) {
      return [member](const SummitGaps &g) { return g.adhesive.*member; };
    };
    const Table adhesionless_table =
        quantity_table({{"b/a", adhesionless(&AdhesionlessSummitGap::aspect_ratio)},
                        {"a/Ax", adhesionless(&AdhesionlessSummitGap::a_over_Ax)},
                        {"b/Ay", adhesionless(&AdhesionlessSummitGap::b_over_Ay)},
                        {"gap area/tension area", adhesionless(&AdhesionlessSummitGap::area_ratio)},
                        {"largest |K_I|/(P K_uniform) on the front",
                         [](const SummitGaps &g) { return largest_magnitude(g.adhesionless_front); }}},
                       solved);
    const Table adhesive_table = quantity_table(
        {{"b/a", adhesive(&AdhesiveSummitGap::aspect_ratio)},
         {"a/(R_p K_Ic)^(2/5)", adhesive(&AdhesiveSummitGap::a)},
         {"psi", adhesive(&AdhesiveSummitGap::tension)},
         {"spread of K_I/K_Ic on the front", [](const SummitGaps &g) { return spread(g.adhesive_front); }}},
        solved);
    const Table front = summit_front_table(solved);

    solved.largest_error = 0;
    for (unsigned int k = 0; k < solved.tension_aspect_ratios.size(); ++k)
      {
        const SummitGaps &fe = solved.fe[k], &exact = solved.exact[k];
        solved.largest_error =
            std::max({solved.largest_error,
                      relative_error(fe.adhesionless.aspect_ratio, exact.adhesionless.aspect_ratio),
                      relative_error(fe.adhesionless.area_ratio, exact.adhesionless.area_ratio),
                      relative_error(fe.adhesive.aspect_ratio, exact.adhesive.aspect_ratio),
                      relative_error(fe.adhesive.tension, exact.adhesive.tension)});
      }
    Table summary = Table::summary();
    summary.add_row({"3D models solved (3 loads each)", solved.fe_models});
    summary.add_row({"MPI ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
    summary.add_row({"largest relative error of b/a, the area ratio and psi",
                     Table::Cell(solved.largest_error, error_digits)});
    add_phase_times(summary, timer);

    log << "\nWithout adhesion: the gap with K_I = 0 at phi = 0 and pi/2 under P (1 - x^2/Ax^2 - y^2/Ay^2)\n";
    adhesionless_table.print(log);
    log << "\nWith adhesion (K_Ic = 1, R_p = (R_1 R_2)^(1/2) = 1): the least P with K_I = K_Ic at phi = 0 "
           "and "
           "pi/2, psi = P/(K_Ic^4/R_p)^(1/5)\n";
    adhesive_table.print(log);
    log << '\n';
    summary.print(log);
    results.write_csv("adhesionless.csv", adhesionless_table);
    results.write_csv("adhesive.csv", adhesive_table);
    results.write_csv("front.csv", front);
    results.write_csv("summary.csv", summary);
    return solved;
  }
} // namespace penny
