#include "problems/adhesive_random_surfaces.h"

#include "contact/extrapolation.h"
#include "contact/half_space.h"
#include "fourier/grid_resampling.h"
#include "problems/random_surfaces.h"
#include "statistics/random_field.h"
#include "statistics/summit_statistics.h"

#include <cmath>

namespace penny
{
  namespace
  {
    // Share of the grid points whose gap exceeds `level`.
    double share_above(const GridField &gap, const double level)
    {
      std::size_t count = 0;
      for (const double g : gap)
        count += g > level;
      return double(count) / gap.size();
    }

  } // namespace

  unsigned int power_of_two_at_least(const double x, const unsigned int smallest)
  {
    unsigned int p = smallest;
    while (p < x)
      p *= 2;
    return p;
  }

  unsigned int AdhesiveRandomSurfaces::grid_points(const double zone) const
  {
    const double zeta = spectrum.wavenumbers.back() / spectrum.wavenumbers.front();
    return power_of_two_at_least(zones.points_per_zone * zeta / zone, 16);
  }

  std::vector<double> RealisationAreas::pack() const
  {
    std::vector<double> row;
    for (const auto *branch : {&loading, &switched_on})
      for (const auto &at_zone : *branch)
        row.insert(row.end(), at_zone.begin(), at_zone.end());
    for (const auto *values : {&adhesionless, &shifted, &isolated_gaps})
      row.insert(row.end(), values->begin(), values->end());
    row.push_back(iterations);
    return row;
  }

  RealisationAreas RealisationAreas::unpack(const std::vector<double> &row, const std::size_t n_zones,
                                            const std::size_t n_loads)
  {
    RealisationAreas areas;
    auto             next = row.begin();
    const auto       take = [&]() {
      std::vector<double> values(next, next + n_loads);
      next += n_loads;
      return values;
    };
    for (auto *branch : {&areas.loading, &areas.switched_on})
      for (std::size_t z = 0; z < n_zones; ++z)
        branch->push_back(take());
    areas.adhesionless  = take();
    areas.shifted       = take();
    areas.isolated_gaps = take();
    areas.iterations    = *next;
    return areas;
  }

  RealisationAreas solve_realisation(const AdhesiveRandomSurfaces &surfaces, const std::uint64_t seed,
                                     RealisationFields *fields)
  {
    const double q0 = surfaces.spectrum.wavenumbers.front(), q1 = surfaces.spectrum.wavenumbers.back();
    const double period = 2 * M_PI / q0, shortest = 2 * M_PI / q1;
    // The surface on a grid that holds every mode of the spectrum, then on each zone's.
    const FourierTransform base(square_grid(power_of_two_at_least(4 * q1 / q0, 16), period));
    return solve_surface(
        surfaces, base, gaussian_field(base, surfaces.spectrum, seed), shortest,
        [&](const double zone) { return square_grid(surfaces.grid_points(zone), period); }, fields);
  }

