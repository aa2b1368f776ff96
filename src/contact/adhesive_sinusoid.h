// Johnson's adhesive sinusoid (1995) by the boundary-element solver: the
// rigid profile h = 2 h0 sin^2(pi x/lambda) on a half-space in plane strain (a
// field constant in y: an n x 1 grid), full-contact pressure
// p_bar - p* cos(2 pi x/lambda) with p* = pi E* h0/lambda, contact strip
// |x - lambda/2| < a, and in the JKR limit (doc/contact-notes.md, "Johnson's sinusoid")
//
//   p_bar/p* = sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda)),   alpha = K_Ic/(p* sqrt(lambda)),
//
// with K_Ic = sqrt(2 E* w) (closed_forms/periodic_array.h). The model works in units E* = lambda = p* = 1,
// where w = alpha^2/2 and the range of the exponential law follows from the
// cohesive zone l_pz = E* rho^2/(pi w) as rho = alpha sqrt(pi l_pz/2).
#pragma once

#include "contact/rigid_surface.h"

#include <vector>

namespace penny::adhesive_sinusoid
{
  // One discretisation of the problem.
  struct Discretisation
  {
    double       alpha;
    double       process_zone; // l_pz/lambda
    unsigned int n_points;     // per wavelength
  };

  // A state on the path: the half-width a/lambda of the strip where the gap
  // is below the range rho (the cohesive zone's edge nearest the contact,
  // which tends to the crack tip as rho -> 0), the load, and the mean gap
  // that controls it.
  struct CurvePoint
  {
    double       contact_ratio; // a/lambda
    double       load_ratio;    // p_bar/p*
    double       mean_gap;      // <g>/h0
    unsigned int iterations; // of the solves that found it, with nested iteration's on coarser grids weighted
                             // by their points
  };

  class Model
  {
  public:
    explicit Model(const Discretisation &discretisation);

    // p_bar/p* at each a/lambda (increasing, inside the curve's range),
    // found by a secant iteration on the mean gap down a path of decreasing
    // mean gap (the contact grows), each solve started from the previous one.
    std::vector<CurvePoint> loads_at_half_widths(const std::vector<double>  &contact_ratios,
                                                 const ContactSolverControl &control) const;

    // The jump into full contact: the largest p_bar/p* along that path
    // (a maximum under prescribed mean gap, where prescribed mean pressure
    // ends the path), by successive parabolic interpolation in the mean gap.
    // It starts from the strip of a/lambda = 0.3, found on `curve` (from
    // loads_at_half_widths) where that holds it.
    CurvePoint jump_into_contact(const ContactSolverControl    &control,
                                 const std::vector<CurvePoint> &curve) const;

  private:
    CurvePoint state(const ContactSolution &solution) const;

    Discretisation discretisation;
    RigidSurface   surface;
  };
} // namespace penny::adhesive_sinusoid
