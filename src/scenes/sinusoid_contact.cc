// sinusoid-contact: Johnson's adhesive 1D sinusoid from its closed form
// (paper Fig. 1): p_bar/p* = sin^2(pi a/lambda) - alpha sqrt(tan(pi
// a/lambda)) for each alpha, and its jump into full contact.
#include "closed_forms/periodic_array.h"
#include "output/table.h"
#include "scenes/scene.h"

#include <sstream>

namespace penny
{
  namespace
  {
    struct SinusoidContactScene : Scene
    {
      void entries(Entries &entries) override
      {
        entries.increasing_numbers(
            "Johnson parameters alpha", alphas, {0, 0.2, 0.4, 0.6}, 1, at_least(0),
            "alpha^2 = 2 lambda dgamma/(pi^2 E* h^2) of Johnson's adhesive 1D sinusoid, one curve each. "
            "Units: none.");
        entries.integer("Number of points", n_points, 199u, 2u, 100000u,
                        "Contact semi-widths a/lambda, evenly spaced inside (0, 1/2). Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        std::vector<Table::Column> columns = {{"a/lambda"}};
        for (const double alpha : alphas)
          columns.push_back({"p/p* alpha=" + Table::label(alpha)});
        Table table(columns);
        for (unsigned int i = 1; i <= n_points; ++i)
          {
            const double             ratio = 0.5 * i / (n_points + 1);
            std::vector<Table::Cell> row   = {ratio};
            for (const double alpha : alphas)
              row.emplace_back(periodic_array::johnson_load(ratio, alpha));
            table.add_row(row);
          }
        results.write_csv("sinusoid-contact.csv", table);

        // The jump into full contact is the curve's maximum inside (0, 1/2), or
        // its end a -> lambda/2 without adhesion; beyond (25/16) (3/5)^(3/4) the
        // curve has none.
        Table jumps({"alpha", "jump into full contact at p/p*", "a/lambda"});
        for (const double alpha : alphas)
          if (alpha < periodic_array::largest_alpha_with_extremes())
            {
              const auto jump = periodic_array::jump_into_contact(alpha);
              jumps.add_row({alpha, jump.load_ratio, jump.contact_ratio});
            }
          else
            jumps.add_row({alpha, "none: p/p* falls monotonically", ""});
        log << "Johnson's adhesive 1D sinusoid: p/p* = sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda))\n";
        jumps.print(log);
        log << "Table: " << results.directory().string() << "/sinusoid-contact.csv\n";
        return {};
      }

      std::vector<double> alphas;
      unsigned int        n_points;
    };
  } // namespace

  PENNY_REGISTER_SCENE(SinusoidContactScene, "sinusoid-contact", "Sinusoid",
                       "Johnson's adhesive 1D sinusoid from its closed form (paper Fig. 1)", "")
} // namespace penny
