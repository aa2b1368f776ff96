#include "problems/rough_surface.h"

#include "input/input_error.h"
#include "problems/solid.h"

#include <cmath>
#include <filesystem>

namespace penny
{
  namespace
  {
    void power_law_shape_entries(Entries &entries, RoughnessParameters &roughness, const std::string &use)
    {
      entries.number("Hurst exponent H", roughness.hurst, 0.75, interval("[)", smallest_hurst_exponent, 1),
                     use + "Units: none.");
      // Beyond 1e30 the spectral moments leave the range of a double.
      entries.number("Magnification zeta", roughness.zeta, 1000, interval("(]", 1, 1e30),
                     use + "q1/q0, the bandwidth of the power law. Units: none.");
    }
  } // namespace

  void power_law_shape_section(Sections &sections, RoughnessParameters &roughness, const std::string &use)
  {
    sections.subsection("Roughness",
                        [&](Entries &entries) { power_law_shape_entries(entries, roughness, use); });
  }

  void roughness_section(Sections &sections, RoughnessParameters &roughness, const bool one_spectrum)
  {
    using Spectrum = RoughnessParameters::Spectrum;
    sections.subsection("Roughness", [&](Entries &entries) {
      if (!one_spectrum)
        {
          roughness.spectrum = Spectrum::power_law;
          entries.number("Long-wavelength cut-off q0", roughness.q0, 6283.185307179586, above(0),
                         "Smallest wavenumber of the power laws, q0 = 2 pi/lambda0. Units: 1/m.");
          double ratio = 0;
          entries.number("Amplitude h0/lambda0", ratio, 0.01, above(0),
                         "h0 = (h0/lambda0) 2 pi/q0 of the power laws. Units: none.");
          roughness.amplitude = ratio * 2 * M_PI / roughness.q0;
          return;
        }
      entries.choice(
          "Spectrum", roughness.spectrum, Spectrum::power_law,
          EnumNames<Spectrum>{{"power-law", Spectrum::power_law}, {"file", Spectrum::file}},
          "Isotropic height PSD C(q): the paper's power law (H/2pi) (h0/q0)^2 (q/q0)^(-2(H+1)) on q0 <= q "
          "<= zeta q0, or the table in 'Spectrum file'.");
      power_law_shape_entries(entries, roughness, "");
      entries.number("Long-wavelength cut-off q0", roughness.q0, 6283.185307179586, above(0),
                     "Smallest wavenumber of the power law, q0 = 2 pi/lambda0. Units: 1/m.");
      bool from_ratio = true;
      entries.choice("Amplitude given by", from_ratio, true,
                     EnumNames<bool>{{"h0/lambda0", true}, {"rms height", false}},
                     "h0/lambda0: h0 = (h0/lambda0) 2 pi/q0; rms height: h0 such that sqrt(m0) is the 'Rms "
                     "height'.");
      double ratio = 0, rms = 0;
      entries.number("Amplitude h0/lambda0", ratio, 0.01, above(0), "Units: none.");
      entries.number("Rms height", rms, 1e-6, above(0), "sqrt(m0) of the power law. Units: m.");
      // m0 = h0^2 (1 - zeta^(-2H))/2 for the power law.
      roughness.amplitude = from_ratio
                                ? ratio * 2 * M_PI / roughness.q0
                                : rms * std::sqrt(2 / (1 - std::pow(roughness.zeta, -2 * roughness.hurst)));
      entries.file(
          "Spectrum file", roughness.spectrum_file, "psd.txt",
          "Two columns q (1/m, increasing) and C(q) (m^4), '#' comments; log-log linear between rows "
          "(relative paths start at the parameter file's folder).");
    });
    sections.check([&] {
      if (roughness.spectrum != Spectrum::file)
        return;
      if (!std::filesystem::is_regular_file(roughness.spectrum_file))
        throw InputError("Roughness/Spectrum file = " + in_quotes(roughness.spectrum_file) +
                         " does not exist or is not a file (expected two columns q (1/m), C(q) (m^4))");
      sections.input_file(roughness.spectrum_file);
    });
  }

