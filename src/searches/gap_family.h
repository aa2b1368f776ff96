// Families of FE models of one gap indexed by its size: the penny gap's radius
// c and the periodic gap's half-width c. For each size the family's model is
// rebuilt with its mesh scaled to that size, on one MPI rank, assembled,
// factorised and solved for two unit loads, and the K_I of each comes from
// the domain integral on one ring. K_I is linear in the load, so the searches
// (searches/gap_searches.h, searches/periodic_searches.h) combine the two for
// any load; every evaluation is a full FE solve. A batch of sizes is spread
// over the ranks of a communicator and every rank receives every result: a
// search on all ranks solves the pair of sizes of a difference quotient on
// two ranks at once, a search inside one piece of a sweep (on MPI_COMM_SELF)
// solves its sizes in turn.
#pragma once

#include "fe/penny_gap_model.h"
#include "fe/periodic_gap_model.h"
#include "parallel/spread_over_ranks.h"

#include <deal.II/base/timer.h>

#include <functional>
#include <vector>

namespace penny
{
  // K_I (Pa m^1/2) of the penny gap's unit loads p = 1 Pa and p = r^2
  // (Pa/m^2). Any parabola is a combination:
  // K_I[P (1 - r^2/a^2)] = P K_uniform - (P/a^2) K_quadratic.
  struct PennyUnitSifs
  {
    double uniform;   // |K_I|, the reference of the interaction form
    double quadratic; // signed, from the interaction form
  };

  // The penny gaps of radius c: `model` scaled to c (R/c and H/c kept, so the
  // meshes are exactly similar), J on the ring of radius ring_radius c.
  struct PennyGaps
  {
    using Sifs = PennyUnitSifs;

    PennyGapModelParameters model;
    double                  ring_radius;

    Sifs solve(double c, dealii::TimerOutput &timer) const;
  };

  // K_I (Pa m^1/2) of the periodic gap's unit tensions t = cos(2 pi x/lambda)
  // Pa and t = 1 Pa. Every Bueckner tension is a combination:
  // K_I[p* cos(2 pi x/lambda) - p_bar] = p* K_cosine - p_bar K_uniform.
  struct SinusoidUnitSifs
  {
    double cosine;  // signed, from the interaction form
    double uniform; // |K_I|, the reference of the interaction form
  };

  // The periodic gaps of half-width c: `model` with its tip at (c, 0), J on
  // the ring of radius ring_radius min(c, lambda/2 - c).
  struct PeriodicGaps
  {
    using Sifs = SinusoidUnitSifs;

    PeriodicGapModelParameters model;
    double                     ring_radius;

    Sifs solve(double c, dealii::TimerOutput &timer) const;
  };

  template <typename Gaps> class GapFamily
  {
  public:
    using Sifs = typename Gaps::Sifs;

    // Every model of the family lives on one rank.
    GapFamily(Gaps gaps, dealii::TimerOutput &timer) : gaps(std::move(gaps)), timer(timer)
    {
      this->gaps.model.communicator = MPI_COMM_SELF;
    }

    // Both unit loads at each size; the models are spread over `ranks`
    // (collective on them).
    std::vector<Sifs> unit_load_sifs(const std::vector<double> &sizes, const MPI_Comm ranks)
    {
      return spread_over_ranks<Sifs>(ranks, sizes.size(), [&](const unsigned int i) {
        const Sifs K = gaps.solve(sizes[i], timer);
        solves += 2;
        if (evaluated)
          evaluated(sizes[i]);
        return K;
      });
    }

    // The FE solves of this rank.
    unsigned int n_solves() const { return solves; }

    // `observer(size)` is called after each model this rank solves.
    void observe(std::function<void(double size)> observer) { evaluated = std::move(observer); }

    const Gaps &members() const { return gaps; }

  private:
    Gaps                        gaps;
    dealii::TimerOutput        &timer;
    unsigned int                solves = 0;
    std::function<void(double)> evaluated;
  };

  using PennyGapFamily    = GapFamily<PennyGaps>;
  using PeriodicGapFamily = GapFamily<PeriodicGaps>;
} // namespace penny
