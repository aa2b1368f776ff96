#include "problems/solid.h"

#include <cmath>

namespace penny
{
  void material_section(Sections &sections, MaterialParameters &material)
  {
    sections.subsection("Material", [&](Entries &entries) {
      entries.number("Young's modulus E", material.youngs_modulus, 1e9, magnitude("Pa"),
                     "Isotropic linear elasticity. Units: Pa.");
      entries.number("Poisson's ratio nu", material.poissons_ratio, 0.3, interval("()", -1, 0.5),
                     "Units: none.");
    });
  }

  void adhesion_section(Sections &sections, double &critical_stress_intensity,
                        const MaterialParameters &material)
  {
    sections.subsection("Adhesion", [&](Entries &entries) {
      bool   from_work = false;
      double K_Ic = 0, G_c = 0;
      entries.choice(
          "Toughness given by", from_work, false, EnumNames<bool>{{"K_Ic", false}, {"G_c", true}},
          "K_Ic: 'Critical stress intensity K_Ic' as given; G_c: K_Ic = sqrt(E' G_c) from 'Work of "
          "adhesion G_c' and the Material section.");
      entries.number("Critical stress intensity K_Ic", K_Ic, 1.28e6, magnitude("Pa m^1/2"),
                     "Toughness of the interface: an adhesive gap is in equilibrium at K_I = K_Ic. Units: "
                     "Pa m^1/2.");
      entries.number("Work of adhesion G_c", G_c, 0.1, magnitude("J/m^2"),
                     "Interface energy per area, used when the toughness is given by G_c. Units: J/m^2.");
      critical_stress_intensity = from_work ? std::sqrt(material.plane_strain_modulus() * G_c) : K_Ic;
    });
  }
} // namespace penny
