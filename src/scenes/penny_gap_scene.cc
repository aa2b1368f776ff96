#include "scenes/penny_gap_scene.h"

#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"
#include "output/field_output.h"
#include "output/table.h"
#include "scenes/scene_support.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace penny
{
  using namespace dealii;

  namespace
  {
    Table ring_table(const PennySceneResults &results)
    {
      const Table::Format digits{10, true};
      Table               table({{"ring (c)", digits},
                                 {"J (J/m^2)", digits},
                                 {"|K_I| FE (Pa m^1/2)", digits},
                                 {"K_I signed FE (Pa m^1/2)", digits},
                                 {"K_I exact (Pa m^1/2)", digits},
                                 {"|K_I| relative error", digits}});
      const double        exact = results.exact_stress_intensity_factor.value;
      for (const auto &ring : results.rings)
        table.add_row({ring.radius, ring.energy_release_rate, ring.stress_intensity_factor,
                       ring.signed_stress_intensity_factor, exact,
                       relative_error(ring.stress_intensity_factor, std::abs(exact))});
      return table;
    }

    // Where a closed form comes from a quadrature whose error estimate exceeds
    // the FE's difference to it, that difference says only that the FE is
    // right to within the estimate.
    std::string closed_form_verdict(const PennySceneResults &results)
    {
      double ring_error = 0;
      for (const auto &ring : results.rings)
        ring_error =
            std::max(ring_error, relative_error(ring.stress_intensity_factor,
                                                std::abs(results.exact_stress_intensity_factor.value)));
      const std::vector<std::tuple<std::string, ClosedForm, double>> quantities = {
          {"K_I", results.exact_stress_intensity_factor, ring_error},
          {"w(0)", results.exact_opening_at_centre,
           relative_error(results.opening_at_centre, results.exact_opening_at_centre.value)},
          {"gap volume", results.exact_gap_volume,
           relative_error(results.gap_volume, results.exact_gap_volume.value)}};
      if (std::all_of(quantities.begin(), quantities.end(),
                      [](const auto &q) { return std::get<1>(q).exact; }))
        return "exact formulas";
      std::string limited;
      for (const auto &[name, closed_form, fe_error] : quantities)
        if (!(closed_form.relative_error_estimate() < fe_error))
          limited += (limited.empty() ? "" : ", ") + name;
      if (limited.empty())
        return "quadrature; every error estimate is below the FE's difference to it";
      return "quadrature error estimate above the FE's difference for " + limited +
             ": there the FE is verified only to the estimate";
    }

    Table summary_table(const PennySceneResults &results, const unsigned int degree, const TimerOutput &timer)
    {
      Table table = Table::summary();
      table.add_row({"cells", results.n_cells});
      table.add_row({"DoFs", results.n_dofs});
      table.add_row({"degree", degree});
      table.add_row({"MPI ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)});
      table.add_row({"solver", results.solver});
      table.add_row({"relative residual", Table::Cell(results.relative_residual, Table::Format{10, true})});
      const auto row = [&](const std::string &name, const double value) {
        table.add_row({name, Table::Cell(value, Table::Format{10, true})});
      };
      const auto estimate = [&](const std::string &name, const ClosedForm &closed_form) {
        table.add_row({name + " exact: quadrature error estimate (relative)",
                       Table::Cell(closed_form.relative_error_estimate(), Table::Format{2, true})});
      };
      row("opening w(0) FE (m)", results.opening_at_centre);
      row("opening w(0) exact (m)", results.exact_opening_at_centre.value);
      row("opening relative error",
          relative_error(results.opening_at_centre, results.exact_opening_at_centre.value));
      row("gap volume FE (m^3)", results.gap_volume);
      row("gap volume exact (m^3)", results.exact_gap_volume.value);
      row("volume relative error", relative_error(results.gap_volume, results.exact_gap_volume.value));
      estimate("K_I", results.exact_stress_intensity_factor);
      estimate("w(0)", results.exact_opening_at_centre);
      estimate("gap volume", results.exact_gap_volume);
      table.add_row({"closed forms", closed_form_verdict(results)});
      add_phase_times(table, timer);
      return table;
    }
  } // namespace

  PennySceneResults measure_penny_gap(PennyGapModel &model, const FaceLoad &load,
                                      const std::vector<double> &ring_radii, TimerOutput &timer,
                                      const ResultFolder *fields)
  {
    const double             c         = model.gap_radius();
    const DisplacementVector u         = model.solve(load);
    const FaceLoad           reference = FaceLoad::unit_uniform();
    const double             residual  = model.get_system().last_solve().relative_residual;
    const DisplacementVector u_ref     = model.solve(reference);

    PennySceneResults results;
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
    results.relative_residual  = std::max(residual, model.get_system().last_solve().relative_residual);
    results.condition_estimate = model.get_system().last_solve().condition_estimate;
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

  PennySceneResults solve_penny_gap(const PennyGapModelParameters &model, const LoadParameters &load,
                                    const std::vector<double> &ring_radii, TimerOutput &timer)
  {
    PennyGapModel gap(model, timer);
    return measure_penny_gap(gap, FaceLoad(load, model.geometry.gap_radius), ring_radii, timer);
  }

  PennySceneResults run_penny_gap_scene(const Parameters &parameters, const ResultFolder &results,
                                        std::ostream &log)
  {
    TimerOutput             timer(log, TimerOutput::never, TimerOutput::wall_times);
    const auto              model = penny_gap_model(parameters);
    PennyGapModel           gap(model, timer);
    const PennySceneResults solved = measure_penny_gap(
        gap, FaceLoad(parameters.load.value(), model.geometry.gap_radius), parameters.j_integral->ring_radii,
        timer, parameters.fields->write_fields ? &results : nullptr);

    const Table rings   = ring_table(solved);
    const Table summary = summary_table(solved, model.degree, timer);
    rings.print(log);
    if (solved.rings.front().signed_stress_intensity_factor < 0)
      log << "K_I < 0: the faces would interpenetrate; no open gap of this radius carries this load.\n";
    log << '\n';
    summary.print(log);
    results.write_csv("rings.csv", rings);
    results.write_csv("summary.csv", summary);
    return solved;
  }
} // namespace penny
