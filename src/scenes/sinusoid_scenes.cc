#include "scenes/sinusoid_scenes.h"

#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"
#include "fracture/periodic_array.h"
#include "fracture/periodic_gap_family.h"
#include "fracture/periodic_searches.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "scenes/scene_support.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    const Table::Format all_digits{16, false}, digits{10, true}, error_digits{3, true};

    // A number as a column name shows it: 0.2.
    std::string name_of(const double value)
    {
      std::ostringstream text;
      text << value;
      return text.str();
    }

    double gap_half_width(const Parameters &parameters)
    {
      return parameters.gap_and_load->gap_ratio * parameters.periodic_gap->wavelength;
    }

    BuecknerTension scene_load(const Parameters &parameters)
    {
      const auto &load = *parameters.gap_and_load;
      return {parameters.periodic_gap->wavelength, load.peak_tension, load.load_ratio * load.peak_tension};
    }

    // The searches' timer and family of models, on the last J-integral ring.
    // Every model lives on one rank; a search of its own shares its models
    // out over all ranks, and a sweep of independent searches gives each
    // rank its share of them, each search on its rank alone.
    struct PeriodicSearch
    {
      explicit PeriodicSearch(const Parameters &parameters)
          : timer(std::cout, TimerOutput::never, TimerOutput::wall_times),
            gaps(periodic_gap_model(parameters, parameters.periodic_gap->wavelength / 4),
                 parameters.periodic_gap->ring_radii.back(), timer)
      {
      }

      // FE solves of all ranks (collective).
      unsigned int n_solves() const { return Utilities::MPI::sum(gaps.n_solves(), MPI_COMM_WORLD); }

      TimerOutput       timer;
      PeriodicGapFamily gaps;
    };

    // The closing rows of every search: its cost.
    void add_cost(Table &summary, const PeriodicSearch &search)
    {
      summary.add_row({"FE solves", search.n_solves()});
      add_phase_times(summary, search.timer);
    }

    Table ring_table(const PeriodicGapResults &results)
    {
      Table        table({{"ring (min(c, lambda/2 - c))", digits},
                          {"J (J/m^2)", digits},
                          {"|K_I| FE (Pa m^1/2)", digits},
                          {"K_I signed FE (Pa m^1/2)", digits},
                          {"K_I exact (Pa m^1/2)", digits},
                          {"|K_I| relative error", error_digits},
                          {"signed K_I relative error", error_digits}});
      const double exact = results.exact_stress_intensity_factor;
      for (const auto &ring : results.rings)
        table.add_row({ring.radius, ring.energy_release_rate, ring.stress_intensity_factor,
                       ring.signed_stress_intensity_factor, exact,
                       relative_error(ring.stress_intensity_factor, std::abs(exact)),
                       relative_error(ring.signed_stress_intensity_factor, exact)});
      return table;
    }

    Table periodic_gap_summary(const Parameters &parameters, const PeriodicGapResults &results,
                               const TimerOutput &timer)
    {
      const auto &load    = *parameters.gap_and_load;
      Table       summary = Table::summary();
      const auto  row     = [&](const std::string &name, const double value, const Table::Format format) {
        summary.add_row({name, Table::Cell(value, format)});
      };
      row("c/lambda", load.gap_ratio, all_digits);
      row("contact half-width a/lambda", 0.5 - load.gap_ratio, all_digits);
      row("p_bar/p*", load.load_ratio, all_digits);
      row("depth D/lambda", parameters.periodic_gap->depth, all_digits);
      summary.add_row({"cells", results.n_cells});
      summary.add_row({"DoFs", results.n_dofs});
      summary.add_row({"degree", parameters.finite_element->degree});
      summary.add_row({"MPI ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
      summary.add_row({"solver", results.solver});
      row("relative residual", results.relative_residual, digits);
      row("K_I of cos(2 pi x/lambda) Pa FE (Pa m^1/2)", results.cosine_sif, digits);
      row("K_I of cos(2 pi x/lambda) Pa exact (Pa m^1/2)", results.exact_cosine_sif, digits);
      row("K_I of cos(2 pi x/lambda) Pa relative error",
          relative_error(results.cosine_sif, results.exact_cosine_sif), error_digits);
      row("K_I of 1 Pa uniform FE (Pa m^1/2)", results.uniform_sif, digits);
      row("K_I of 1 Pa uniform, Koiter (Pa m^1/2)", results.exact_uniform_sif, digits);
      row("K_I of 1 Pa uniform relative error",
          relative_error(results.uniform_sif, results.exact_uniform_sif), error_digits);
      add_phase_times(summary, timer);
      return summary;
    }
  } // namespace

  PeriodicGapModelParameters periodic_gap_model(const Parameters &parameters, const double c)
  {
    const auto                &model = *parameters.periodic_gap;
    PeriodicGapModelParameters gap{model.wavelength,
                                   model.depth * model.wavelength,
                                   c,
                                   model.tip_levels,
                                   model.grading_distance,
                                   parameters.material.value(),
                                   parameters.finite_element.value().degree,
                                   parameters.linear_solver.value()};
    gap.levels_per_degree = parameters.finite_element.value().levels_per_degree;
    return gap;
  }

  PeriodicGapResults solve_periodic_gap(const PeriodicGapModelParameters &model, const BuecknerTension &load,
                                        const std::vector<double> &ring_radii, TimerOutput &timer)
  {
    PeriodicGapModel         gap(model, timer);
    const auto               cosine    = BuecknerTension::unit_cosine(model.wavelength);
    const auto               uniform   = BuecknerTension::unit_uniform(model.wavelength);
    const DisplacementVector u         = gap.solve(load);
    double                   residual  = gap.get_system().last_solve().relative_residual;
    const DisplacementVector u_cosine  = gap.solve(cosine);
    residual                           = std::max(residual, gap.get_system().last_solve().relative_residual);
    const DisplacementVector u_uniform = gap.solve(uniform);
    residual                           = std::max(residual, gap.get_system().last_solve().relative_residual);

    PeriodicGapResults results;
    {
      TimerOutput::Scope                scope(timer, "J-integral");
      const double                      e_prime = model.material.plane_strain_modulus();
      const DomainIntegral<PlaneStrain> j_integral(gap.get_system(), e_prime);
      // All rings in one pass over the cells.
      std::vector<RingExtension<2>> rings;
      for (const double rho : ring_radii)
        rings.emplace_back(gap.crack_tip(), rho * model.tip_distance(), 1);
      std::vector<const CrackExtension<2> *> extensions;
      for (const auto &ring : rings)
        extensions.push_back(&ring);
      using Traction   = DomainIntegral<PlaneStrain>::Traction;
      const Traction t = load, t_cosine = cosine, t_uniform = uniform;
      const auto     K = j_integral.stress_intensities({{&u, &t}, {&u_cosine, &t_cosine}},
                                                       {&u_uniform, &t_uniform}, extensions, true);
      for (unsigned int i = 0; i < ring_radii.size(); ++i)
        {
          const double G = K.energy_release_rates[0][i];
          results.rings.push_back(
              {ring_radii[i], G, j_integral.stress_intensity_factor(G), K.signed_sifs[0][i]});
        }
      results.cosine_sif  = K.signed_sifs[1].back();
      results.uniform_sif = K.reference.back();
    }
    const double c = model.gap_half_width;
    results.exact_stress_intensity_factor =
        periodic_array::stress_intensity_factor(c, model.wavelength, load.peak_tension, load.mean_pressure);
    results.exact_cosine_sif  = periodic_array::stress_intensity_factor(c, model.wavelength, 1, 0);
    results.exact_uniform_sif = periodic_array::stress_intensity_factor(c, model.wavelength, 0, -1);
    results.n_cells           = gap.get_system().get_triangulation().n_global_active_cells();
    results.n_dofs            = gap.get_system().get_dof_handler().n_dofs();
    results.relative_residual = residual;
    results.solver            = gap.get_system().solver_name();
    return results;
  }

  PeriodicGapResults run_periodic_gap_scene(const Parameters &parameters, const ResultFolder &results,
                                            std::ostream &log)
  {
    TimerOutput              timer(log, TimerOutput::never, TimerOutput::wall_times);
    const PeriodicGapResults solved =
        solve_periodic_gap(periodic_gap_model(parameters, gap_half_width(parameters)), scene_load(parameters),
                           parameters.periodic_gap->ring_radii, timer);

    const Table rings   = ring_table(solved);
    const Table summary = periodic_gap_summary(parameters, solved, timer);
    log << "Periodic gap of Johnson's sinusoid (plane strain): K_I beside "
           "sqrt(lambda) [p* cos^2(pi c/lambda) - p_bar] sqrt(tan(pi c/lambda))\n";
    rings.print(log);
    if (solved.rings.back().signed_stress_intensity_factor < 0)
      log << "K_I < 0: the faces would interpenetrate; no open gap of this width carries this load.\n";
    log << '\n';
    summary.print(log);
    results.write_csv("rings.csv", rings);
    results.write_csv("summary.csv", summary);
    return solved;
  }

  // Each depth is a full solve of the scene's gap; the error of the last ring
  // against the closed form for the infinitely deep solid.
  std::vector<DepthStudyRow> run_periodic_gap_depth_scene(const Parameters   &parameters,
                                                          const ResultFolder &results, std::ostream &log)
  {
    TimerOutput timer(log, TimerOutput::never, TimerOutput::wall_times);
    Table       table({{"D/lambda", Table::Format{4, false}},
                       {"cells"},
                       {"DoFs"},
                       {"K_I signed FE (Pa m^1/2)", digits},
                       {"K_I exact (Pa m^1/2)", digits},
                       {"K_I relative error", error_digits},
                       {"K_cosine relative error", error_digits},
                       {"K_uniform relative error", error_digits}});
    // Each depth a model on one rank, the depths spread over the ranks:
    // (cells, DoFs, K_I signed, K_I exact, errors of K_I, K_cosine, K_uniform).
    const auto &depths = parameters.depth_study->depths;
    const auto  solved = spread_over_ranks(MPI_COMM_WORLD, depths.size(), [&](const unsigned int i) {
      PeriodicGapModelParameters model = periodic_gap_model(parameters, gap_half_width(parameters));
      model.depth                      = depths[i] * model.wavelength;
      model.communicator               = MPI_COMM_SELF;
      const PeriodicGapResults gap =
          solve_periodic_gap(model, scene_load(parameters), parameters.periodic_gap->ring_radii, timer);
      const double K = gap.rings.back().signed_stress_intensity_factor;
      return std::vector<double>{double(gap.n_cells),
                                 double(gap.n_dofs),
                                 K,
                                 gap.exact_stress_intensity_factor,
                                 relative_error(K, gap.exact_stress_intensity_factor),
                                 relative_error(gap.cosine_sif, gap.exact_cosine_sif),
                                 relative_error(gap.uniform_sif, gap.exact_uniform_sif)};
    });
    std::vector<DepthStudyRow> rows;
    for (unsigned int i = 0; i < depths.size(); ++i)
      {
        const auto &row = solved[i];
        rows.push_back({depths[i], static_cast<unsigned int>(row[1]), row[4], row[5], row[6]});
        table.add_row({depths[i], static_cast<unsigned int>(row[0]), static_cast<unsigned int>(row[1]),
                       row[2], row[3], row[4], row[5], row[6]});
      }
    log << "Truncation study: K_I of the periodic gap (c/lambda = " << parameters.gap_and_load->gap_ratio
        << ", p_bar/p* = " << parameters.gap_and_load->load_ratio
        << ", last ring) against the depth D of the solid, free at z = D\n";
    table.print(log);
    log << "wall time total (s): " << total_wall_time(timer) << '\n';
    results.write_csv("depth-study.csv", table);
    return rows;
  }

  CurveErrors run_westergaard_curve_scene(const Parameters &parameters, const ResultFolder &results,
                                          std::ostream &log)
  {
    PeriodicSearch     search(parameters);
    const double       lambda = parameters.periodic_gap->wavelength;
    const unsigned int n      = parameters.westergaard_curve->n_points;
    Table              table({{"p_bar/p*", digits},
                              {"a/lambda FE", all_digits},
                              {"a/lambda exact", all_digits},
                              {"a/lambda error", error_digits},
                              {"sin^2(pi a_FE/lambda)", all_digits},
                              {"p_bar/p* error", error_digits}});
    CurveErrors        worst{0, 0, 0};
    const auto         load_at = [&](const unsigned int i) { return (i + 1.) / (n + 1); };
    const auto         contact = spread_over_ranks(MPI_COMM_WORLD, n, [&](const unsigned int i) {
      return std::vector<double>{fe_westergaard_contact_half_width(search.gaps, load_at(i), MPI_COMM_SELF)};
    });
    for (unsigned int i = 0; i < n; ++i)
      {
        const double load        = load_at(i);
        const double fe_ratio    = contact[i][0] / lambda;
        const double exact       = periodic_array::westergaard_contact_ratio(load);
        const double curve       = periodic_array::johnson_load(fe_ratio, 0);
        worst.largest_load_error = std::max(worst.largest_load_error, std::abs(curve - load));
        worst.largest_contact_ratio_error =
            std::max(worst.largest_contact_ratio_error, std::abs(fe_ratio - exact));
        table.add_row({load, fe_ratio, exact, std::abs(fe_ratio - exact), curve, std::abs(curve - load)});
      }
    worst.n_solves = search.n_solves();
    results.write_csv("westergaard-curve.csv", table);
    log << "Adhesionless sinusoid: contact half-width a from FE roots of K_I = 0, beside "
           "p_bar/p* = sin^2(pi a/lambda)\n";
    table.print(log);
    Table summary = Table::summary();
    summary.add_row(
        {"largest |a/lambda FE - exact|", Table::Cell(worst.largest_contact_ratio_error, error_digits)});
    summary.add_row(
        {"largest |p_bar/p* - sin^2(pi a_FE/lambda)|", Table::Cell(worst.largest_load_error, error_digits)});
    add_cost(summary, search);
    summary.print(log);
    results.write_csv("westergaard-summary.csv", summary);
    return worst;
  }

  // The FE points (one solve of the two unit loads per a, shared by every
  // alpha), the closed-form curves on a fine grid and their extremes: the
  // tables of the Fig. 1 overlay (postprocess/plot_johnson_curves.py).
  CurveErrors run_johnson_curves_scene(const Parameters &parameters, const ResultFolder &results,
                                       std::ostream &log)
  {
    PeriodicSearch                                     search(parameters);
    const double                                       lambda = parameters.periodic_gap->wavelength;
    const auto                                        &curves = *parameters.johnson_curves;
    Table                                              points({{"alpha", Table::Format{4, false}},
                                                               {"a/lambda", Table::Format{6, false}},
                                                               {"p_bar/p* FE", all_digits},
                                                               {"p_bar/p* Johnson", all_digits},
                                                               {"absolute error", error_digits}});
    std::vector<double>                                worst(curves.alphas.size(), 0.);
    std::vector<std::vector<std::vector<Table::Cell>>> rows(curves.alphas.size());
    const auto ratio_at = [&](const unsigned int i) { return 0.5 * (i + 1) / (curves.n_points + 1); };
    std::vector<double> half_widths;
    for (unsigned int i = 0; i < curves.n_points; ++i)
      half_widths.push_back((0.5 - ratio_at(i)) * lambda);
    const std::vector<SinusoidUnitSifs> sifs = search.gaps.unit_load_sifs(half_widths, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < curves.n_points; ++i)
      {
        const double           ratio = ratio_at(i);
        const SinusoidUnitSifs K     = sifs[i];
        for (unsigned int k = 0; k < curves.alphas.size(); ++k)
          {
            const double fe    = fe_johnson_load(K, lambda, curves.alphas[k]);
            const double exact = periodic_array::johnson_load(ratio, curves.alphas[k]);
            worst[k]           = std::max(worst[k], std::abs(fe - exact));
            rows[k].push_back({curves.alphas[k], ratio, fe, exact, std::abs(fe - exact)});
          }
      }
    for (auto &curve : rows)
      for (auto &row : curve)
        points.add_row(std::move(row));
    results.write_csv("johnson-curves.csv", points);

    // 400 closed-form points in (0, 1/2) per alpha.
    std::vector<Table::Column> columns = {{"a/lambda"}};
    for (const double alpha : curves.alphas)
      columns.push_back({"p_bar/p* alpha=" + name_of(alpha)});
    Table closed_form(columns);
    for (unsigned int i = 1; i < 400; ++i)
      {
        std::vector<Table::Cell> row = {0.5 * i / 400};
        for (const double alpha : curves.alphas)
          row.emplace_back(periodic_array::johnson_load(0.5 * i / 400, alpha));
        closed_form.add_row(row);
      }
    results.write_csv("johnson-closed-form.csv", closed_form);

    Table extremes({{"alpha"},
                    {"jump into contact a/lambda"},
                    {"jump into contact p_bar/p*"},
                    {"pull-off a/lambda"},
                    {"pull-off p_bar/p*"}});
    for (const double alpha : curves.alphas)
      if (alpha < periodic_array::largest_alpha_with_extremes())
        {
          const auto jump = periodic_array::jump_into_contact(alpha);
          const auto pull = periodic_array::pull_off(alpha);
          extremes.add_row({alpha, jump.contact_ratio, jump.load_ratio, pull.contact_ratio, pull.load_ratio});
        }
    results.write_csv("johnson-extremes.csv", extremes);

    log << "Johnson's adhesive sinusoid from FE: p_bar/p* = [K_cosine - alpha sqrt(lambda)]/K_uniform at "
           "K_I = K_Ic, beside sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda))\n";
    Table summary = Table::summary();
    for (unsigned int k = 0; k < curves.alphas.size(); ++k)
      summary.add_row({"largest |p_bar/p* FE - Johnson|, alpha = " + name_of(curves.alphas[k]),
                       Table::Cell(worst[k], error_digits)});
    add_cost(summary, search);
    summary.print(log);
    log << "Extremes of the closed form (jump into contact, pull-off):\n";
    extremes.print(log);
    log << "Tables: " << results.directory().string() << "/johnson-curves.csv, johnson-closed-form.csv, "
        << "johnson-extremes.csv\n";
    return {*std::max_element(worst.begin(), worst.end()), 0, search.n_solves()};
  }

  JumpIntoContactResults run_jump_into_contact_scene(const Parameters   &parameters,
                                                     const ResultFolder &results, std::ostream &log)
  {
    PeriodicSearch           search(parameters);
    const double             lambda   = parameters.periodic_gap->wavelength;
    const FeCriticalAdhesion critical = fe_critical_alpha(search.gaps, MPI_COMM_WORLD);
    const double             contact  = critical.contact_half_width / lambda;
    // The definition checked: at the FE alpha_c the FE maximum of p_bar/p* is zero.
    const FeLoadExtremum at_critical = fe_jump_into_contact(search.gaps, critical.alpha, MPI_COMM_WORLD);

    Table summary = Table::summary();
    summary.add_row({"critical alpha FE", Table::Cell(critical.alpha, all_digits)});
    summary.add_row(
        {"critical alpha exact, 3^(3/4)/4", Table::Cell(periodic_array::critical_alpha, all_digits)});
    summary.add_row(
        {"relative error",
         Table::Cell(relative_error(critical.alpha, periodic_array::critical_alpha), error_digits)});
    summary.add_row({"a/lambda at alpha_c FE", Table::Cell(contact, all_digits)});
    summary.add_row(
        {"a/lambda at alpha_c exact", Table::Cell(periodic_array::critical_contact_ratio, all_digits)});
    summary.add_row({"max p_bar/p* FE at the FE alpha_c", Table::Cell(at_critical.load_ratio, error_digits)});
    const unsigned int critical_solves = search.n_solves();
    summary.add_row({"FE solves", critical_solves});
    log << "Critical alpha: the FE maximum over c of K_cosine(c)/sqrt(lambda), where the jump into contact "
           "reaches p_bar = 0 (spontaneous full contact at zero load)\n";
    summary.print(log);
    results.write_csv("critical-alpha.csv", summary);

    const auto &range = *parameters.jump_into_contact;
    Table       table({{"alpha", Table::Format{4, true}},
                       {"a/lambda FE", Table::Format{8, false}},
                       {"a/lambda Johnson", Table::Format{8, false}},
                       {"1 - p_bar_max/p* FE", digits},
                       {"1 - p_bar_max/p* Johnson", digits},
                       {"absolute error", error_digits},
                       {"5 (alpha/4)^(4/5)", digits},
                       {"Johnson/small-alpha law", Table::Format{6, false}}});
    double      worst   = 0;
    const auto  maximum = spread_over_ranks(MPI_COMM_WORLD, range.n_alphas, [&](const unsigned int i) {
      const FeLoadExtremum fe = fe_jump_into_contact(search.gaps, range.alpha(i), MPI_COMM_SELF);
      return std::vector<double>{fe.contact_half_width, fe.load_ratio};
    });
    for (unsigned int i = 0; i < range.n_alphas; ++i)
      {
        const double         alpha = range.alpha(i);
        const FeLoadExtremum fe{maximum[i][0], maximum[i][1]};
        const auto           exact = periodic_array::jump_into_contact(alpha);
        const double         law   = periodic_array::small_alpha_jump(alpha);
        worst                      = std::max(worst, std::abs(fe.load_ratio - exact.load_ratio));
        table.add_row({alpha, fe.contact_half_width / lambda, exact.contact_ratio, 1 - fe.load_ratio,
                       1 - exact.load_ratio, std::abs(fe.load_ratio - exact.load_ratio), law,
                       (1 - exact.load_ratio) / law});
      }
    results.write_csv("jump-into-contact.csv", table);
    log << "\nJump into full contact: 1 - p_bar_max/p* from the FE maximum over c of p_bar/p* at K_I = K_Ic, "
           "beside the maximum of Johnson's curve and the small-alpha law\n";
    table.print(log);
    Table cost = Table::summary();
    cost.add_row({"largest |p_bar_max/p* FE - Johnson|", Table::Cell(worst, error_digits)});
    add_cost(cost, search);
    cost.print(log);
    return {critical.alpha, contact, worst, search.n_solves()};
  }
} // namespace penny
