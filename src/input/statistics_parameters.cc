#include "input/statistics_parameters.h"

#include "input/input_error.h"
#include "input/parameter_parsing.h"

#include <cmath>
#include <limits>

namespace penny
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::FileName;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;

  namespace
  {
    constexpr double max_double = std::numeric_limits<double>::max();

    using Spectrum                    = RoughnessParameters::Spectrum;
    const EnumNames<Spectrum> spectra = {{"power-law", Spectrum::power_law}, {"file", Spectrum::file}};
    const EnumNames<bool>     amplitude_forms = {{"h0/lambda0", true}, {"rms height", false}};
    const EnumNames<bool>     conventions     = {{"paper", true}, {"consistent", false}};
  } // namespace

  void RoughnessParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Roughness");
    prm.declare_entry("Spectrum", "power-law", selection(spectra),
                      "Isotropic height PSD C(q): the paper's power law (H/2pi) (h0/q0)^2 (q/q0)^(-2(H+1)) "
                      "on q0 <= q <= zeta q0, or the table in 'Spectrum file'.");
    prm.declare_entry("Hurst exponent H", "0.75", Double(0, 1), "Open range (0, 1). Units: none.");
    prm.declare_entry("Long-wavelength cut-off q0", "6283.185307179586", Double(0),
                      "Smallest wavenumber of the power law, q0 = 2 pi/lambda0. Units: 1/m.");
    prm.declare_entry("Magnification zeta", "1000", Double(1),
                      "q1/q0, the bandwidth of the power law; above 1. Units: none.");
    prm.declare_entry("Amplitude given by", "h0/lambda0", selection(amplitude_forms),
                      "h0/lambda0: h0 = (h0/lambda0) 2 pi/q0; rms height: h0 such that sqrt(m0) is the "
                      "'Rms height'.");
    prm.declare_entry("Amplitude h0/lambda0", "0.01", Double(0), "Units: none.");
    prm.declare_entry("Rms height", "1e-6", Double(0), "sqrt(m0) of the power law. Units: m.");
    prm.declare_entry("Spectrum file", "psd.txt", FileName(),
                      "Two columns q (1/m, increasing) and C(q) (m^4), '#' comments; log-log linear between "
                      "rows (relative paths start at the parameter file's folder).");
    prm.leave_subsection();
  }

  void RoughnessParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Roughness");
    spectrum                = to_enum(spectra, prm.get("Spectrum"));
    hurst                   = prm.get_double("Hurst exponent H");
    q0                      = prm.get_double("Long-wavelength cut-off q0");
    zeta                    = prm.get_double("Magnification zeta");
    spectrum_file           = prm.get("Spectrum file");
    const bool   from_ratio = to_enum(amplitude_forms, prm.get("Amplitude given by"));
    const double ratio = prm.get_double("Amplitude h0/lambda0"), rms = prm.get_double("Rms height");
    prm.leave_subsection();
    require(hurst > 0 && hurst < 1, "Roughness/Hurst exponent H", hurst, "(0, 1)");
    require(q0 > 0, "Roughness/Long-wavelength cut-off q0", q0, "(0, inf)");
    require(zeta > 1, "Roughness/Magnification zeta", zeta, "(1, inf)");
    require(from_ratio ? ratio > 0 : rms > 0,
            from_ratio ? "Roughness/Amplitude h0/lambda0" : "Roughness/Rms height", from_ratio ? ratio : rms,
            "(0, inf)");
    // m0 = h0^2 (1 - zeta^(-2H))/2 for the power law.
    amplitude = from_ratio ? ratio * 2 * M_PI / q0 : rms * std::sqrt(2 / (1 - std::pow(zeta, -2 * hurst)));
  }

  double AreaLoadParameters::mean_pressure(const unsigned int i) const
  {
    return smallest_mean_pressure + i * (largest_mean_pressure - smallest_mean_pressure) / (n_points - 1);
  }

  void AreaLoadParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Area-load");
    prm.declare_entry(
        "Convention", "paper", selection(conventions),
        "paper: the paper's normalisations, prefactor 3 pi R_p eta sqrt(V) = sqrt(2 pi) and "
        "p0/sqrt(V) = zeta^theta, theta = (2/5)(2H - 1). consistent: V, eta, R_p and p0 from the "
        "moments of the Roughness spectrum (each H and zeta below replacing its own), the "
        "Material and the Adhesion sections.");
    prm.declare_entry("Smallest mean pressure", "0", Double(-max_double, max_double),
                      "First p_bar/sqrt(V) of the curves (compression positive). Units: sqrt(V).");
    prm.declare_entry("Largest mean pressure", "3", Double(-max_double, max_double),
                      "Last p_bar/sqrt(V). Units: sqrt(V).");
    prm.declare_entry("Number of points", "61", Integer(2, 100000),
                      "Points of every curve, evenly spaced: mean pressures, or p0/sqrt(V) in "
                      "zero-load-gap-area. Units: none.");
    prm.declare_entry("Hurst exponents", "0.75, 0.5, 0.25", List(Double(0, 1), 1),
                      "area-load: one panel per H; magnification-scaling: one fit per H. Open range (0, 1). "
                      "Units: none.");
    prm.declare_entry("Magnifications", "1, 10, 100, 1000, 10000", List(Double(1), 1),
                      "area-load: one curve per zeta >= 1 (> 1 in the consistent convention). Units: none.");
    prm.leave_subsection();
  }

  void AreaLoadParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Area-load");
    convention_is_paper    = to_enum(conventions, prm.get("Convention"));
    smallest_mean_pressure = prm.get_double("Smallest mean pressure");
    largest_mean_pressure  = prm.get_double("Largest mean pressure");
    n_points               = prm.get_integer("Number of points");
    hurst_exponents        = get_doubles(prm, "Hurst exponents");
    magnifications         = get_doubles(prm, "Magnifications");
    prm.leave_subsection();
    // Near full contact the gaps are isolated for p_bar of a few sqrt(V); far
    // beyond, the laws underflow to 0 or overflow.
    require(std::abs(smallest_mean_pressure) <= 100, "Area-load/Smallest mean pressure",
            smallest_mean_pressure, "[-100, 100] sqrt(V)");
    require(largest_mean_pressure > smallest_mean_pressure && largest_mean_pressure <= 100,
            "Area-load/Largest mean pressure", largest_mean_pressure,
            "(Smallest mean pressure, 100] sqrt(V)");
    for (const double H : hurst_exponents)
      require(H > 0 && H < 1, "Area-load/Hurst exponents", H, "(0, 1)");
    // Beyond 1e30 the spectral moments leave the range of a double.
    for (const double zeta : magnifications)
      require((convention_is_paper ? zeta >= 1 : zeta > 1) && zeta <= 1e30, "Area-load/Magnifications", zeta,
              convention_is_paper ? "[1, 1e30]" : "(1, 1e30] in the consistent convention");
  }

  void ZeroLoadGapAreaParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Zero-load gap area");
    prm.declare_entry(
        "Largest p0/sqrt(V)", "5", Double(0),
        "p0/sqrt(V) runs from 0 to this value in Area-load/Number of points steps. Units: none.");
    prm.leave_subsection();
  }

  void ZeroLoadGapAreaParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Zero-load gap area");
    largest_adhesion_ratio = prm.get_double("Largest p0/sqrt(V)");
    prm.leave_subsection();
  }

  void FeGapAreaParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("FE gap area");
    prm.declare_entry(
        "p0/sqrt(V)", "1", Double(0),
        "Adhesion of the gap population; sqrt(V) = p0/this, with p0 from Load/Summit radius R_p "
        "and the Adhesion section. Units: none.");
    prm.declare_entry("Tabulated tensions", "20", Integer(3, 200),
                      "FE gap radii at this many peak tensions P = p0 + t^2 sqrt(V), Chebyshev points in t. "
                      "Units: none.");
    prm.leave_subsection();
  }

  void FeGapAreaParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("FE gap area");
    adhesion_ratio       = prm.get_double("p0/sqrt(V)");
    n_tabulated_tensions = prm.get_integer("Tabulated tensions");
    prm.leave_subsection();
    require(adhesion_ratio > 0, "FE gap area/p0/sqrt(V)", adhesion_ratio, "(0, inf)");
  }

  void MagnificationScalingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Magnification scaling");
    prm.declare_entry("Fit magnifications", "1e12, 1e16", List(Double(1), 2, 2),
                      "The zeta range of the least-squares fit of theta. Units: none.");
    prm.leave_subsection();
  }

  void MagnificationScalingParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Magnification scaling");
    const auto fit          = get_doubles(prm, "Fit magnifications");
    first_fit_magnification = fit[0];
    last_fit_magnification  = fit[1];
    prm.leave_subsection();
    require(last_fit_magnification > first_fit_magnification && first_fit_magnification > 1 &&
                last_fit_magnification <= 1e30,
            "Magnification scaling/Fit magnifications", last_fit_magnification, "(first > 1, 1e30]");
  }

  void SinusoidParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Sinusoid");
    prm.declare_entry("Johnson parameters alpha", "0, 0.2, 0.4, 0.6", List(Double(0), 1),
                      "alpha^2 = 2 lambda dgamma/(pi^2 E* h^2) of Johnson's adhesive 1D sinusoid, one curve "
                      "each. Units: none.");
    prm.declare_entry("Number of points", "199", Integer(2, 100000),
                      "Contact semi-widths a/lambda, evenly spaced inside (0, 1/2). Units: none.");
    prm.leave_subsection();
  }

  void SinusoidParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Sinusoid");
    alphas   = get_doubles(prm, "Johnson parameters alpha");
    n_points = prm.get_integer("Number of points");
    prm.leave_subsection();
  }
} // namespace penny
