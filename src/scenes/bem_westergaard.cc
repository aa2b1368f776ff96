// bem-westergaard: the FFT boundary-element contact solver on Westergaard's
// sinusoid h = 2 h0 sin^2(pi x/lambda) on grids of increasing size: the
// contact half-width (sub-grid, from the gap beside the edge) and the
// pressure against p_bar/p* = sin^2(pi a/lambda), with the rates of their
// errors. PASS when the half-width on the finest grid lies within
// 'Half-width tolerance' of Westergaard's.
#include "closed_forms/periodic_array.h"
#include "contact/contact_geometry.h"
#include "contact/half_space_contact.h"
#include "numerics/relative_error.h"
#include "output/table.h"
#include "problems/contact_solver.h"
#include "problems/solid.h"
#include "scenes/scene.h"

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace penny
{
  namespace
  {
    // The least-squares slope of y against x.
    double fitted_slope(const std::vector<double> &x, const std::vector<double> &y)
    {
      const double n  = x.size();
      double       sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          sx += x[i];
          sy += y[i];
          sxx += x[i] * x[i];
          sxy += x[i] * y[i];
        }
      return (n * sxy - sx * sy) / (n * sxx - sx * sx);
    }

    struct BemWestergaardScene : Scene
    {
      void inputs(Sections &sections) override
      {
        material_section(sections, material);
        contact_solver_section(sections, control, 1e-12);
        // p* is a traction: in the range every traction keeps (the quoted
        // range of h0 is also within the entry's own).
        sections.check([&] {
          const double scale = M_PI * material.plane_strain_modulus() / wavelength; // p* per metre of h0
          sections.require(
              scale * amplitude >= smallest_magnitude && scale * amplitude <= largest_magnitude,
              "BEM Westergaard/Amplitude h0", amplitude,
              "p* = pi E* h0/lambda in [1e-30, 1e30] Pa: [" +
                  Table::label(std::max(smallest_magnitude, smallest_magnitude / scale), 3) + ", " +
                  Table::label(std::min(largest_magnitude, largest_magnitude / scale), 3) + "] m");
        });
      }

      void entries(Entries &entries) override
      {
        entries.number("Wavelength lambda", wavelength, 1e-3, magnitude("m"),
                       "Period of the sinusoid. Units: m.");
        entries.number("Amplitude h0", amplitude, 1e-6, magnitude("m"),
                       "h = 2 h0 sin^2(pi x/lambda); p* = pi E* h0/lambda. Units: m.");
        std::vector<double> sizes;
        entries.numbers(
            "Grid sizes", sizes, {64, 128, 256, 512, 1024}, interval("[]", 16, 1 << 20),
            "Grid points per wavelength, even and increasing (the grid is N x 4, the surface does not "
            "depend on y). Units: none.");
        grid_sizes.assign(sizes.begin(), sizes.end());
        for (std::size_t k = 0; k < sizes.size(); ++k)
          entries.require(sizes[k] == grid_sizes[k] && grid_sizes[k] % 2 == 0 &&
                              (k == 0 || grid_sizes[k] > grid_sizes[k - 1]),
                          "Grid sizes", sizes[k], "even whole numbers, increasing");
        entries.increasing_numbers(
            "Load ratios", load_ratios, {0.2, 0.5, 0.8}, 1, interval("()", 0, 1),
            "p_bar/p* of the solves, where the coarsest grid resolves the strip and the gap: "
            "a contact half-width of at least 0.05 lambda + 2 points (the pressure is compared "
            "more than 0.05 lambda inside the edges) and 5 points of gap beside the edge (the "
            "sub-grid edge is fitted to them). Units: none.");
        entries.number(
            "Half-width tolerance", half_width_tolerance, 1e-3, above(0),
            "The verdict: |a - a_Westergaard|/lambda at the finest grid, every load. Units: none.");
        if (!entries.reading())
          return;
        entries.require(grid_sizes.size() >= 2, "Grid sizes", grid_sizes.back(),
                        "at least two grids (the rates are fitted over them)");
        const double coarsest = grid_sizes.front();
        const double lowest   = std::pow(std::sin(M_PI * (0.05 + 2 / coarsest)), 2);
        const double highest  = std::pow(std::sin(M_PI * (0.5 - 5 / coarsest)), 2);
        for (const double ratio : load_ratios)
          entries.require(ratio >= lowest && ratio <= highest, "Load ratios", ratio,
                          "[" + Table::label(lowest, 3) + ", " + Table::label(highest, 3) +
                              "] with the coarsest of the Grid sizes, " + Table::label(coarsest) +
                              " points per wavelength");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        const auto  &bem    = *this;
        const double lambda = bem.wavelength;
        const double E_star = material.plane_strain_modulus();
        const double p_star = M_PI * E_star * bem.amplitude / lambda;
        Table        table({"points per lambda",
                            "p_bar/p*",
                            {"a/lambda exact", {8}},
                            {"a/lambda BEM", {8}},
                            {"|a error|/lambda", {2, true}},
                            {"|a error|/lambda contact points", {2, true}},
                            {"max |p error|/p* inside", {2, true}},
                            "iterations",
                            {"wall time (s)", {3}}});
        // Per load: log N and the logs of both errors, for the fitted rates.
        std::vector<std::vector<double>> log_n(bem.load_ratios.size()), log_error(bem.load_ratios.size()),
            log_pressure_error(bem.load_ratios.size());
        double worst_at_finest = 0;
        for (std::size_t g = 0; g < bem.grid_sizes.size(); ++g)
          {
            const unsigned int     n = bem.grid_sizes[g];
            const PeriodicGrid     grid{n, 4, lambda, 4 * lambda / n};
            const FourierTransform transform(grid);
            GridField              h(grid.n_points());
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < grid.ny; ++j)
                h[i * grid.ny + j] = 2 * bem.amplitude * std::pow(std::sin(M_PI * i / n), 2);
            const HalfSpaceContact contact(transform, h, E_star);
            for (std::size_t l = 0; l < bem.load_ratios.size(); ++l)
              {
                const double          ratio = bem.load_ratios[l];
                dealii::Timer         timer;
                const ContactSolution solution = contact.solve(ratio * p_star, control);
                // The strip is centred on the crest x = lambda/2 (i = n/2); its
                // edge lies between the last contact point and the gap beside it.
                unsigned int last = n / 2;
                while (last + 1 < n && solution.pressure[(last + 1) * grid.ny] > 0)
                  ++last;
                std::vector<double> gaps;
                for (unsigned int k = 1; k <= 8 && last + k < n; ++k)
                  gaps.push_back(solution.gap[(last + k) * grid.ny]);
                const double exact      = periodic_array::westergaard_contact_ratio(ratio);
                const double half_width = (last - n / 2. + edge_from_gap(gaps)) / n;
                const double error      = std::abs(half_width - exact);
                const double coarse     = std::abs((last - n / 2. + 0.5) / n - exact);
                // The pressure more than 0.05 lambda inside the edges.
                double pressure_error = 0;
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const double s = double(i) / n - 0.5;
                    if (std::abs(s) < exact - 0.05)
                      pressure_error =
                          worse(pressure_error, std::abs(solution.pressure[i * grid.ny] / p_star -
                                                         periodic_array::westergaard_pressure(s, ratio)));
                  }
                table.add_row({n, ratio, exact, half_width, error, coarse, pressure_error,
                               solution.iterations, timer.wall_time()});
                log_n[l].push_back(std::log(n));
                log_error[l].push_back(std::log(error));
                log_pressure_error[l].push_back(std::log(pressure_error));
                if (g + 1 == bem.grid_sizes.size())
                  worst_at_finest = worse(worst_at_finest, error);
              }
          }
        // The rate r of error ~ N^-r: least squares over all grids (the sub-grid
        // half-width error does not fall monotonically from one grid to the next).
        Table rates({"p_bar/p*", {"half-width rate", {3}}, {"pressure rate", {3}}});
        for (std::size_t l = 0; l < bem.load_ratios.size(); ++l)
          rates.add_row({bem.load_ratios[l], -fitted_slope(log_n[l], log_error[l]),
                         -fitted_slope(log_n[l], log_pressure_error[l])});
        publish(table, "bem-westergaard.csv", results, log,
                "FFT boundary elements on Westergaard's sinusoid h = 2 h0 sin^2(pi x/lambda): contact "
                "half-width (sub-grid, from the gap beside the edge; and from the contact points alone) and "
                "pressure against p_bar/p* = sin^2(pi a/lambda)");
        publish(rates, "bem-westergaard-rates.csv", results, log,
                "Rates r of error ~ N^-r, least squares over the grids:");
        log << "Tables: bem-westergaard.csv, bem-westergaard-rates.csv in " << results.directory().string()
            << "/\n";

        std::ostringstream message;
        message.precision(2);
        message << std::scientific << "largest |a error|/lambda at " << bem.grid_sizes.back()
                << " points per wavelength " << worst_at_finest
                << (worst_at_finest <= bem.half_width_tolerance ? " <= " : " > ")
                << "BEM Westergaard/Half-width tolerance = " << bem.half_width_tolerance;
        return {worst_at_finest <= bem.half_width_tolerance, message.str()};
      }

      MaterialParameters        material;
      double                    wavelength, amplitude; // lambda (m), h0 (m) of h = 2 h0 sin^2(pi x/lambda)
      std::vector<unsigned int> grid_sizes;            // points per wavelength
      std::vector<double>       load_ratios;           // p_bar/p*
      ContactSolverControl      control;
      double                    half_width_tolerance; // of a/lambda at the finest grid
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      BemWestergaardScene, "bem-westergaard", "BEM Westergaard",
      "the FFT boundary-element contact solver on Westergaard's sinusoid: half-width and pressure against "
      "grid size",
      "")
} // namespace penny
