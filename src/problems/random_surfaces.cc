#include "problems/random_surfaces.h"

#include "input/input_error.h"
#include "parallel/memory_budget.h"
#include "problems/rough_surface.h"
#include "problems/solid.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace penny
{
  void RandomSurfaceInput::sections(Sections &sections, const bool one_spectrum,
                                    const unsigned int fewest_realisations)
  {
    material_section(sections, material);
    roughness_section(sections, roughness, one_spectrum);
    sections.subsection("Random surfaces", [&](Entries &entries) {
      entries.integer("Grid points per side", surfaces.n_points, 256u, 8u, 65536u,
                      "N of the periodic N x N grid; even. Units: none.");
      entries.require(surfaces.n_points % 2 == 0, "Grid points per side", surfaces.n_points,
                      "even numbers 8 ... 65536");
      entries.number(
          "Period L/lambda0", surfaces.period, 1, at_least(1),
          "Side of the periodic square in units of the longest wavelength lambda0 = 2 pi/q0 (Roughness). "
          "The shortest wavelength lambda0/zeta must span at least 4 grid points. Units: none.");
      entries.integer("Realisations", surfaces.n_realisations, 16u, fewest_realisations, 1000000u,
                      "Independent surfaces, spread over the MPI ranks. Units: none.");
      entries.integer(
          "Seed", surfaces.seed, std::uint64_t(1), std::uint64_t(0),
          std::uint64_t(std::numeric_limits<long long>::max()),
          "Realisation k uses the seed realisation_seed(Seed, k): the same surfaces on any number of "
          "ranks. Units: none.");
    });
  }

  void SampledPowerLaws::entries(Entries &entries, const std::vector<double> &default_magnifications,
                                 const Range &magnification_range)
  {
    entries.increasing_numbers(
        "Hurst exponents", hurst_exponents, {0.25, 0.5, 0.75}, 1, interval("[)", smallest_hurst_exponent, 1),
        "One power law per H and zeta (replacing Roughness/Hurst exponent H). Units: none.");
    entries.increasing_numbers(
        "Magnifications", magnifications, default_magnifications, 1, magnification_range,
        "zeta of each power law (replacing Roughness/Magnification zeta). Units: none.");
  }

  PeriodicGrid surface_grid(const RandomSurfaceParameters &surfaces, const PowerSpectrum &spectrum)
  {
    const double q0 = spectrum.wavenumbers.front(), zeta = spectrum.wavenumbers.back() / q0;
    const double points_per_shortest_wavelength = surfaces.n_points / (surfaces.period * zeta);
    if (points_per_shortest_wavelength < 4)
      {
        std::ostringstream message;
        message << "Random surfaces/Grid points per side = " << surfaces.n_points << " leaves "
                << points_per_shortest_wavelength
                << " points per shortest wavelength lambda0/zeta; at least 4 are needed";
        throw InputError(message.str());
      }
    return square_grid(surfaces.n_points, surfaces.period * 2 * M_PI / q0);
  }

  void check_grid_memory(const RandomSurfaceParameters &surfaces, const double bytes_per_point,
                         const MPI_Comm communicator)
  {
    check_grid_memory(surfaces.n_points, bytes_per_point,
                      "Random surfaces/Grid points per side = " + std::to_string(surfaces.n_points),
                      communicator);
  }

  void check_summit_spectrum(const FieldMoments &pressure, const std::string &choice)
  {
    if (!summits_have_expectation(pressure))
      throw InputError(choice + " leaves the grid no wavevectors, or wavevectors of one length only, "
                                "between q0 and zeta q0: a spectrum too narrow for summit statistics; the "
                                "allowed range: a band holding wavevectors of two lengths at least (zeta >= "
                                "sqrt(2) at Period L/lambda0 = 1)");
  }

  Estimate mean_over(const std::vector<std::vector<double>> &rows, const std::size_t column)
  {
    const double n    = rows.size();
    double       mean = 0, square = 0;
    for (const auto &row : rows)
      mean += row[column] / n;
    for (const auto &row : rows)
      square += std::pow(row[column] - mean, 2);
    return {mean, n > 1 ? std::sqrt(square / (n - 1) / n) : 0.};
  }
} // namespace penny
