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
// summit, P = p* - p_bar and R_p = 1/(p* k^2)):
// - without adhesion A_nc/A_0 -> (3/(2 pi)) (1 - p_bar/p*) as p_bar -> p*;
// - with K_Ic = alpha p* sqrt(lambda) (w = alpha^2/2 in the units) a gap of
//   radius c needs P(c) = c^2/(3 R_p) + sqrt(pi) K_Ic/(2 sqrt(c)), c >= c_min,
//   and the gaps close on loading at 1 - p_bar/p* = psi (2 pi)^(2/5) alpha^(4/5).
#pragma once

#include "contact/rigid_surface.h"

#include <optional>
#include <vector>

namespace penny::adhesive_bisinusoid
{
  constexpr double psi = 1.2020809449045589; // p0 = psi (K_Ic^4/R_p)^(1/5)

  // (3/(2 pi)) (1 - p_bar/p*): the adhesionless non-contact area as p_bar -> p*.
  double isolated_noncontact_fraction(double load_ratio);
  // 1 - p_bar/p* at which the gaps close on loading, psi (2 pi)^(2/5) alpha^(4/5).
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
    // adhesionless gap at the first load (with adhesion: then switched on).
    std::vector<State> loading(const std::vector<double>  &load_ratios,
                               const ContactSolverControl &control) const;

    // With adhesion: the load at which the gap snaps shut on loading, the
    // largest p_bar/p* along a path of falling mean gap (by 20 % a step)
    // from the gap at `start_load_ratio`.
    State closure(double start_load_ratio, const ContactSolverControl &control) const;

  private:
    State state(const ContactSolution &solution) const;

    Discretisation discretisation;
    RigidSurface   surface;
  };
} // namespace penny::adhesive_bisinusoid
