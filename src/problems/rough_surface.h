// The statistical layer's problem (doc/theory.md, section 4): the subsections
// of the rough surface (Roughness) and of the area-load curves (Area-load),
// and the population of gaps a surface of given H and zeta holds, in the
// paper's convention or the consistent one.
#pragma once

#include "fe/elasticity.h"
#include "input/entries.h"
#include "statistics/contact_area.h"
#include "statistics/roughness.h"

#include <string>
#include <vector>

namespace penny
{
  // Roughness. Once read, a spectrum file must exist. A scene that samples
  // power laws of its own H and zeta (`one_spectrum` false) reads only q0 and
  // h0/lambda0 of them.
  void roughness_section(Sections &sections, RoughnessParameters &roughness, bool one_spectrum = true);

  // Roughness/Hurst exponent H and Magnification zeta alone: the shape of a
  // power law, for a scene that needs no scale; `use` starts their text.
  void power_law_shape_section(Sections &sections, RoughnessParameters &roughness, const std::string &use);

  // The spectrum a Roughness subsection describes; throws InputError naming
  // Roughness/Spectrum file for a file that is not a valid table.
  PowerSpectrum power_spectrum(const RoughnessParameters &roughness);

  // The entries of Area-load, the curves aggregated over the Gaussian field
  // of pressure summits; each scene reads those it uses.
  // The mean pressures of the curves, p_bar/sqrt(V).
  void mean_pressure_entries(Sections &sections, Sweep &mean_pressures);
  // The power laws of the curves: their Hurst exponents.
  void hurst_exponents_entry(Sections &sections, std::vector<double> &hurst_exponents);
  // ... and their magnifications, above 1 in the consistent convention.
  void magnifications_entry(Sections &sections, std::vector<double> &magnifications,
                            const bool &convention_is_paper);

  // What the statistical scenes read: the surface, its solid, the adhesion
  // and the curves.
  struct RoughSurfaceProblem
  {
    RoughnessParameters roughness;
    MaterialParameters  material;
    double              critical_stress_intensity; // K_Ic (Pa m^1/2)
    bool                convention_is_paper = true;

    // The gaps of the power-law surface (H, zeta): the paper's normalised
    // population, or the consistent one from the moments of the Roughness
    // spectrum with this H and zeta.
    GapPopulation population(double hurst, double zeta) const;

    // Which convention the curves use, as a line of the screen output.
    std::string convention_line() const;
  };

  // Material, Adhesion and Roughness (`one_spectrum` as for roughness_section).
  void rough_surface_sections(Sections &sections, RoughSurfaceProblem &problem, bool one_spectrum = true);

  // Area-load/Convention, for the scenes whose curves use one.
  void convention_entry(Sections &sections, bool &convention_is_paper);
} // namespace penny
