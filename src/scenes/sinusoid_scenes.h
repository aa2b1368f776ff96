// The finite-element scenes of Johnson's adhesive sinusoid as a periodic
// array of gaps (doc/theory.md, section 6; paper Fig. 1): one gap beside the
// closed-form K_I, its truncation study over the depth, the adhesionless
// (Westergaard) and adhesive (Johnson) curves, and the jump into contact with
// the critical alpha, each from FE alone and printed beside the closed forms.
#pragma once

#include "fe/periodic_gap_model.h"
#include "input/parameters.h"
#include "output/result_folder.h"
#include "scenes/penny_gap_scene.h"

#include <deal.II/base/timer.h>

#include <ostream>
#include <vector>

namespace penny
{
  // The periodic-gap model of the scene's sections with the gap half-width c (m).
  PeriodicGapModelParameters periodic_gap_model(const Parameters &parameters, double c);

  struct PeriodicGapResults
  {
    std::vector<RingResult> rings; // radii in units of min(c, lambda/2 - c)
    double                  exact_stress_intensity_factor;
    // The unit tensions cos(2 pi x/lambda) Pa and 1 Pa on the last ring (Pa m^1/2).
    double       cosine_sif, exact_cosine_sif;
    double       uniform_sif, exact_uniform_sif;
    unsigned int n_cells;
    unsigned int n_dofs;
    double       relative_residual; // the largest of the three solves
    std::string  solver;
  };

  // One factorisation, three right-hand sides: the load, the unit cosine and
  // the unit uniform tension (the reference of the signed K_I).
  PeriodicGapResults solve_periodic_gap(const PeriodicGapModelParameters &model, const BuecknerTension &load,
                                        const std::vector<double> &ring_radii, dealii::TimerOutput &timer);

  PeriodicGapResults run_periodic_gap_scene(const Parameters &parameters, const ResultFolder &results,
                                            std::ostream &log);

  struct DepthStudyRow
  {
    double       depth; // D/lambda
    unsigned int n_dofs;
    double       error, cosine_error, uniform_error; // relative, last ring
  };
  std::vector<DepthStudyRow> run_periodic_gap_depth_scene(const Parameters   &parameters,
                                                          const ResultFolder &results, std::ostream &log);

  struct CurveErrors
  {
    double       largest_load_error;          // |p_bar/p* FE - closed form|
    double       largest_contact_ratio_error; // |a/lambda FE - closed form|; westergaard-curve only
    unsigned int n_solves;
  };
  CurveErrors run_westergaard_curve_scene(const Parameters &parameters, const ResultFolder &results,
                                          std::ostream &log);
  CurveErrors run_johnson_curves_scene(const Parameters &parameters, const ResultFolder &results,
                                       std::ostream &log);

  struct JumpIntoContactResults
  {
    double       critical_alpha, critical_contact_ratio; // FE
    double       largest_jump_error;                     // |p_bar_max/p* FE - Johnson|
    unsigned int n_solves;
  };
  JumpIntoContactResults run_jump_into_contact_scene(const Parameters   &parameters,
                                                     const ResultFolder &results, std::ostream &log);
} // namespace penny
