// Parameters of the periodic-gap model of Johnson's sinusoid and of its
// scenes (doc/theory.md, section 6): the model, the one gap and its load, and
// one subsection per scene for the entries that scene alone reads.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace penny
{
  // The model every sinusoid FE scene solves.
  struct PeriodicGapParameters
  {
    double              wavelength;       // lambda (m)
    double              depth;            // D/lambda
    unsigned int        tip_levels;       // tip cells min(c, lambda/2 - c)/2^levels wide
    double              grading_distance; // in cell widths
    std::vector<double> ring_radii;       // in units of min(c, lambda/2 - c)

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // periodic-gap and periodic-gap-depth: the gap and its Bueckner tension.
  struct GapAndLoadParameters
  {
    double gap_ratio;    // c/lambda, in (0, 1/2)
    double peak_tension; // p* (Pa)
    double load_ratio;   // p_bar/p*

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // periodic-gap-depth: the truncation study.
  struct DepthStudyParameters
  {
    std::vector<double> depths; // D/lambda

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // westergaard-curve: loads p_bar/p* = i/(n + 1), i = 1 ... n.
  struct WestergaardCurveParameters
  {
    unsigned int n_points;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // johnson-curves: contact half-widths a/lambda = i/(2 (n + 1)), i = 1 ... n.
  struct JohnsonCurvesParameters
  {
    std::vector<double> alphas;
    unsigned int        n_points;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  // jump-into-contact: alphas evenly spaced in log(alpha).
  struct JumpIntoContactParameters
  {
    double       smallest_alpha, largest_alpha;
    unsigned int n_alphas;

    // The i-th of the n_alphas.
    double alpha(unsigned int i) const;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace penny
