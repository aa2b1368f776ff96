// The family of periodic-gap models indexed by the gap half-width c: for each
// c the scene's model (wavelength, depth, mesh, degree) is rebuilt with its
// tip at (c, 0), assembled, factorised and solved for the two unit loads.
// K_I is linear in the load, so every Bueckner tension is a combination:
// K_I[p* cos(2 pi x/lambda) - p_bar] = p* K_cosine - p_bar K_uniform.
// The searches over c (fracture/periodic_searches.h) call it; every
// evaluation is a full FE solve.
#pragma once

#include "fe/periodic_gap_model.h"

#include <deal.II/base/timer.h>

namespace penny
{
  // K_I (Pa m^1/2) of the unit tensions t = cos(2 pi x/lambda) Pa and t = 1 Pa.
  struct SinusoidUnitSifs
  {
    double cosine;
    double uniform;
  };

  class PeriodicGapFamily
  {
  public:
    // `ring_radius`: the J-integral ring, in units of min(c, lambda/2 - c).
    PeriodicGapFamily(const PeriodicGapModelParameters &model, double ring_radius,
                      dealii::TimerOutput &timer);

    // Both unit load cases from one factorisation of the model built for c:
    // |K_I| of the uniform tension (the reference), and the signed K_I of
    // the cosine from the interaction form.
    SinusoidUnitSifs unit_load_sifs(double c);

    double       wavelength() const { return model.wavelength; }
    unsigned int n_solves() const { return solves; }

  private:
    const PeriodicGapModelParameters model;
    const double                     ring_radius;
    dealii::TimerOutput             &timer;
    unsigned int                     solves = 0;
  };
} // namespace penny
