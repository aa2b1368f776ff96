// johnson-curves: Johnson's adhesive curves p_bar/p*(a/lambda) from FE (paper
// Fig. 1): at each contact half-width one solve of the two unit tensions,
// shared by every alpha, gives the p_bar at which K_I = K_Ic; beside the closed
// form sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda)), with the closed-form
// curves on a fine grid and their extremes for the overlay
// (postprocess/plot_johnson_curves.py). PASS when every FE p_bar/p* lies
// within Verification/Tolerance of Johnson's.
#include "closed_forms/periodic_array.h"
#include "numerics/relative_error.h"
#include "problems/periodic_gap.h"
#include "scenes/scene.h"
#include "searches/periodic_searches.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace penny
{
  namespace
  {

    struct JohnsonCurvesScene : Scene
    {
      void inputs(Sections &sections) override { periodic.sections(sections); }

      void entries(Entries &entries) override
      {
        entries.increasing_numbers(
            "Johnson parameters alpha", alphas, {0, 0.2, 0.4, 0.6}, 1, at_least(0),
            "alpha = K_Ic/(p* sqrt(lambda)), one curve each (Johnson's alpha^2 = 2 lambda "
            "dgamma/(pi^2 E* h^2)). Units: none.");
        entries.integer(
            "Number of points", n_points, 24u, 1u, 1000u,
            "Contact half-widths a/lambda = i/(2 (n + 1)), i = 1 ... n; each is one FE solve of the two "
            "unit loads, shared by every alpha. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PeriodicGapSearch                                  search(periodic);
        const double                                       lambda = periodic.model.wavelength;
        Table                                              points({{"alpha", Table::Format{4, false}},
                                                                   {"a/lambda", Table::Format{6, false}},
                                                                   {"p_bar/p* FE", Table::all_digits},
                                                                   {"p_bar/p* Johnson", Table::all_digits},
                                                                   {"absolute error", Table::error_digits}});
        std::vector<double>                                worst(alphas.size(), 0.);
        std::vector<std::vector<std::vector<Table::Cell>>> rows(alphas.size());
        const auto          ratio_at = [&](const unsigned int i) { return 0.5 * (i + 1) / (n_points + 1); };
        std::vector<double> half_widths;
        for (unsigned int i = 0; i < n_points; ++i)
          half_widths.push_back((0.5 - ratio_at(i)) * lambda);
        const std::vector<SinusoidUnitSifs> sifs = search.gaps.unit_load_sifs(half_widths, MPI_COMM_WORLD);
        for (unsigned int i = 0; i < n_points; ++i)
          {
            const double           ratio = ratio_at(i);
            const SinusoidUnitSifs K     = sifs[i];
            for (unsigned int k = 0; k < alphas.size(); ++k)
              {
                const double fe    = fe_johnson_load(K, lambda, alphas[k]);
                const double exact = periodic_array::johnson_load(ratio, alphas[k]);
                worst[k]           = worse(worst[k], std::abs(fe - exact));
                rows[k].push_back({alphas[k], ratio, fe, exact, std::abs(fe - exact)});
              }
          }
        for (auto &curve : rows)
          for (auto &row : curve)
            points.add_row(std::move(row));
        results.write_csv("johnson-curves.csv", points);

        // 400 closed-form points in (0, 1/2) per alpha.
        std::vector<Table::Column> columns = {{"a/lambda"}};
        for (const double alpha : alphas)
          columns.push_back({"p_bar/p* alpha=" + Table::label(alpha)});
        Table closed_form(columns);
        for (unsigned int i = 1; i < 400; ++i)
          {
            std::vector<Table::Cell> row = {0.5 * i / 400};
            for (const double alpha : alphas)
              row.emplace_back(periodic_array::johnson_load(0.5 * i / 400, alpha));
            closed_form.add_row(row);
          }
        results.write_csv("johnson-closed-form.csv", closed_form);

        Table extremes({"alpha", "jump into contact a/lambda", "jump into contact p_bar/p*",
                        "pull-off a/lambda", "pull-off p_bar/p*"});
        for (const double alpha : alphas)
          if (alpha < periodic_array::largest_alpha_with_extremes())
            {
              const auto jump = periodic_array::jump_into_contact(alpha);
              const auto pull = periodic_array::pull_off(alpha);
              extremes.add_row(
                  {alpha, jump.contact_ratio, jump.load_ratio, pull.contact_ratio, pull.load_ratio});
            }

        log << "Johnson's adhesive sinusoid from FE: p_bar/p* = [K_cosine - alpha sqrt(lambda)]/K_uniform "
               "at K_I = K_Ic, beside sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda))\n";
        Table summary = Table::summary();
        for (unsigned int k = 0; k < alphas.size(); ++k)
          summary.add_row({"largest |p_bar/p* FE - Johnson|, alpha = " + Table::label(alphas[k]),
                           Table::Cell(worst[k], Table::error_digits)});
        search.add_cost(summary);
        summary.print(log);
        publish(extremes, "johnson-extremes.csv", results, log,
                "Extremes of the closed form (jump into contact, pull-off):");
        log << "Tables: " << results.directory().string() << "/johnson-curves.csv, johnson-closed-form.csv, "
            << "johnson-extremes.csv\n";
        return verdict(*std::max_element(worst.begin(), worst.end()));
      }

      PeriodicGapInput    periodic;
      std::vector<double> alphas;
      unsigned int        n_points;
    };
  } // namespace

  PENNY_REGISTER_SCENE(
      JohnsonCurvesScene, "johnson-curves", "Johnson curves",
      "Johnson's adhesive curves p_bar/p*(a/lambda) from FE roots of K_I = K_Ic beside the closed form "
      "(paper Fig. 1 from FE)",
      "largest |p_bar/p* FE - Johnson|")
} // namespace penny
