// jump-into-contact: from FE, the critical alpha of spontaneous full contact
// at zero load (the maximum over c of K_cosine(c)/sqrt(lambda)), and the
// jump-into-contact load 1 - p_bar_max/p* against alpha (the FE maximum over c
// of p_bar/p* at K_I = K_Ic), beside the maximum of Johnson's curve and the
// small-alpha law 5 (alpha/4)^(4/5). PASS when the relative error of alpha_c
// and the error of 1 - p_bar_max/p* are within Verification/Tolerance.
#include "closed_forms/periodic_array.h"
#include "numerics/relative_error.h"
#include "parallel/spread_over_ranks.h"
#include "problems/periodic_gap.h"
#include "scenes/scene.h"
#include "searches/periodic_searches.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

namespace penny
{
  namespace
  {

    struct JumpIntoContactScene : Scene
    {
      void inputs(Sections &sections) override { periodic.sections(sections); }

      void entries(Entries &entries) override
      {
        // Above 0.56 the maximum leaves the search interval.
        entries.sweep("alpha", "Number of alphas", alphas, {1e-4, 0.5, 9, true}, 1, 1000,
                      interval("[]", 1e-8, 0.56),
                      "The range of alpha = K_Ic/(p* sqrt(lambda)); each alpha is one FE maximisation over "
                      "the contact half-width. Units: none.");
      }

      Verdict run(const ResultFolder &results, std::ostream &log) override
      {
        PeriodicGapSearch        search(periodic);
        const double             lambda   = periodic.model.wavelength;
        const FeCriticalAdhesion critical = fe_critical_alpha(search.gaps, MPI_COMM_WORLD);
        const double             contact  = critical.contact_half_width / lambda;
        // The definition checked: at the FE alpha_c the FE maximum of p_bar/p* is zero.
        const FeLoadExtremum at_critical = fe_jump_into_contact(search.gaps, critical.alpha, MPI_COMM_WORLD);

        Table summary = Table::summary();
        summary.add_row({"critical alpha FE", Table::Cell(critical.alpha, Table::all_digits)});
        summary.add_row({"critical alpha exact, 3^(3/4)/4",
                         Table::Cell(periodic_array::critical_alpha, Table::all_digits)});
        summary.add_row(
            {"relative error", Table::Cell(relative_error(critical.alpha, periodic_array::critical_alpha),
                                           Table::error_digits)});
        summary.add_row({"a/lambda at alpha_c FE", Table::Cell(contact, Table::all_digits)});
        summary.add_row({"a/lambda at alpha_c exact",
                         Table::Cell(periodic_array::critical_contact_ratio, Table::all_digits)});
        summary.add_row(
            {"max p_bar/p* FE at the FE alpha_c", Table::Cell(at_critical.load_ratio, Table::error_digits)});
        summary.add_row({"FE solves", dealii::Utilities::MPI::sum(search.gaps.n_solves(), MPI_COMM_WORLD)});
        publish(summary, "critical-alpha.csv", results, log,
                "Critical alpha: the FE maximum over c of K_cosine(c)/sqrt(lambda), where the jump into "
                "contact reaches p_bar = 0 (spontaneous full contact at zero load)");

        Table      table({{"alpha", Table::Format{4, true}},
                          {"a/lambda FE", Table::Format{8, false}},
                          {"a/lambda Johnson", Table::Format{8, false}},
                          {"1 - p_bar_max/p* FE", Table::digits},
                          {"1 - p_bar_max/p* Johnson", Table::digits},
                          {"absolute error", Table::error_digits},
                          {"5 (alpha/4)^(4/5)", Table::digits},
                          {"Johnson/small-alpha law", Table::Format{6, false}}});
        double     worst = 0;
        const auto maximum =
            spread_over_ranks<FeLoadExtremum>(MPI_COMM_WORLD, alphas.n_points, [&](const unsigned int i) {
              return fe_jump_into_contact(search.gaps, alphas.at(i), MPI_COMM_SELF);
            });
        for (unsigned int i = 0; i < alphas.n_points; ++i)
          {
            const double         alpha = alphas.at(i);
            const FeLoadExtremum fe    = maximum[i];
            const auto           exact = periodic_array::jump_into_contact(alpha);
            const double         law   = periodic_array::small_alpha_jump(alpha);
            worst                      = worse(worst, std::abs(fe.load_ratio - exact.load_ratio));
            table.add_row({alpha, fe.contact_half_width / lambda, exact.contact_ratio, 1 - fe.load_ratio,
                           1 - exact.load_ratio, std::abs(fe.load_ratio - exact.load_ratio), law,
                           (1 - exact.load_ratio) / law});
          }
        publish(table, "jump-into-contact.csv", results, log,
                "\nJump into full contact: 1 - p_bar_max/p* from the FE maximum over c of p_bar/p* at K_I = "
                "K_Ic, beside the maximum of Johnson's curve and the small-alpha law");
        Table cost = Table::summary();
        cost.add_row({"largest |p_bar_max/p* FE - Johnson|", Table::Cell(worst, Table::error_digits)});
        search.add_cost(cost);
        cost.print(log);
        return verdict(worse(relative_error(critical.alpha, periodic_array::critical_alpha), worst));
      }

      PeriodicGapInput periodic;
      Sweep            alphas;
    };
  } // namespace

  PENNY_REGISTER_SCENE(JumpIntoContactScene, "jump-into-contact", "Jump into contact",
                       "from FE: the critical alpha of spontaneous full contact at zero load, and the "
                       "jump-into-contact load 1 - p_bar_max/p* against alpha beside 5 (alpha/4)^(4/5)",
                       "largest of the relative error of alpha_c and the error of 1 - p_bar_max/p*")
} // namespace penny
