#include "problems/periodic_gap.h"

#include "closed_forms/periodic_array.h"
#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"
#include "output/field_output.h"
#include "output/phase_times.h"
#include "problems/fe_sections.h"
#include "problems/solid.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <iostream>
#include <limits>

namespace penny
{
  using namespace dealii;

  void PeriodicGapInput::sections(Sections &sections, const bool read_depth)
  {
    elastic_model_sections(sections, model, ModelDimension::two);
    sections.subsection("Periodic gap", [&](Entries &entries) {
      // Bounded so that no product the solver forms overflows, and the mesh,
      // whose coarse cells are at most lambda/4 wide, stays small.
      entries.number(
          "Wavelength lambda", model.wavelength, 1, magnitude("m"),
          "Period of the sinusoid and of its array of gaps; the model is the half period 0 <= x <= "
          "lambda/2. Units: m.");
      double depth = 0;
      if (read_depth)
        {
          entries.number(
              "Depth D", depth, 3, interval("[]", smallest_depth, 100, "lambda"),
              "Depth of the solid from the crack plane z = 0 to its far side z = D, which is free (the "
              "perturbation of the gaps decays like exp(-2 pi z/lambda)). Units: lambda.");
          model.depth = depth * model.wavelength;
        }
      entries.integer("Tip refinement levels", model.tip_levels, 24u, 0u, 40u,
                      "Cells at the tip are min(c, lambda/2 - c)/2^levels wide. Units: none.");
      entries.number("Grading distance", model.grading_distance, 3, interval("[]", 0.5, 10),
                     "A cell is refined while it lies closer to the tip than this many of its own widths; "
                     "larger values give more cells per ring. Units: cell widths.");
      entries.increasing_numbers(
          "Ring radii", ring_radii, {0.25, 0.5, 0.75}, 1, interval("()", 0, 1),
          "Outer radii of the J-integral domains around the tip, weight q = (1 - (d/rho)^2)^4; "
          "inside the domain for every c: below 4 D/lambda (D the Depth D, or each of the depth study's "
          "Depths). The searches and periodic-gap-depth use the last. Units: min(c, lambda/2 - c).");
      // min(c, lambda/2 - c) is at most lambda/4: rings below 4 D/lambda stay above z = -D.
      if (read_depth)
        {
          const double largest = std::min(1., 4 * depth);
          for (const double rho : ring_radii)
            entries.require(rho < largest, "Ring radii", rho,
                            "(0, min(1, 4 D/lambda) = " + shortest(largest) + ")");
        }
    });
  }

  void gap_and_load_section(Sections &sections, GapAndLoad &gap)
  {
    sections.subsection("Gap and load", [&](Entries &entries) {
      // The tip cells are min(c, lambda/2 - c)/2^levels wide: a gap or a
      // contact narrower than 1e-6 lambda would need more quadtree levels than a mesh holds.
      entries.number("Gap half-width c/lambda", gap.gap_ratio, 0.2,
                     {"[1e-6, 0.5 - 1e-6]", [](const double x) { return x >= 1e-6 && x <= 0.5 - 1e-6; }},
                     "Half-width of the gap, centred where the tension peaks; the contact half-width is a "
                     "= lambda/2 - c. Units: lambda.");
      entries.number(
          "Peak tension p*", gap.peak_tension, 1e6, magnitude("Pa"),
          "Amplitude of the full-contact pressure, p* = pi E' h/lambda for a sinusoid of amplitude h. "
          "Units: Pa.");
      entries.number("Mean pressure p_bar/p*", gap.load_ratio, 0, interval("[]", -1e3, 1e3),
                     "Mean contact pressure (compressive positive); the gap faces carry t = p* cos(2 pi "
                     "x/lambda) - p_bar. Units: p*.");
    });
  }

  PeriodicGapMeasurement solve_periodic_gap(const PeriodicGapModelParameters &model,
                                            const BuecknerTension            &load,
                                            const std::vector<double> &ring_radii, TimerOutput &timer,
                                            const ResultFolder *fields)
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

    PeriodicGapMeasurement results;
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
    if (fields)
      {
        TimerOutput::Scope scope(timer, "output");
        write_displacement(gap.get_system(), u, *fields);
      }
    return results;
  }

  PeriodicGapSearch::PeriodicGapSearch(const PeriodicGapInput &periodic)
      : timer(std::cout, TimerOutput::never, TimerOutput::wall_times),
        gaps({periodic.model, periodic.ring_radii.back()}, timer)
  {
  }

  void PeriodicGapSearch::add_cost(Table &summary) const
  {
    summary.add_row({"FE solves", Utilities::MPI::sum(gaps.n_solves(), MPI_COMM_WORLD)});
    add_phase_times(summary, timer);
  }
} // namespace penny
