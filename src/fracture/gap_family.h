// The family of penny-gap models indexed by the gap radius c: for each c the
// scene's model is rebuilt with its domain and mesh scaled to c (R/c and H/c
// kept), assembled, factorised and solved. Root finders and minimisers over c
// call it; every evaluation is a full FE solve.
#pragma once

#include "fe/face_load.h"
#include "fe/penny_gap_model.h"

#include <deal.II/base/timer.h>

#include <functional>

namespace penny
{
  // K_I (Pa m^1/2) of the unit load cases p = 1 Pa and p = r^2 (Pa/m^2) on a gap
  // of radius c. Any parabola is a combination:
  // K_I[P (1 - r^2/a^2)] = P K_uniform - (P/a^2) K_quadratic.
  struct UnitLoadSifs
  {
    double uniform;
    double quadratic;
  };

  class GapFamily
  {
  public:
    // `ring_radius`: the J-integral ring, in units of c.
    GapFamily(const PennyGapModelParameters &model, double ring_radius, dealii::TimerOutput &timer);

    // Signed K_I of the parabola P (1 - r^2/a^2) on a gap of radius c: the
    // interaction form with the unit-pressure solution as reference.
    double parabolic_stress_intensity_factor(double c, double P, double a);

    // Both unit load cases from one factorisation.
    UnitLoadSifs unit_load_sifs(double c);

    unsigned int n_solves() const { return solves; }

    // `observer(c)` is called after each evaluation, with its gap radius.
    void observe(std::function<void(double c)> observer) { evaluated = std::move(observer); }

  private:
    // |K_I| of unit pressure (the reference) and the signed K_I of `load`,
    // both from one factorisation of the model built for radius c.
    struct SifsWithReference
    {
      double reference;
      double load;
    };
    SifsWithReference solve_with_reference(double c, const FaceLoad &load);

    const PennyGapModelParameters model;
    const double                  ring_radius;
    dealii::TimerOutput          &timer;
    unsigned int                  solves = 0;
    std::function<void(double)>   evaluated;
  };
} // namespace penny
