// measured-analysis: the paper's statistical layer on a measured surface,
// beside its Gaussian twins (doc/measured.md, "The paper's layer on a measured
// surface"). The prepared map, taken as one period, and its twins (its
// Fourier amplitudes with random phases, spread over the ranks): the summits of the tension -p_fc (density,
// mean curvature) beside Kac-Rice's expectation from the map's moments, and
// at each load the adhesionless non-contact area of the full boundary-element
// solution beside the layer's laws: the isolated-gap law over the sampled
// summits, over Kac-Rice's, and the paper's linear law in both conventions.
// What differs between the map and its twin is due to the map's heights not
// being Gaussian (the power spectra are the same). No verdict.
#include "contact/half_space.h"
#include "output/table.h"
#include "parallel/spread_over_ranks.h"
#include "problems/contact_solver.h"
#include "problems/measured_surface.h"
#include "problems/random_surfaces.h"
#include "problems/solid.h"
#include "scenes/scene.h"
#include "statistics/contact_area.h"
#include "statistics/random_field.h"
#include "statistics/summit_statistics.h"

#include <deal.II/base/mpi.h>

#include <cmath>

namespace penny
{
  namespace
  {
    // Per surface: sqrt(V), the summits' density and mean curvature, then per
    // load the BEM's A_nc/A_0 and the isolated-gap law over the summits.
    std::vector<double> analyse(const FourierTransform &transform, const GridField &heights,
                                const double E_star, const std::vector<double> &loads,
                                const ContactSolverControl &control)
    {
      const TensionSummits   tension = tension_summits(transform, heights, E_star);
      std::vector<double>    row     = {std::sqrt(tension.moments.m0),
                                        tension.summits.size() / transform.grid().area(), tension.mean_curvature};
      const HalfSpaceContact contact(transform, heights, E_star);
      for (const LoadStep &step : load_sweep(contact, loads, control))
        row.push_back(step.noncontact_fraction);
      for (const double load : loads)
        row.push_back(sampled_gap_area(tension.summits, transform.grid().area(), load, 0));
      return row;
    }

    struct MeasuredAnalysisScene : Scene
    {
      void inputs(Sections &sections) override
      {
        measured_surface_section(sections, input);
        material_section(sections, material);
        contact_solver_section(sections, control, 1e-8);
      }

      void entries(Entries &entries) override
      {
        entries.increasing_numbers("Mean pressures", mean_pressures, {0.5, 1, 1.5, 2, 3}, 1,
                                   interval("(]", 0, 100, "sqrt(V)"),
                                   "p_bar/sqrt(V), V = <p_fc^2> of the prepared map taken as one period. "
                                   "Units: sqrt(V).");
        entries.integer(
            "Twin realisations", n_twins, 8u, 2u, 10000u,
            "Gaussian twins of the map (its Fourier amplitudes, random phases), spread over the ranks. "
            "Units: none.");
        entries.integer("Seed", seed, 1u, 0u, 4294967295u, "The twins' random seed. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        const Topography       topography = prepared_topography(input, log);
        const double           E_star     = material.plane_strain_modulus();
        const FourierTransform transform(topography.grid);

        // The map's moments set the scale V and the expectations.
        const GridField    pressure = full_contact_pressure(transform, topography.heights, E_star);
        const FieldMoments moments  = sampled_moments(transform, pressure);
        check_summit_spectrum(moments, "Measured surface/File = " + in_quotes(input.file));
        const double        sqrt_V = std::sqrt(moments.m0);
        std::vector<double> loads;
        for (const double p : mean_pressures)
          loads.push_back(p * sqrt_V);

        const std::vector<double> map = analyse(transform, topography.heights, E_star, loads, control);
        const auto twins              = spread_over_ranks(MPI_COMM_WORLD, n_twins, [&](const unsigned int k) {
          return analyse(transform, gaussian_twin(transform, topography.heights, realisation_seed(seed, k)),
                                      E_star, loads, control);
        });

        // The summits.
        const ExpectedSummits expected = expected_summits(moments);
        Table                 summits({"surface", "sqrt(V) (Pa)", "summits per area (1/m^2)", "std error",
                                       "mean summit curvature (Pa/m^2)", "std error"});
        summits.add_row({"measured map", map[0], map[1], "one map", map[2], "one map"});
        const Estimate twin_V = mean_over(twins, 0), twin_density = mean_over(twins, 1),
                       twin_curvature = mean_over(twins, 2);
        summits.add_row({"Gaussian twins", twin_V.value, twin_density.value, twin_density.standard_error,
                         twin_curvature.value, twin_curvature.standard_error});
        summits.add_row({"Kac-Rice from the map's moments", sqrt_V, expected.density, "expectation",
                         expected.mean_curvature, "expectation"});
        publish(summits, "measured-analysis-summits.csv", results, log,
                "Summits of the tension -p_fc of the map and of " + std::to_string(n_twins) +
                    " Gaussian twins (its Fourier amplitudes, random phases)");

        // The areas: the BEM and the layer's laws.
        const SpectralMoments continuum = spectral_moments(isotropic_spectrum(topography, false));
        GapPopulation         laws[2];
        double                law_sqrt_V[2];
        for (const Convention convention : {Convention::paper, Convention::consistent})
          {
            const PressureSummits s     = pressure_summits(continuum, E_star, convention);
            laws[int(convention)]       = surface_population(s, 0, convention);
            law_sqrt_V[int(convention)] = std::sqrt(s.variance);
          }
        const std::size_t n_loads = loads.size();
        Table             areas({"p_bar/sqrtV",
                                 {"A_nc/A_0 BEM map", {4, true}},
                                 {"BEM twins", {4, true}},
                                 {"std error", {2, true}},
                                 {"isolated gaps map summits", {4, true}},
                                 {"isolated gaps twin summits", {4, true}},
                                 {"isolated gaps Kac-Rice", {4, true}},
                                 {"linear law paper", {4, true}},
                                 {"linear law consistent", {4, true}},
                                 {"BEM map/twins", {3}}});
        for (std::size_t l = 0; l < n_loads; ++l)
          {
            const Estimate bem = mean_over(twins, 3 + l), isolated = mean_over(twins, 3 + n_loads + l);
            areas.add_row({mean_pressures[l], map[3 + l], bem.value, bem.standard_error, map[3 + n_loads + l],
                           isolated.value, expected_gap_area(moments, loads[l]),
                           linear_law_noncontact_area(laws[0], loads[l] / law_sqrt_V[0]),
                           linear_law_noncontact_area(laws[1], loads[l] / law_sqrt_V[1]),
                           bem.value > 0 ? Table::Cell(map[3 + l] / bem.value, Table::Format{3})
                                         : Table::Cell("twins: no gaps")});
          }
        log << '\n';
        publish(
            areas, "measured-analysis.csv", results, log,
            "Adhesionless non-contact area: the map and its twins (BEM, periodic) beside the layer's laws");
        log << "Tables: " << results.directory().string()
            << "/measured-analysis.csv, measured-analysis-summits.csv\n";
        return {};
      }

      MeasuredSurfaceInput input;
      MaterialParameters   material;
      ContactSolverControl control;
      std::vector<double>  mean_pressures; // p_bar/sqrt(V)
      unsigned int         n_twins;
      unsigned int         seed;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      MeasuredAnalysisScene, "measured-analysis", "Measured analysis",
      "the paper's statistical layer on a measured surface beside its Gaussian twins: summits, "
      "and the adhesionless area-load law against the full solution",
      "")
} // namespace penny
