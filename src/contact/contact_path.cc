#include "contact/contact_path.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace penny
{
  ContactPath::ContactPath(const HalfSpaceContact &contact, std::string name,
                           const ContactSolverControl &control, GridField initial_gap)
      : contact(contact), name(std::move(name)), control(control)
  {
    if (contact.transform().split())
      throw std::invalid_argument("ContactPath: the contact topology of each step needs the whole field, "
                                  "and the grid is split over ranks (follow paths on one rank)");
    current_.gap = std::move(initial_gap);
  }

  const ContactSolution &ContactPath::to_mean_pressure(const double mean_pressure)
  {
    return record(advance(Control::mean_pressure, mean_pressure));
  }

  const ContactSolution &ContactPath::to_mean_gap(const double mean_gap)
  {
    return record(advance(Control::mean_gap, mean_gap));
  }

  ContactSolution ContactPath::solve(const Control control_kind, const double value,
                                     const ContactSolution &from) const
  {
    return control_kind == Control::mean_pressure ? contact.solve(value, control, from.gap)
                                                  : contact.solve_at_mean_gap(value, control, from.gap);
  }

  // From the current state (value v0) to the target: where the topology
  // changes, [v0, target] is halved 7 times, each half solved from the last
  // state before the change, and the path continues from the state just after it.
  ContactSolution ContactPath::advance(const Control control_kind, const double target) const
  {
    ContactSolution solution = solve(control_kind, target, current_);
    if (!contact.adhesion().active() || steps_.empty())
      return solution;
    const PeriodicGrid &grid     = contact.transform().grid();
    ContactSolution     before   = current_;
    ContactTopology     topology = steps_.back().topology;
    while (!(contact_topology(grid, solution.gap) == topology))
      {
        double low  = control_kind == Control::mean_pressure ? before.mean_pressure : before.mean_gap;
        double high = target;
        for (unsigned int k = 0; k < 7; ++k)
          {
            const double    middle = (low + high) / 2;
            ContactSolution trial  = solve(control_kind, middle, before);
            if (contact_topology(grid, trial.gap) == topology)
              {
                low    = middle;
                before = std::move(trial);
              }
            else
              high = middle;
          }
        const ContactSolution after = solve(control_kind, high, before);
        topology                    = contact_topology(grid, after.gap);
        if (high == target)
          return after;
        before   = after;
        solution = solve(control_kind, target, before);
      }
    return solution;
  }

  const ContactSolution &ContactPath::record(ContactSolution solution)
  {
    const ContactTopology topology = contact_topology(contact.transform().grid(), solution.gap);
    const bool            jumped =
        contact.adhesion().active() && !steps_.empty() && !(topology == steps_.back().topology);
    steps_.push_back({name, static_cast<unsigned int>(steps_.size()), solution.mean_pressure,
                      solution.mean_gap, solution.contact_fraction, solution.energy, topology,
                      solution.iterations, jumped});
    current_ = std::move(solution);
    return current_;
  }

  ContactSolution load_extremum(const HalfSpaceContact &contact, const ContactSolverControl &control,
                                const ContactSolution &start, const double factor, const bool largest,
                                const double relative_width)
  {
    // f is the load to maximise: p_bar or -p_bar.
    const double sign = largest ? 1 : -1;
    struct Sample
    {
      double          mean_gap, f;
      ContactSolution solution;
    };
    const auto at = [&](const double mean_gap, const ContactSolution &from) {
      ContactSolution solution = contact.solve_at_mean_gap(mean_gap, control, from.gap);
      return Sample{mean_gap, sign * solution.mean_pressure, std::move(solution)};
    };
    Sample a{start.mean_gap, sign * start.mean_pressure, start};
    Sample b = at(a.mean_gap * factor, a.solution);
    if (b.f < a.f)
      throw std::runtime_error("load_extremum: the load moves away from the extremum at the start");
    Sample c = at(b.mean_gap * factor, b.solution);
    for (unsigned int k = 0; c.f >= b.f; ++k)
      {
        if (k == 1000 || c.mean_gap < 1e-9 * start.mean_gap || c.mean_gap > 1e9 * start.mean_gap)
          throw std::runtime_error(
              "load_extremum: the load does not turn (mean gap " + std::to_string(start.mean_gap) + " to " +
              std::to_string(c.mean_gap) +
              "): no extremum on this path (with adhesion, a cohesive zone too long for a jump?)");
        a = std::move(b);
        b = std::move(c);
        c = at(b.mean_gap * factor, b.solution);
      }
    // Now f(b) > f(a), f(c) with b between a and c.
    const double golden = 0.381966011250105;
    for (unsigned int k = 0;
         k < 100 && std::abs(c.mean_gap - a.mean_gap) > relative_width * std::abs(b.mean_gap); ++k)
      {
        const double x1 = a.mean_gap, x2 = b.mean_gap, x3 = c.mean_gap;
        const double numerator   = (x2 - x1) * (x2 - x1) * (b.f - c.f) - (x2 - x3) * (x2 - x3) * (b.f - a.f);
        const double denominator = (x2 - x1) * (b.f - c.f) - (x2 - x3) * (b.f - a.f);
        double       x           = denominator != 0 ? x2 - numerator / denominator / 2 : x2;
        // The parabola's vertex, unless it leaves the bracket or nearly repeats x2.
        if (!((x - x1) * (x - x3) < 0) || std::abs(x - x2) < 1e-3 * std::abs(x3 - x1))
          x = std::abs(x3 - x2) > std::abs(x1 - x2) ? x2 + golden * (x3 - x2) : x2 + golden * (x1 - x2);
        Sample     trial     = at(x, b.solution);
        const bool towards_c = (x - x2) * (x3 - x2) > 0;
        if (trial.f > b.f)
          {
            (towards_c ? a : c) = std::move(b);
            b                   = std::move(trial);
          }
        else
          (towards_c ? c : a) = std::move(trial);
      }
    return std::move(b.solution);
  }
} // namespace penny
