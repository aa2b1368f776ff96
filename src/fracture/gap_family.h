// The family of penny-gap models indexed by the gap radius c: for each c the
// scene's model is rebuilt with its domain and mesh scaled to c (R/c and H/c
// kept), on one MPI rank, assembled, factorised and solved for the two unit
// loads. Root finders and minimisers over c call it; every evaluation is a
// full FE solve. A batch of radii is spread over the ranks of a communicator
// and every rank receives every result: a search on all ranks solves the
// pair of radii of a difference quotient on two ranks at once, a search
// inside one piece of a sweep (on MPI_COMM_SELF) solves its radii in turn.
#pragma once

#include "fe/face_load.h"
#include "fe/penny_gap_model.h"

#include <deal.II/base/timer.h>

#include <functional>
#include <vector>

namespace penny
{
  // K_I (Pa m^1/2) of the unit load cases p = 1 Pa and p = r^2 (Pa/m^2) on a gap
  // of radius c. Any parabola is a combination:
  // K_I[P (1 - r^2/a^2)] = P K_uniform - (P/a^2) K_quadratic.
  struct UnitLoadSifs
  {
    double uniform;   // |K_I|, the reference of the interaction form
    double quadratic; // signed, from the interaction form
  };

  class GapFamily
  {
  public:
    // `ring_radius`: the J-integral ring, in units of c.
    GapFamily(const PennyGapModelParameters &model, double ring_radius, dealii::TimerOutput &timer);

    // Both unit load cases at each radius, from one factorisation per
    // radius; the models are spread over `ranks` (collective on them).
    std::vector<UnitLoadSifs> unit_load_sifs(const std::vector<double> &radii, MPI_Comm ranks);

    // The FE solves of this rank.
    unsigned int n_solves() const { return solves; }

    // `observer(c)` is called after each model this rank solves, with its gap radius.
    void observe(std::function<void(double c)> observer) { evaluated = std::move(observer); }

  private:
    UnitLoadSifs solve(double c);

    const PennyGapModelParameters model;
    const double                  ring_radius;
    dealii::TimerOutput          &timer;
    unsigned int                  solves = 0;
    std::function<void(double)>   evaluated;
  };
} // namespace penny
