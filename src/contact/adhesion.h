// The short-range adhesion between the rigid surface and the half-space: an
// interaction energy per area phi(g) of the local gap g >= 0 (m),
//
//   phi(g) = -w exp(-g/rho),
//
// w (J/m^2) the work of adhesion and rho (m) the range (doc/contact-notes.md,
// "The adhesive law"). Its attraction -phi'(g) = -(w/rho) exp(-g/rho) is
// strongest in contact, sigma_max = w/rho, and the cohesive zone at a contact
// edge is about l_pz = E* w/(pi sigma_max^2) = E* rho^2/(pi w) long. As rho -> 0
// at fixed w the edge becomes a crack whose energy release rate is w: the JKR
// limit, K_Ic = sqrt(2 E* w). w = 0 is the hard wall alone.
#pragma once

#include <cmath>

namespace penny
{
  struct Adhesion
  {
    double work  = 0; // w (J/m^2)
    double range = 0; // rho (m)

    bool   active() const { return work > 0; }
    double energy(const double gap) const { return -work * std::exp(-gap / range); }
    // phi'(g) (Pa): minus the attraction, so the traction on the half-space
    // (compressive positive) is p = -phi'(g) in a gap.
    double slope(const double gap) const { return work / range * std::exp(-gap / range); }
    double curvature(const double gap) const { return -slope(gap) / range; }
    double strength() const { return work / range; }
    double process_zone(const double E_star) const { return E_star * range * range / (M_PI * work); }
    // Beyond this gap exp(-g/rho) < 1e-17: the attraction is below rounding.
    double reach() const { return 40 * range; }
  };
} // namespace penny
