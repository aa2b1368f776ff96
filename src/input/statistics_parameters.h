// Parameters of the statistical layer: the rough surface, the area-load
// curves and the scenes built on them.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace penny
{
  // The rough surface of the statistical layer: its height PSD.
  struct RoughnessParameters
  {
    enum class Spectrum
    {
      power_law,
      file
    };
    Spectrum    spectrum;
    double      hurst;     // H
    double      q0;        // long-wavelength cut-off (1/m)
    double      zeta;      // magnification q1/q0
    double      amplitude; // h0 (m) of the power law
    std::string spectrum_file;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // Area-load curves aggregated over the Gaussian field of pressure summits.
  struct AreaLoadParameters
  {
    bool                convention_is_paper;
    double              smallest_mean_pressure, largest_mean_pressure; // p_bar/sqrt(V)
    unsigned int        n_points;
    std::vector<double> hurst_exponents, magnifications;

    // The i-th of the n_points mean pressures p_bar/sqrt(V).
    double mean_pressure(unsigned int i) const;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // zero-load-gap-area: A_nc/A_0 at p_bar = 0 against p0/sqrt(V).
  struct ZeroLoadGapAreaParameters
  {
    double largest_adhesion_ratio; // largest p0/sqrt(V)

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // fe-gap-area: the area-load curve with the FE gap function.
  struct FeGapAreaParameters
  {
    double       adhesion_ratio;       // p0/sqrt(V)
    unsigned int n_tabulated_tensions; // FE g at this many P

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // magnification-scaling: the zeta range of the fit of theta.
  struct MagnificationScalingParameters
  {
    double first_fit_magnification, last_fit_magnification;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct SinusoidParameters
  {
    std::vector<double> alphas; // Johnson's adhesion parameters
    unsigned int        n_points;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace penny
