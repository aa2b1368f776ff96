// The finite-element model of one gap of a periodic array: Johnson's
// sinusoid pressed into full contact, seen as a row of gaps of half-width c
// and period lambda (doc/theory.md, section 6). Plane strain on one half
// period 0 <= x <= lambda/2 of the solid 0 <= z <= D above the crack plane:
// u_x = 0 on both symmetry lines x = 0 (gap centre) and x = lambda/2 (contact
// centre), u_z = 0 on the ligament z = 0, x > c, the Bueckner tension on the
// gap face z = 0, x < c, and the far side z = D free (the face load is
// balanced by the ligament, and the perturbation of the mean stress decays
// like exp(-2 pi z/lambda)). The mesh is a quadtree graded towards the tip
// (fe/tip_graded_mesh.h) on a parallel::shared::Triangulation.
#pragma once

#include "fe/linear_elastic_system.h"

#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>

#include <cmath>

namespace penny
{
  // What a periodic-gap model is built from.
  // The degree is graded in tip levels below min(c, lambda/2 - c).
  struct PeriodicGapModelParameters : ElasticModelParameters
  {
    double       wavelength;       // lambda (m)
    double       depth;            // D (m)
    double       gap_half_width;   // c (m), 0 < c < lambda/2
    unsigned int tip_levels;       // tip cells are min(c, lambda/2 - c)/2^levels wide
    double       grading_distance; // in cell widths (fe/tip_graded_mesh.h)

    // The same model with the gap half-width c.
    PeriodicGapModelParameters with_gap_half_width(double c) const;

    // min(c, lambda/2 - c): the distance from the tip to the nearer symmetry
    // line, the length that scales the mesh and the J-integral rings (m).
    double tip_distance() const;
  };

  // The Bueckner tension on the gap face, t(x) = p* cos(2 pi x/lambda) - p_bar:
  // the full-contact pressure p_bar - p* cos(2 pi x/lambda) of the sinusoid
  // with its sign reversed; positive t opens the gap.
  struct BuecknerTension
  {
    double wavelength;    // lambda (m)
    double peak_tension;  // p* (Pa)
    double mean_pressure; // p_bar (Pa)

    // The unit load cases: t = cos(2 pi x/lambda) Pa, and t = 1 Pa uniform.
    static BuecknerTension unit_cosine(const double wavelength) { return {wavelength, 1, 0}; }
    static BuecknerTension unit_uniform(const double wavelength) { return {wavelength, 0, -1}; }

    double operator()(const dealii::Point<2> &x) const
    {
      return peak_tension * std::cos(2 * M_PI * x[0] / wavelength) - mean_pressure;
    }
  };

  class PeriodicGapModel
  {
  public:
    // Builds the mesh, the constraints and the factorised stiffness matrix.
    PeriodicGapModel(const PeriodicGapModelParameters &parameters, dealii::TimerOutput &timer);

    // The displacement under the face tension t. Throws if the solve misses
    // the tolerance or produces NaN/Inf.
    DisplacementVector solve(const BuecknerTension &t);

    const LinearElasticSystem<PlaneStrain> &get_system() const { return system; }
    const PeriodicGapModelParameters       &get_parameters() const { return parameters; }
    dealii::Point<2>                        crack_tip() const { return {parameters.gap_half_width, 0}; }

  private:
    const PeriodicGapModelParameters           parameters;
    dealii::parallel::shared::Triangulation<2> triangulation;
    LinearElasticSystem<PlaneStrain>           system;
  };
} // namespace penny
