// Quasi-static loading and unloading: equilibria followed by continuation,
// each started from the previous one. With adhesion the equilibria are
// multistable (half_space_contact.h), so each records which path and step it
// came from and whether the step jumped: changed the contact topology, as a
// gap snapping shut, a contact snapping on or the surfaces pulling off do.
// A descent over a long step could cross into another branch's basin where
// the quasi-static path does not, so a step that changes the topology is
// retraced by halving until the change falls within 1/128 of it, and the path
// goes on from the state just after the change. Without adhesion the
// equilibrium is unique and changes continuously, and no step counts as a
// jump (gaps that shrink to nothing still change the count).
#pragma once

#include "contact/contact_geometry.h"
#include "contact/half_space_contact.h"

#include <string>
#include <vector>

namespace penny
{
  struct PathStep
  {
    std::string     path; // the caller's name for the path, e.g. "loading"
    unsigned int    step; // 0, 1, ... along it
    double          mean_pressure, mean_gap, contact_fraction, energy;
    ContactTopology topology;
    unsigned int    iterations;
    bool            jumped; // adhesive, and the topology differs from the previous step's
  };

  class ContactPath
  {
  public:
    // A path named `name` from `initial_gap` (empty: full contact). Continue
    // a path under another name by starting it from the other's current().gap.
    // Each step's topology needs the whole field: std::invalid_argument if
    // the contact's grid is split over ranks.
    ContactPath(const HalfSpaceContact &contact, std::string name, const ContactSolverControl &control,
                GridField initial_gap = {});

    const ContactSolution &to_mean_pressure(double mean_pressure);
    const ContactSolution &to_mean_gap(double mean_gap);

    const ContactSolution       &current() const { return current_; }
    const std::vector<PathStep> &steps() const { return steps_; }

  private:
    enum class Control
    {
      mean_pressure,
      mean_gap
    };
    ContactSolution        advance(Control control, double target) const;
    ContactSolution        solve(Control control, double value, const ContactSolution &from) const;
    const ContactSolution &record(ContactSolution solution);

    const HalfSpaceContact &contact;
    std::string             name;
    ContactSolverControl    control;
    ContactSolution         current_;
    std::vector<PathStep>   steps_;
  };

  // The extreme mean pressure along a path of prescribed mean gaps from
  // `start`: the mean gap is multiplied by `factor` a step until the load turns (a maximum if
  // `largest`, else a minimum), then successive parabolic interpolation (golden
  // section where the parabola leaves the bracket) narrows the bracket to
  // `relative_width` of the mean gap. Under prescribed mean pressure such an
  // extremum ends the path (a jump into contact, a pull-off); at prescribed
  // mean gap the path passes it. Returns the best equilibrium found.
  ContactSolution load_extremum(const HalfSpaceContact &contact, const ContactSolverControl &control,
                                const ContactSolution &start, double factor, bool largest,
                                double relative_width = 1e-4);
} // namespace penny
