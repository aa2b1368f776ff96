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

  // The spectrum a Roughness subsection describes; throws InputError naming
  // Roughness/Spectrum file for a file that is not a valid table.
  PowerSpectrum power_spectrum(const RoughnessParameters &roughness);

  // Area-load curves aggregated over the Gaussian field of pressure summits.
  struct AreaLoadParameters
  {
    bool                convention_is_paper;
    Sweep               mean_pressures; // p_bar/sqrt(V)
    std::vector<double> hurst_exponents, magnifications;
  };

  // Area-load.
  void area_load_section(Sections &sections, AreaLoadParameters &area_load);

  // What the statistical scenes read: the surface, its solid, the adhesion
  // and the curves.
  struct RoughSurfaceProblem
  {
    RoughnessParameters roughness;
    MaterialParameters  material;
    double              critical_stress_intensity; // K_Ic (Pa m^1/2)
    AreaLoadParameters  area_load;

    // The gaps of the power-law surface (H, zeta): the paper's normalised
    // population, or the consistent one from the moments of the Roughness
    // spectrum with this H and zeta.
    GapPopulation population(double hurst, double zeta) const;

    // Which convention the curves use, as a line of the screen output.
    std::string convention_line() const;
  };

  // Material, Adhesion, Roughness and Area-load.
  void rough_surface_sections(Sections &sections, RoughSurfaceProblem &problem);
} // namespace penny
