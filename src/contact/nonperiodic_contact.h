// Frictionless, adhesionless contact of a rigid surface known on a patch that
// is not periodic (a measured map) with an elastic half-space: the isolated
// patch, with no images, by the DC-FFT (Liu, Wang and Liu 2000) and the
// constrained conjugate gradients of Polonsky and Keer (1999)
// (doc/measured.md, "Contact of a patch that is not periodic").
//
// The pressure is constant on each pixel; Love's closed form for a uniformly
// loaded rectangle gives the displacement each pixel's unit pressure causes
// at every pixel centre, and the displacement of all the patch's pressures,
// a linear (not cyclic) convolution, is a cyclic one on the grid doubled in
// each direction with the pressures zero-padded: one FFT pair there, exact to
// rounding. The unknown is the pressure p >= 0; the separation
// s(x) = (u(x) - h(x)) - delta must vanish where p > 0 and be >= 0 elsewhere,
// delta the rigid approach, at the prescribed total load.
#pragma once

#include "contact/half_space_contact.h"
#include "fourier/fourier_transform.h"

namespace penny
{
  struct NonperiodicSolution
  {
    GridField    pressure;         // Pa, >= 0, on the patch's points
    GridField    separation;       // m, >= 0, exactly zero where pressure > 0
    double       approach;         // delta (m): the rigid body's approach, up to the heights' datum
    double       contact_fraction; // share of the patch's points in contact
    unsigned int iterations;
    double residual; // rms of the separation on the contact points and of the overlap elsewhere (units of rms
                     // height)
  };

  class NonperiodicContact
  {
  public:
    // Heights h (m) of the rigid surface on `patch` (lx = nx dx, ly = ny dy,
    // not periodic), against a half-space of plane-strain modulus E* (Pa).
    NonperiodicContact(const PeriodicGrid &patch, GridField heights, double E_star);

    // The half-space's surface displacement (m, into the solid positive) at
    // the pixel centres under the pixels' pressures (Pa).
    GridField displacement(const GridField &pressure) const;

    // Equilibrium at the mean pressure p_bar > 0 over the patch (total load
    // p_bar lx ly), from a uniform pressure; the tolerance bounds the rms
    // separation on contact and overlap off it, in units of the rms height.
    // Throws ContactSolverFailure when it is not reached within max_iterations.
    NonperiodicSolution solve(double mean_pressure, const ContactSolverControl &control) const;

    // Love's displacement (m) at offset (x, y) from the centre of a dx x dy
    // rectangle under unit pressure (1 Pa) on a half-space of modulus E*.
    static double rectangle_influence(double x, double y, double dx, double dy, double E_star);

  private:
    PeriodicGrid               patch;
    GridField                  heights;
    double                     E_star;
    FourierTransform           padded; // on the doubled grid
    FourierTransform::Spectrum influence;
  };
} // namespace penny