  PowerSpectrum power_spectrum(const RoughnessParameters &roughness)
  {
    if (roughness.spectrum == RoughnessParameters::Spectrum::power_law)
      return power_law_spectrum(roughness.hurst, roughness.q0, roughness.zeta, roughness.amplitude);
    try
      {
        return read_power_spectrum(roughness.spectrum_file);
      }
    catch (const InputError &error)
      {
        throw InputError("Roughness/Spectrum file = " + std::string(error.what()));
      }
  }

  void mean_pressure_entries(Sections &sections, Sweep &mean_pressures)
  {
    sections.subsection("Area-load", [&](Entries &entries) {
      // Near full contact the gaps are isolated for p_bar of a few sqrt(V);
      // far beyond, the laws underflow to 0 or overflow.
      entries.sweep("mean pressure", "Number of points", mean_pressures, {0, 3, 61}, 2, 100000,
                    interval("[]", -100, 100, "sqrt(V)"),
                    "The range of p_bar/sqrt(V) of the curves (compression positive). Units: sqrt(V).");
    });
  }

  void hurst_exponents_entry(Sections &sections, std::vector<double> &hurst_exponents)
  {
    sections.subsection("Area-load", [&](Entries &entries) {
      entries.numbers("Hurst exponents", hurst_exponents, {0.75, 0.5, 0.25},
                      interval("[)", smallest_hurst_exponent, 1),
                      "area-load: one panel per H; magnification-scaling: one fit per H. Units: none.");
    });
  }

  void magnifications_entry(Sections &sections, std::vector<double> &magnifications,
                            const bool &convention_is_paper)
  {
    sections.subsection("Area-load", [&](Entries &entries) {
      // Beyond 1e30 the spectral moments leave the range of a double.
      entries.numbers("Magnifications", magnifications, {1, 10, 100, 1000, 10000}, interval("[]", 1, 1e30),
                      "One curve per zeta (above 1 in the consistent convention). Units: none.");
      if (!convention_is_paper)
        for (const double zeta : magnifications)
          entries.require(zeta > 1, "Magnifications", zeta, "(1, 1e30] in the consistent convention");
    });
  }

  void convention_entry(Sections &sections, bool &convention_is_paper)
  {
    sections.subsection("Area-load", [&](Entries &entries) {
      entries.choice(
          "Convention", convention_is_paper, true, EnumNames<bool>{{"paper", true}, {"consistent", false}},
          "paper: the paper's normalisations, prefactor 3 pi R_p eta sqrt(V) = sqrt(2 pi) and p0/sqrt(V) = "
          "zeta^theta, theta = (2/5)(2H - 1). consistent: V, eta, R_p and p0 from the moments of the "
          "Roughness spectrum (with the curve's H and zeta, where the scene has its own), and where the "
          "scene has them, the Material and the Adhesion sections.");
    });
  }

  GapPopulation RoughSurfaceProblem::population(const double hurst, const double zeta) const
  {
    if (convention_is_paper)
      return paper_population(hurst, zeta);
    const auto moments = spectral_moments(power_law_spectrum(hurst, roughness.q0, zeta, roughness.amplitude));
    return surface_population(
        pressure_summits(moments, material.plane_strain_modulus(), Convention::consistent),
        critical_stress_intensity, Convention::consistent);
  }

  std::string RoughSurfaceProblem::convention_line() const
  {
    return convention_is_paper
               ? "convention: paper (3 pi R_p eta sqrt(V) = sqrt(2 pi), p0/sqrt(V) = zeta^theta)"
               : "convention: consistent (V, eta, R_p and p0 from the moments of the Roughness power law)";
  }

  void rough_surface_sections(Sections &sections, RoughSurfaceProblem &problem, const bool one_spectrum)
  {
    material_section(sections, problem.material);
    adhesion_section(sections, problem.critical_stress_intensity, problem.material);
    roughness_section(sections, problem.roughness, one_spectrum);
  }
} // namespace penny
