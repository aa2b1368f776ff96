// Frictionless contact of a rigid periodic rough surface h(x, y) (m) with an
// elastic half-space of plane-strain modulus E* (Pa), a hard wall plus an
// optional short-range adhesion (adhesion.h), by the FFT-based boundary-element
// method (doc/contact-notes.md).
//
// The unknown is the gap g >= 0. The half-space's surface displacement is
// u = g + h - (rigid approach), and a periodic displacement needs the traction
// (K u)^_q = (E*/2) |q| u^_q (q != 0), so with <.> the mean over the period
//
//   elastic traction  p_el = p_bar + K (g + h) = p_bar + p_fc + K g  (compressive positive),
//   energy per area   Pi(g) = (1/2) <(g + h) K (g + h)> + <phi(g)> + p_bar <g>,
//
// p_fc = K h the full-contact pressure less its mean. Equilibrium is a local
// minimum of Pi over g >= 0 at a prescribed mean pressure p_bar, or over
// g >= 0 with <g> = g_bar at a prescribed mean gap (then p_bar is the
// multiplier of that constraint). Its gradient r = p_el + phi'(g) vanishes
// where g > 0 and is the wall's reaction (>= 0) where g = 0. Without adhesion
// Pi is convex and the equilibrium unique; with adhesion several equilibria
// coexist and the one found depends on the start (contact_path.h).
//
// On a grid split over the ranks of a communicator (fourier_transform.h)
// heights, gaps and pressures are the rank's rows, every member is
// collective, each sum over the grid is a sum over the ranks, and the scalar
// results and errors are the same on every rank.
#pragma once

#include "contact/adhesion.h"
#include "contact/half_space.h"
#include "numerics/solver_failure.h"

#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

namespace penny
{
  // An iteration that did not reach its tolerance within its limit.
  struct ContactSolverFailure : SolverFailure
  {
    explicit ContactSolverFailure(const std::string &message)
        : SolverFailure(message, "subsection 'Contact solver' sets its Tolerance and Maximum iterations")
    {
    }
  };

  struct ContactSolverControl
  {
    unsigned int max_iterations;
    double       tolerance; // on the residual below
  };

  struct ContactSolution
  {
    // p (Pa): on the contact points the wall's reaction plus the attraction
    // -phi'(0), in the gaps the attraction -phi'(g).
    GridField pressure;
    // g >= 0 (m), zero exactly on the contact points.
    GridField    gap;
    double       mean_pressure;    // p_bar (Pa): prescribed, or the result at a prescribed mean gap
    double       mean_gap;         // <g> (m)
    double       contact_fraction; // share of grid points with g = 0
    double       energy;           // (1/2) <(g + h) K (g + h)> + <phi(g)> (J/m^2); add p_bar <g> for Pi
    unsigned int iterations;
    // Iterations of nested iteration's solves on coarser grids, weighted by
    // their grid points relative to this grid's.
    double coarse_iterations;
    // The displacement that the unbalanced traction of the gap points would
    // cause there, rms over the grid in units of the rms height (doc/contact-notes.md).
    double residual;
  };

  class HalfSpaceContact
  {
  public:
    // `transform` must outlive the object; heights on its grid (m). With
    // adhesion, w and rho must be positive and finite and the cohesive zone
    // must span at least `min_process_zone_points` grid spacings.
    HalfSpaceContact(const FourierTransform &transform, GridField heights, double E_star,
                     const Adhesion &adhesion = {});

    static constexpr double min_process_zone_points = 4;

    // Equilibrium at mean pressure p_bar (compressive positive; without
    // adhesion p_bar > 0), reached by descent from `initial_gap` (>= 0) or,
    // if empty, from full contact g = 0 (the solution whenever no gap opens;
    // with adhesion also the full-contact branch). Without adhesion such a
    // cold start first solves the problem on the grid halved in each
    // direction (heights resampled, recursively while the halved grid keeps
    // 128 points a side; to a tolerance of at least 1e-4) and starts from that
    // gap interpolated: nested iteration, after which the iterations on the
    // fine grid hardly depend on it (on a split grid the halved grids are
    // split over the same ranks). With adhesion a start from `initial_gap` is
    // nested too, while the halved grid keeps the cohesive zone over
    // min_process_zone_points spacings: the halved grid's problem is solved
    // from the gap restricted to it and its solution, interpolated, starts
    // this grid's, so that the contact edges arrive within the coarse grid's
    // error of their place instead of travelling the whole way here.
    // Throws ContactSolverFailure (one line)
    // if the residual does not fall below the tolerance within
    // max_iterations, std::runtime_error if the surfaces separate (p_bar
    // beyond the pull-off load).
    ContactSolution solve(double mean_pressure, const ContactSolverControl &control,
                          const GridField &initial_gap = {}) const;

