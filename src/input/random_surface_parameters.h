// Parameters of the scenes on sampled random surfaces (doc/theory.md, section 7):
// the grid and realisations, the summit statistics, the boundary-element
// check on Westergaard's sinusoid and the contact of random surfaces.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <cstdint>
#include <vector>

namespace penny
{
  // Realisations of the Roughness spectrum on a periodic square grid.
  struct RandomSurfaceParameters
  {
    unsigned int  n_points; // grid points per side
    double        period;   // side L in units of lambda0 = 2 pi/q0
    unsigned int  n_realisations;
    std::uint64_t seed;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // summit-statistics: the power laws sampled and the checks of the samples.
  struct SummitStatisticsParameters
  {
    std::vector<double> hurst_exponents, magnifications;
    unsigned int        n_height_bins;
    double              largest_deviation; // in standard errors

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // bem-westergaard: the sinusoid on grids of increasing size.
  struct BemWestergaardParameters
  {
    double                    wavelength, amplitude; // lambda (m), h0 (m) of h = 2 h0 sin^2(pi x/lambda)
    std::vector<unsigned int> grid_sizes;            // points per wavelength
    std::vector<double>       load_ratios;           // p_bar/p*
    double                    solver_tolerance;
    double                    half_width_tolerance; // of a/lambda at the finest grid

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // random-contact: the loads and the solver.
  struct RandomContactParameters
  {
    std::vector<double> mean_pressures; // p_bar/sqrt(V)
    double              solver_tolerance;
    unsigned int        max_iterations;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace penny
