#include "input/random_surface_parameters.h"

#include "input/input_error.h"
#include "input/parameter_parsing.h"

#include <limits>

namespace penny
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;

  void RandomSurfaceParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Random surfaces");
    prm.declare_entry("Grid points per side", "256", Integer(8, 65536),
                      "N of the periodic N x N grid; even, 8 ... 65536. Units: none.");
    prm.declare_entry("Period L/lambda0", "1", Double(1),
                      "Side of the periodic square in units of the longest wavelength lambda0 = 2 pi/q0 "
                      "(Roughness); at least 1. The shortest wavelength lambda0/zeta must span at least 4 "
                      "grid points. Units: none.");
    prm.declare_entry("Realisations", "16", Integer(1, 1000000),
                      "Independent surfaces, spread over the MPI ranks. Units: none.");
    prm.declare_entry("Seed", "1", Integer(0),
                      "Realisation k uses the seed realisation_seed(Seed, k): the same surfaces on any "
                      "number of ranks. Units: none.");
    prm.leave_subsection();
  }

  void RandomSurfaceParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Random surfaces");
    n_points       = prm.get_integer("Grid points per side");
    period         = prm.get_double("Period L/lambda0");
    n_realisations = prm.get_integer("Realisations");
    seed           = prm.get_integer("Seed");
    prm.leave_subsection();
    require(n_points % 2 == 0, "Random surfaces/Grid points per side", n_points, "even numbers 8 ... 65536");
  }

  void SummitStatisticsParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Summit statistics");
    prm.declare_entry("Hurst exponents", "0.25, 0.5, 0.75", List(Double(0, 1), 1),
                      "One power law per H and zeta (replacing Roughness/Hurst exponent H). Open range "
                      "(0, 1). Units: none.");
    prm.declare_entry("Magnifications", "8, 32", List(Double(1), 1),
                      "zeta > 1 of each power law (replacing Roughness/Magnification zeta). Units: none.");
    prm.declare_entry("Height bins", "12", Integer(1, 1000),
                      "Bins of the summit height distribution over [-2, 4] sqrt(V). Units: none.");
    prm.declare_entry("Largest deviation", "4", Double(0),
                      "The verdict: the sampled moments, summit density and mean summit curvature lie within "
                      "this many standard errors of their expectation for the sampled lattice. Units: "
                      "standard errors.");
    prm.leave_subsection();
  }

  void SummitStatisticsParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Summit statistics");
    hurst_exponents   = get_doubles(prm, "Hurst exponents");
    magnifications    = get_doubles(prm, "Magnifications");
    n_height_bins     = prm.get_integer("Height bins");
    largest_deviation = prm.get_double("Largest deviation");
    prm.leave_subsection();
    for (const double zeta : magnifications)
      require(zeta > 1, "Summit statistics/Magnifications", zeta, "(1, inf)");
  }

  void BemWestergaardParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("BEM Westergaard");
    prm.declare_entry("Wavelength lambda", "1e-3", Double(0), "Period of the sinusoid. Units: m.");
    prm.declare_entry("Amplitude h0", "1e-6", Double(0),
                      "h = 2 h0 sin^2(pi x/lambda); p* = pi E* h0/lambda. Units: m.");
    prm.declare_entry("Grid sizes", "64, 128, 256, 512, 1024", List(Integer(16, 1 << 20), 1),
                      "Grid points per wavelength, increasing (the grid is N x 4, the surface does not "
                      "depend on y). Units: none.");
    prm.declare_entry("Load ratios", "0.2, 0.5, 0.8", List(Double(0, 1), 1),
                      "p_bar/p* of the solves, in (0, 1). Units: none.");
    prm.declare_entry("Solver tolerance", "1e-12", Double(0),
                      "Residual of the constrained CG, in units of the rms height. Units: none.");
    prm.declare_entry("Half-width tolerance", "1e-3", Double(0),
                      "The verdict: |a - a_Westergaard|/lambda at the finest grid, every load. Units: none.");
    prm.leave_subsection();
  }

  void BemWestergaardParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("BEM Westergaard");
    wavelength = prm.get_double("Wavelength lambda");
    amplitude  = prm.get_double("Amplitude h0");
    grid_sizes.clear();
    for (const double n : get_doubles(prm, "Grid sizes"))
      grid_sizes.push_back(n);
    load_ratios          = get_doubles(prm, "Load ratios");
    solver_tolerance     = prm.get_double("Solver tolerance");
    half_width_tolerance = prm.get_double("Half-width tolerance");
    prm.leave_subsection();
    for (std::size_t k = 0; k < grid_sizes.size(); ++k)
      require(grid_sizes[k] % 2 == 0 && (k == 0 || grid_sizes[k] > grid_sizes[k - 1]),
              "BEM Westergaard/Grid sizes", grid_sizes[k], "even and increasing");
    for (const double ratio : load_ratios)
      require(ratio > 0 && ratio < 1, "BEM Westergaard/Load ratios", ratio, "(0, 1)");
  }

  void RandomContactParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Random contact");
    prm.declare_entry("Mean pressures", "1, 1.5, 2, 2.5, 3", List(Double(0), 1),
                      "p_bar/sqrt(V), V the variance of the full-contact pressure of the sampled lattice; "
                      "solved from the largest down. Units: sqrt(V).");
    prm.declare_entry("Solver tolerance", "1e-8", Double(0),
                      "Residual of the constrained CG, in units of the rms height. Units: none.");
    prm.declare_entry("Maximum iterations", "5000", Integer(1), "Of one solve. Units: none.");
    prm.leave_subsection();
  }

  void RandomContactParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Random contact");
    mean_pressures   = get_doubles(prm, "Mean pressures");
    solver_tolerance = prm.get_double("Solver tolerance");
    max_iterations   = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
    for (const double p : mean_pressures)
      require(p > 0, "Random contact/Mean pressures", p, "(0, inf)");
  }
} // namespace penny