    // Equilibrium at mean gap g_bar > 0 (displacement control), from
    // `initial_gap` scaled to that mean (with adhesion nested as in solve())
    // or, if empty or zero, from the uniform gap g_bar. It passes the load extremes (pull-off, jump into
    // contact) that end a path at prescribed mean pressure.
    ContactSolution solve_at_mean_gap(double mean_gap, const ContactSolverControl &control,
                                      const GridField &initial_gap = {}) const;

    const GridField        &heights() const { return heights_; }
    const FourierTransform &transform() const { return transform_; }
    const Adhesion         &adhesion() const { return adhesion_; }
    double                  plane_strain_modulus() const { return E_star; }

  private:
    enum class Control
    {
      mean_pressure,
      mean_gap
    };
    ContactSolution minimise(Control control, double value, const ContactSolverControl &solver,
                             GridField gap) const;
    // std::invalid_argument unless `gap` fits the grid and is finite and >= 0.
    void                           check_start(const GridField &gap) const;
    std::optional<ContactSolution> nested_start(Control control, double value,
                                                const ContactSolverControl &solver,
                                                const GridField            &initial_gap) const;
    ContactSolution solve_from(Control control, double value, const ContactSolverControl &solver,
                               GridField gap, const std::optional<ContactSolution> &start) const;

    const FourierTransform &transform_;
    GridField               heights_;
    double                  E_star;
    Adhesion                adhesion_;
    // The iteration runs in units of the rms height L of h about its mean
    // and of the traction T = E* q_min L (q_min the longest wavelength's
    // wavenumber), in which every field is of order one on any grid and
    // scale: single precision spans 1e-38 to 3e38, which SI values at the
    // ends of the input ranges left (E* |q|/2 overflowed, d.Kd underflowed).
    double                           length_unit, traction_unit;
    Adhesion                         scaled_adhesion; // w/(T L), rho/L
    GridField                        full_contact;    // p_fc/T
    FourierTransform::RealMultiplier stiffness;       // K/(E* q_min) = |q|/(2 q_min), zero at q = 0
    // Single precision, on the same grid and split, for the preconditioner C,
    // the curvature d.Kd and the updates K (g_new - g) of the traction, which
    // is recomputed in double precision before a solution is accepted.
    SingleFourierTransform                 single;
    SingleFourierTransform::RealMultiplier single_stiffness;
    SingleFourierTransform::RealMultiplier compliance; // C E* q_min = 2 q_min/|q|, 2 at q = 0
    double point_compliance; // the diagonal of C: the displacement of a point under its own unit load
    // The problem on the grid halved in each direction, for nested iteration
    // (none if the grid cannot be halved).
    std::unique_ptr<const FourierTransform> coarse_transform;
    std::unique_ptr<const HalfSpaceContact> coarse;
  };

  // One load of a sweep: the non-contact share of the grid points, the mean
  // gap and the solver's cost and residual.
  struct LoadStep
  {
    double       mean_pressure;
    double       noncontact_fraction;
    double       mean_gap;
    unsigned int iterations;
    double       residual;
  };

  // A_nc/A_0 at several mean pressures without adhesion, each a cold start
  // (nested iteration; the equilibrium is unique, and starting from the gap
  // of the next load instead took more iterations: 132 against 110 for the
  // six loads 3 ... 0.5 sqrt(V) of a 1024^2 random surface).
  std::vector<LoadStep> load_sweep(const HalfSpaceContact &contact, const std::vector<double> &mean_pressures,
                                   const ContactSolverControl &control);

} // namespace penny
