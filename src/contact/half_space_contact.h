// Frictionless, adhesionless contact of a rigid periodic rough surface h(x, y)
// (m) with an elastic half-space of plane-strain modulus E* (Pa) at a
// prescribed mean pressure p_bar (Pa), by the FFT-based boundary-element
// method (doc/theory.md, section 7). The half-space's surface displacement under
// a periodic pressure is u^_q = 2 p^_q/(E* |q|) (q != 0; the mean displacement
// is the rigid-body approach and drops out), and the solution is the pressure
// p >= 0 with mean p_bar and gap g = u - h + const >= 0, p g = 0: the minimiser
// of the complementary energy p.u/2 - p.h under those constraints, found by
// Polonsky and Keer's (1999) constrained conjugate gradients.
#pragma once

#include "contact/half_space.h"

#include <vector>

namespace penny
{
  struct ContactSolverControl
  {
    unsigned int max_iterations;
    double       tolerance; // on the residual below
  };

  struct ContactSolution
  {
    GridField    pressure;         // p >= 0 (Pa), mean exactly p_bar
    GridField    gap;              // g (m), shifted to mean zero over the contact points
    double       contact_fraction; // share of grid points with p > 0
    unsigned int iterations;
    // The violation of the contact conditions, in units of the rms height:
    // sqrt((sum_{p > 0} g^2 + sum_{p = 0, g < 0} g^2)/N)/h_rms.
    double residual;
  };

  class HalfSpaceContact
  {
  public:
    // `transform` must outlive the object; heights on its grid (m).
    HalfSpaceContact(const FourierTransform &transform, GridField heights, double E_star);

    // The contact at mean pressure p_bar > 0. Starts from `initial_pressure`
    // (clipped at 0 and scaled to mean p_bar) or, if empty, from the clipped
    // full-contact pressure p_bar + p_fc, which is the solution when no gap
    // opens. Throws std::runtime_error (one line) if the residual does not
    // fall below the tolerance within max_iterations.
    ContactSolution solve(double mean_pressure, const ContactSolverControl &control,
                          const GridField &initial_pressure = {}) const;

    const GridField &heights() const { return heights_; }

  private:
    // u = 2/(E* |q|) p^ (zero mean).
    void displacement(const GridField &pressure, GridField &u) const;

    const FourierTransform    &transform;
    GridField                  heights_;
    double                     E_star;
    double                     height_scale; // rms of h about its mean
    FourierTransform::Spectrum compliance;
  };

  // One load of a sweep: the non-contact share of the grid points and the
  // solver's cost and residual.
  struct LoadStep
  {
    double       mean_pressure;
    double       noncontact_fraction;
    unsigned int iterations;
    double       residual;
  };

  // A_nc/A_0 at several mean pressures, solved from the largest down, each
  // solve started from the previous pressure shifted by the change in load
  // (near full contact the change is almost uniform). Returned in the order given.
  std::vector<LoadStep> load_sweep(const HalfSpaceContact &contact, const std::vector<double> &mean_pressures,
                                   const ContactSolverControl &control);

  // Where a contact edge lies between grid points, from the gaps g_1 ... g_M
  // (M >= 4) of the first non-contact points beside it, g_k at k cells from
  // the last contact point. Beside a smooth edge g ~ (x - a)^(3/2), so g^(2/3)
  // is smooth and vanishes linearly at the edge: fitted by a quadratic (least
  // squares, Eigen) over k = 2 ... M (the first point, nearest the discrete
  // edge, is left out) and returned is its root, in cells from the last
  // contact point.
  double edge_from_gap(const std::vector<double> &gaps);
} // namespace penny
