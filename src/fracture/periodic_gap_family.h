// The family of periodic-gap models indexed by the gap half-width c: for each
// c the scene's model (wavelength, depth, mesh, degree) is rebuilt with its
// tip at (c, 0), on one MPI rank, assembled, factorised and solved for the
// two unit loads. K_I is linear in the load, so every Bueckner tension is a
// combination: K_I[p* cos(2 pi x/lambda) - p_bar] = p* K_cosine - p_bar K_uniform.
// The searches over c (fracture/periodic_searches.h) call it; every
// evaluation is a full FE solve. A batch of half-widths is spread over the
// ranks of a communicator, and every rank receives every result (as for the
// penny gaps, fracture/gap_family.h).
#pragma once

#include "fe/periodic_gap_model.h"

#include <deal.II/base/timer.h>

#include <vector>

namespace penny
{
  // K_I (Pa m^1/2) of the unit tensions t = cos(2 pi x/lambda) Pa and t = 1 Pa.
  struct SinusoidUnitSifs
  {
    double cosine;  // signed, from the interaction form
    double uniform; // |K_I|, the reference of the interaction form
  };

  class PeriodicGapFamily
  {
  public:
    // `ring_radius`: the J-integral ring, in units of min(c, lambda/2 - c).
    PeriodicGapFamily(const PeriodicGapModelParameters &model, double ring_radius,
                      dealii::TimerOutput &timer);

    // Both unit load cases at each half-width, from one factorisation per
    // half-width; the models are spread over `ranks` (collective on them).
    std::vector<SinusoidUnitSifs> unit_load_sifs(const std::vector<double> &half_widths, MPI_Comm ranks);

    double wavelength() const { return model.wavelength; }
    // The FE solves of this rank.
    unsigned int n_solves() const { return solves; }

  private:
    SinusoidUnitSifs solve(double c);

    const PeriodicGapModelParameters model;
    const double                     ring_radius;
    dealii::TimerOutput             &timer;
    unsigned int                     solves = 0;
  };
} // namespace penny
