// Adhesive contact of sampled random surfaces near full contact, set against
// the paper's adhesive claims (doc/contact-notes.md, section 6a): the
// non-contact area of one realisation of a power-law surface at several
// loads, by the adhesive boundary-element solver at several cohesive zones
// (for the extrapolation to the JKR limit), beside the adhesionless solver at
// the same loads and at the loads shifted by p0, and the isolated-gap law
// summed over the realisation's own summits.
#pragma once

#include "contact/half_space_contact.h"
#include "problems/contact_solver.h"
#include "statistics/roughness.h"
#include "statistics/summit_statistics.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace penny
{
  // The least power of two at or above x and `smallest` (a power of two): a grid's points a side.
  unsigned int power_of_two_at_least(double x, unsigned int smallest = 1);

  // One power law and its adhesion, and how its realisations are solved.
  struct AdhesiveRandomSurfaces
  {
    PowerSpectrum        spectrum;
    double               E_star;             // plane-strain modulus (Pa)
    double               critical_intensity; // K_Ic = sqrt(2 E* w) (Pa m^1/2)
    double               sqrt_V;             // pressure spread of the sampled lattice (Pa)
    double               p0;                 // psi (K_Ic^4/R_p)^(1/5), R_p of the lattice's summits (Pa)
    std::vector<double>  mean_pressures;     // p_bar/sqrt(V), increasing
    double               first_contact;      // p_s/sqrt(V) > 0
    CohesiveZones        zones;              // l_pz/lambda1 (lambda1 = 2 pi/(zeta q0)), decreasing
    ContactSolverControl control;

    // Points per side of the grid at cohesive zone `zone` (l_pz/lambda1): the
    // power of two with at least points_per_zone points over l_pz.
    unsigned int grid_points(double zone) const;
  };

  // What one realisation gives, per load (index j): the adhesive A_nc/A_0
  // (share of the points whose gap exceeds the range rho) at each cohesive
  // zone (index z) on two branches, the adhesionless A_nc/A_0 at p_bar and
  // at p_bar + p0 on the finest grid, and the isolated-gap law with adhesion
  // over the realisation's summits; the solver's iterations. The branches:
  // `loading`, the path from first contact (without adhesion at p_s, then
  // adhesion, then the loads in increasing order, each solve started from
  // the previous state); `switched_on`, at each load the adhesionless
  // equilibrium with adhesion switched on (every summit whose tension opens
  // a gap without adhesion starts with one: the state the isolated-gap law
  // sums; NaN at p_bar = 0, where there is no contact without adhesion).
  struct RealisationAreas
  {
    std::vector<std::vector<double>> loading, switched_on; // [z][j]
    std::vector<double>              adhesionless, shifted, isolated_gaps;
    double                           iterations;

    std::vector<double>     pack() const;
    static RealisationAreas unpack(const std::vector<double> &row, std::size_t n_zones, std::size_t n_loads);
  };

  // The fields of one realisation on the finest zone's grid, for ParaView:
  // heights (m), the full-contact pressure less its mean (Pa), and per load
  // the gap without adhesion (none at p_bar = 0, where there is no contact)
  // and the gap and the pressure (Pa; tension negative) with adhesion on the
  // loading branch.
  struct RealisationFields
  {
    PeriodicGrid           grid;
    GridField              heights, full_contact;
    std::vector<GridField> adhesionless_gaps, adhesive_gaps, adhesive_pressures;
  };

  // The realisation of `seed`, resampled onto the grid of each cohesive zone
  // (its spectrum is band-limited, so every grid holds the same surface);
  // its fields into `fields` if given. Throws std::runtime_error if the
  // surfaces separate.
  RealisationAreas solve_realisation(const AdhesiveRandomSurfaces &surfaces, std::uint64_t seed,
                                     RealisationFields *fields = nullptr);

  // The same for any band-limited surface: `heights` on the grid of `base`,
  // resampled onto zone_grid(l_pz/lambda1) for each cohesive zone, lambda1 =
  // `shortest` (m), the surfaces' spectrum unused (a measured surface).
  RealisationAreas solve_surface(const AdhesiveRandomSurfaces &surfaces, const FourierTransform &base,
                                 const GridField &heights, double shortest,
                                 const std::function<PeriodicGrid(double zone)> &zone_grid,
                                 RealisationFields                              *fields = nullptr);

  // The JKR limit of one branch at one load over realisations: the mean
  // area at each cohesive zone, the leading order the last three means show
  // (1 if they show none in (1/4, 4), or with two zones), each realisation
  // extrapolated to l_pz -> 0 at that order (Richardson) and the mean of
  // those limits with its standard error, and the extrapolation's own error
  // estimate on the means.
  struct JkrLimit
  {
    std::vector<double> means;
    double              order;
    Estimate            value;
    double              extrapolation_error;
  };
  JkrLimit jkr_limit(const std::vector<RealisationAreas> &areas,
                     std::vector<std::vector<double>> RealisationAreas::*branch, std::size_t load,
                     const std::vector<double> &zones);
} // namespace penny
