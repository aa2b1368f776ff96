// The solid every model is made of: the Material subsection, and the
// Adhesion subsection of the scenes with an adhesive interface, whose
// toughness may be given as a work of adhesion and the material's E'.
#pragma once

#include "fe/elasticity.h"
#include "input/entries.h"

namespace penny
{
  // Material: Young's modulus E and Poisson's ratio nu.
  void material_section(Sections &sections, MaterialParameters &material);

  // Adhesion: K_Ic (Pa m^1/2) as given, or sqrt(E' G_c) from the work of
  // adhesion G_c and `material`.
  void adhesion_section(Sections &sections, double &critical_stress_intensity,
                        const MaterialParameters &material);
} // namespace penny
