// Johnson's sinusoid from FE solves alone: roots and extremes over the gap
// half-width c of a PeriodicGapFamily. Closed-form values never enter a
// search; the brackets come from the half period and, for the jump into
// contact, from the adhesion length lambda alpha^(2/5). `ranks` share a
// search's FE models: all ranks for a search of its own, MPI_COMM_SELF for a
// search inside one piece of a sweep. The result is the same on any number
// of ranks.
#pragma once

#include "searches/gap_family.h"

namespace penny
{
  // p_bar/p* at which the FE K_I of the gap equals K_Ic = alpha p* sqrt(lambda):
  // the root in p_bar of the linear K_I = p* K_cosine - p_bar K_uniform,
  // p_bar/p* = [K_cosine - alpha sqrt(lambda)]/K_uniform.
  double fe_johnson_load(const SinusoidUnitSifs &K, double wavelength, double alpha);

  // Adhesionless contact: the contact half-width a = lambda/2 - c (m) where
  // the FE K_I of the load p_bar/p* in (0, 1) vanishes, the root over c of
  // K_cosine(c)/K_uniform(c) - p_bar/p* (TOMS 748).
  double fe_westergaard_contact_half_width(PeriodicGapFamily &gaps, double load_ratio, MPI_Comm ranks);

  struct FeLoadExtremum
  {
    double contact_half_width; // a (m)
    double load_ratio;         // p_bar/p*
  };

  // The jump into full contact: the maximum over c of fe_johnson_load (the
  // root of its difference quotient, fracture/root_finding.h), searched for
  // c in [l/16, min(l/2, lambda/4)], l = lambda alpha^(2/5).
  FeLoadExtremum fe_jump_into_contact(PeriodicGapFamily &gaps, double alpha, MPI_Comm ranks);

  struct FeCriticalAdhesion
  {
    double contact_half_width; // a (m) of the gap that closes last at zero load
    double alpha;
  };

  // The alpha at which the maximum over c of p_bar/p* is zero. With K_uniform > 0,
  // p_bar(c) <= 0 for every c exactly when alpha sqrt(lambda) >= K_cosine(c)
  // for every c, so alpha_c = max over c of K_cosine(c)/sqrt(lambda) (as
  // above, c in [lambda/16, 7 lambda/16]).
  FeCriticalAdhesion fe_critical_alpha(PeriodicGapFamily &gaps, MPI_Comm ranks);
} // namespace penny
