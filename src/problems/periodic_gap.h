// The periodic-gap problem of Johnson's sinusoid (doc/theory.md, section 6):
// the subsections its model and its Bueckner tension are read from, the
// solve-and-measure routine of one gap, and the set-up of the scenes that
// search over the gap's half-width.
#pragma once

#include "fe/periodic_gap_model.h"
#include "input/entries.h"
#include "output/result_folder.h"
#include "output/table.h"
#include "problems/penny_gap.h"
#include "searches/gap_family.h"

#include <deal.II/base/timer.h>

#include <string>
#include <vector>

namespace penny
{
  // The thinnest solid the periodic model takes, in wavelengths: thinner
  // strips need ever more coarse cells (about lambda/D of them), and below
  // 0.01 lambda the direct solve loses the digits of its residual (1e-9 at
  // 0.005 lambda, 2.5e-6 at 0.001 lambda).
  constexpr double smallest_depth = 0.05;

  // What every periodic-gap scene reads: Material, Periodic gap (the
  // wavelength, depth, mesh and J-integral rings, in units of
  // min(c, lambda/2 - c)), Finite element and Linear solver. The gap
  // half-width is the scene's. A scene that sets the depth itself (the depth
  // study) reads no Depth D and checks the rings against its own depths.
  struct PeriodicGapInput
  {
    PeriodicGapModelParameters model;
    std::vector<double>        ring_radii;

    void sections(Sections &sections, bool read_depth = true);
  };

  // One gap and its Bueckner tension t = p* cos(2 pi x/lambda) - p_bar.
  struct GapAndLoad
  {
    double gap_ratio;    // c/lambda, in (0, 1/2)
    double peak_tension; // p* (Pa)
    double load_ratio;   // p_bar/p*
  };

  // Gap and load.
  void gap_and_load_section(Sections &sections, GapAndLoad &gap);

  struct PeriodicGapMeasurement
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
  // the unit uniform tension (the reference of the signed K_I); with
  // `fields`, the displacement of the load written there.
  PeriodicGapMeasurement solve_periodic_gap(const PeriodicGapModelParameters &model,
                                            const BuecknerTension            &load,
                                            const std::vector<double> &ring_radii, dealii::TimerOutput &timer,
                                            const ResultFolder *fields = nullptr);

  // What the scenes that search over the half-width share: a timer of the
  // phases and the family of models of the input (J on its last ring). Every
  // model lives on one rank; a search of its own shares its models out over
  // all ranks, and a sweep of independent searches gives each rank its share
  // of them, each search on its rank alone.
  struct PeriodicGapSearch
  {
    explicit PeriodicGapSearch(const PeriodicGapInput &periodic);
    PeriodicGapSearch(const PeriodicGapSearch &) = delete;

    // The closing rows of a search's summary: the FE solves of all ranks and
    // the phase times (collective).
    void add_cost(Table &summary) const;

    dealii::TimerOutput timer;
    PeriodicGapFamily   gaps;
  };
} // namespace penny
