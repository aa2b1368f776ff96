// The JKR sphere by the boundary-element solver: a rigid paraboloid
// h = -r^2/(2R) (its apex towards the half-space), one per periodic cell of
// side L, with exponential adhesion of work w (doc/contact-notes.md, "The JKR
// sphere"). In the JKR limit the contact radius a and the load F (compressive
// positive) obey
//
//   F = 4 E* a^3/(3R) - sqrt(8 pi w E* a^3),   pull-off at F = -(3/2) pi w R (prescribed load),
//
// reached there at a = (9 pi w R^2/(8 E*))^(1/3). The model works in units
// E* = R = 1 and w = 8/(9 pi), in which that radius is 1 and the pull-off
// load -4/3; the range follows from the cohesive zone l_pz = E* rho^2/(pi w).
// The periodic images of the sphere shift the result by a little that falls
// as the period grows.
#pragma once

#include "contact/rigid_surface.h"

#include <vector>

namespace penny::adhesive_sphere
{
  constexpr double work_of_adhesion = 8 / (9 * M_PI);
  constexpr double pull_off_load    = -4. / 3;

  // JKR's F(a) in the model's units.
  double jkr_load(double contact_radius);

  struct Discretisation
  {
    double       process_zone; // l_pz/a_pull-off
    double       period;       // L/a_pull-off
    unsigned int n_points;     // per period
  };

  // A state: the radius of the disc where the gap is below the range rho
  // (the cohesive zone's inner edge, which tends to the crack tip as rho -> 0),
  // the load F = p_bar L^2 and the mean gap that controls it.
  struct State
  {
    double contact_radius;
    double load;
    double mean_gap;
  };

  class Model
  {
  public:
    explicit Model(const Discretisation &discretisation);

    // States along an unloading path at prescribed mean gap from Hertz's
    // contact of radius 1.2 with adhesion switched on, `steps` steps each
    // raising the mean gap by `increment`, until the surfaces separate (the
    // apex's gap beyond the range rho: no contact left to measure).
    std::vector<State> unloading(const ContactSolverControl &control, unsigned int steps,
                                 double increment) const;

    // The pull-off load under prescribed load: the least load along that path.
    State pull_off(const ContactSolverControl &control) const;

    double range() const { return surface.adhesion().range; }

  private:
    ContactSolution start(const ContactSolverControl &control) const;
    State           state(const ContactSolution &solution) const;

    Discretisation discretisation;
    RigidSurface   surface;
  };
} // namespace penny::adhesive_sphere