  RealisationAreas solve_surface(const AdhesiveRandomSurfaces &surfaces, const FourierTransform &base,
                                 const GridField &heights, const double shortest,
                                 const std::function<PeriodicGrid(double zone)> &zone_grid,
                                 RealisationFields                              *fields)
  {
    const double work = surfaces.critical_intensity * surfaces.critical_intensity / (2 * surfaces.E_star);
    std::vector<double> loads, shifted_loads;
    for (const double p : surfaces.mean_pressures)
      {
        loads.push_back(p * surfaces.sqrt_V);
        shifted_loads.push_back(p * surfaces.sqrt_V + surfaces.p0);
      }

    RealisationAreas areas;
    areas.iterations = 0;
    for (std::size_t z = 0; z < surfaces.zones.lengths.size(); ++z)
      {
        const FourierTransform transform(zone_grid(surfaces.zones.lengths[z]));
        const GridField        h = resampled(base, transform, heights);
        const double range = std::sqrt(M_PI * work * surfaces.zones.lengths[z] * shortest / surfaces.E_star);
        const HalfSpaceContact adhesionless(transform, h, surfaces.E_star);
        const HalfSpaceContact adhesive(transform, h, surfaces.E_star, Adhesion{work, range});
        if (z == 0)
          {
            // Summits of the tension -p_fc, on the coarsest of the zones' grids.
            const std::vector<Summit> summits = tension_summits(transform, h, surfaces.E_star).summits;
            for (const double p_bar : loads)
              areas.isolated_gaps.push_back(
                  sampled_gap_area(summits, transform.grid().area(), p_bar, surfaces.critical_intensity));
          }

        // The loading path from first contact, and at each load the
        // adhesionless state with adhesion switched on.
        ContactSolution state =
            adhesionless.solve(surfaces.first_contact * surfaces.sqrt_V, surfaces.control);
        areas.iterations += state.iterations;
        std::vector<double> on_path, switched_on;
        const bool          finest = z + 1 == surfaces.zones.lengths.size();
        RealisationFields  *keep   = finest ? fields : nullptr;
        if (keep)
          *keep = {transform.grid(), h, full_contact_pressure(transform, h, surfaces.E_star), {}, {}, {}};
        for (const double p_bar : loads)
          {
            state = adhesive.solve(p_bar, surfaces.control, state.gap);
            on_path.push_back(share_above(state.gap, range));
            areas.iterations += state.iterations;
            if (keep)
              {
                keep->adhesive_gaps.push_back(state.gap);
                keep->adhesive_pressures.push_back(state.pressure);
              }
            if (!(p_bar > 0))
              {
                // No contact without adhesion: nothing to switch it on in.
                switched_on.push_back(std::nan(""));
                if (finest)
                  areas.adhesionless.push_back(1);
                continue;
              }
            const ContactSolution free = adhesionless.solve(p_bar, surfaces.control);
            const ContactSolution on   = adhesive.solve(p_bar, surfaces.control, free.gap);
            switched_on.push_back(share_above(on.gap, range));
            areas.iterations += free.iterations + on.iterations;
            if (keep)
              keep->adhesionless_gaps.push_back(free.gap);
            if (finest)
              areas.adhesionless.push_back(share_above(free.gap, 0));
          }
        areas.loading.push_back(on_path);
        areas.switched_on.push_back(switched_on);
        if (finest)
          for (const double p_bar : shifted_loads)
            {
              const ContactSolution free = adhesionless.solve(p_bar, surfaces.control);
              areas.shifted.push_back(share_above(free.gap, 0));
              areas.iterations += free.iterations;
            }
      }
    return areas;
  }

  JkrLimit jkr_limit(const std::vector<RealisationAreas> &areas,
                     std::vector<std::vector<double>> RealisationAreas::*branch, const std::size_t load,
                     const std::vector<double> &zones)
  {
    const std::size_t                n = zones.size();
    std::vector<std::vector<double>> at_zones; // [realisation][zone]
    JkrLimit                         limit{std::vector<double>(n, 0), 1, {}, 0};
    for (const RealisationAreas &a : areas)
      {
        at_zones.emplace_back();
        for (std::size_t z = 0; z < n; ++z)
          {
            at_zones.back().push_back((a.*branch)[z][load]);
            limit.means[z] += at_zones.back().back() / areas.size();
          }
      }
    if (n > 2)
      {
        const double order = observed_order(limit.means[n - 3], limit.means[n - 2], limit.means[n - 1],
                                            zones[n - 2] / zones[n - 1]);
        if (order > 0.25 && order < 4)
          limit.order = order;
      }
    std::vector<std::vector<double>> limits;
    for (const auto &values : at_zones)
      limits.push_back({extrapolate(zones, values, {limit.order}).value});
    limit.value               = mean_over(limits, 0);
    limit.extrapolation_error = extrapolate(zones, limit.means, {limit.order}).error;
    return limit;
  }
} // namespace penny
