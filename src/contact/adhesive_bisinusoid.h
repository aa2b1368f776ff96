// The bi-sinusoid near full contact by the boundary-element solver
// (doc/contact-notes.md, "The bi-sinusoid"): the rigid surface
// h = Delta cos(kx) cos(ky), k = 2 pi/lambda, needs the full-contact pressure
// p_bar - p* cos(kx) cos(ky), p* = sqrt(2) pi E* Delta/lambda, whose tension
// peaks, two per period cell, hold the gaps. As
// cos(kx) cos(ky) = (cos(k'u) + cos(k'v))/2 in axes u, v turned by 45 degrees
// with k' = sqrt(2) k, the model solves the equivalent egg-box
// h = (Delta/2)(cos(k'x) + cos(k'y)) on a square cell of side lambda/sqrt(2)
// that holds one gap, centred. Units E* = lambda = p* = 1.
//
// Isolated-gap predictions (each gap a penny crack under the tension of its
// summit, P = p* - p_bar and R_p = 1/(p* k^2), closed_forms/adhesive_gap.h):
// - without adhesion A_nc/A_0 -> (3/(2 pi)) (1 - p_bar/p*) as p_bar -> p*;
// - with K_Ic = alpha p* sqrt(lambda) (w = alpha^2/2 in the units) a gap of
//   radius c needs P(c) = c^2/(3 R_p) + sqrt(pi) K_Ic/(2 sqrt(c)), c >= c_min,
//   and the gaps close on loading at 1 - p_bar/p* = p0/p* = psi (2 pi)^(2/5) alpha^(4/5).
#pragma once

#include "contact/rigid_surface.h"

#include <optional>
#include <vector>

namespace penny::adhesive_bisinusoid
{
  // R_p of the tension peaks, 1/(p* k^2), in the units lambda/p*: with the
  // peak tension P = 1 - p_bar/p* and K_Ic = alpha the summit's penny gap
  // follows from the closed forms (or FE) of one gap.
  constexpr double summit_radius = 1 / (4 * M_PI * M_PI);

  // (3/(2 pi)) (1 - p_bar/p*): the adhesionless non-contact area as p_bar -> p*.
  double isolated_noncontact_fraction(double load_ratio);
  // 1 - p_bar/p* at which the gaps close on loading, p0/p* = psi (2 pi)^(2/5) alpha^(4/5).
  double isolated_closure_margin(double alpha);
  // The isolated gap's radius c/lambda at 1 - p_bar/p* (the stable branch),
  // nothing where the tension is below p0 and the gap closes.
  std::optional<double> isolated_gap_radius(double load_margin, double alpha);

  struct Discretisation
  {
    double       alpha;        // 0: no adhesion
    double       process_zone; // l_pz/lambda (with adhesion)
    unsigned int n_points;     // per side of the cell lambda/sqrt(2)
  };

  // A state: the load and the gap's equivalent radius sqrt(area/pi) (the
  // area where the gap exceeds the range rho; without adhesion the share of
  // grid points not in contact), nothing if the gap has closed.
  struct State
  {
    double                load_ratio; // p_bar/p*
    double                mean_gap;   // <g>/lambda
    double                noncontact_fraction;
    std::optional<double> gap_radius; // c/lambda
  };

  class Model
  {
  public:
    explicit Model(const Discretisation &discretisation);

    // Equilibria at increasing p_bar/p* along a loading path from the
    // adhesionless gap at the first load (with adhesion: then switched on);
    // `until_closure` (with adhesion), then the load at which the gap snaps
    // shut beyond the last of them, appended: the largest p_bar/p* along a
    // path of falling mean gap (by 20 % a step) from there.
    std::vector<State> loading(const std::vector<double> &load_ratios, const ContactSolverControl &control,
                               bool until_closure = false) const;

  private:
    State state(const ContactSolution &solution) const;

    Discretisation discretisation;
    RigidSurface   surface;
  };
} // namespace penny::adhesive_bisinusoid
