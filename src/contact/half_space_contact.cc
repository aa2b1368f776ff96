#include "contact/half_space_contact.h"

#include "contact/half_space_contact_internal.h"
#include "fourier/grid_resampling.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace penny
{
  using internal::formatted;
  using internal::mean;
  using internal::on_any_rank;

  namespace
  {
    // A failure of the start of nested iteration, named by its grid once.
    struct StartFailure : ContactSolverFailure
    {
      using ContactSolverFailure::ContactSolverFailure;
    };

    // The largest grid spacing along a direction that has more than one point
    // (an nx x 1 grid is a plane-strain problem: its y spacing means nothing).
    double grid_spacing(const PeriodicGrid &grid)
    {
      double spacing = 0;
      if (grid.nx > 1)
        spacing = grid.lx / grid.nx;
      if (grid.ny > 1)
        spacing = std::max(spacing, grid.ly / grid.ny);
      return spacing;
    }

    // A grid's halved or single-precision twin is split as the grid is.
    SplitTransform split_of(const FourierTransform &transform)
    {
      return transform.shares_memory() ? SplitTransform::shared_memory : SplitTransform::fftw_mpi;
    }
  } // namespace

  HalfSpaceContact::HalfSpaceContact(const FourierTransform &transform, GridField heights,
                                     const double E_star, const Adhesion &adhesion)
      : transform_(transform), heights_(std::move(heights)), E_star(E_star), adhesion_(adhesion),
        single(transform.grid(), transform.planning(), transform.communicator(), split_of(transform))
  {
    if (on_any_rank(transform,
                    single.first_row() != transform.first_row() || single.n_rows() != transform.n_rows()))
      throw std::logic_error("contact solver: the single-precision transform splits the grid differently");
    if (on_any_rank(transform, heights_.size() != transform.n_local_points()))
      throw std::invalid_argument("contact solver: the heights do not match the grid");
    if (on_any_rank(transform, !std::all_of(heights_.begin(), heights_.end(),
                                            [](double h) { return std::isfinite(h); })))
      throw std::invalid_argument("contact solver: the heights hold NaN or Inf");
    if (!(E_star > 0) || !std::isfinite(E_star))
      throw std::invalid_argument("contact solver: E* must be positive and finite");
    if (!(adhesion.work >= 0) || !std::isfinite(adhesion.work))
      throw std::invalid_argument(formatted("contact solver: the work of adhesion w = %g J/m^2 is outside "
                                            "the allowed range [0, inf) (0: no adhesion)",
                                            adhesion.work));
    if (adhesion.active())
      {
        if (!(adhesion.range > 0) || !std::isfinite(adhesion.range))
          throw std::invalid_argument(
              formatted("contact solver: the adhesive range rho = %g m is outside the allowed range (0, inf)",
                        adhesion.range));
        const double zone = adhesion.process_zone(E_star), spacing = grid_spacing(transform.grid());
        if (!(zone / spacing >= min_process_zone_points * (1 - 1e-9)))
          throw std::invalid_argument(formatted("contact solver: the cohesive zone E* rho^2/(pi w) = %.3g m "
                                                "spans %.3g grid spacings; at least %g "
                                                "are needed (a finer grid or a longer range)",
                                                zone, zone / spacing, min_process_zone_points));
      }
    const double h_mean = mean(transform, heights_);
    double       square = 0;
    for (const double h : heights_)
      square += (h - h_mean) * (h - h_mean);
    length_unit = std::sqrt(transform.sum(square) / transform.grid().n_points());
    if (!(length_unit > 0))
      throw std::invalid_argument("contact solver: a flat surface is in full contact at any load");

    // The mean mode has no stiffness; the preconditioner gives it the
    // compliance of the longest wavelength of the period.
    const PeriodicGrid &grid  = transform.grid();
    const double        q_min = 2 * M_PI / std::max(grid.nx > 1 ? grid.lx : 0, grid.ny > 1 ? grid.ly : 0);
    traction_unit             = E_star * q_min * length_unit;
    scaled_adhesion           = {adhesion.work / (traction_unit * length_unit), adhesion.range / length_unit};
    const auto stiffness_of   = [=](const Wavevector &q) { return q.norm() / (2 * q_min); };
    const auto compliance_of  = [=](const Wavevector &q) {
      return q.kx == 0 && q.ky == 0 ? 2. : 2 * q_min / q.norm();
    };
    stiffness        = transform.tabulate_real(stiffness_of);
    single_stiffness = single.tabulate_real(stiffness_of);
    compliance       = single.tabulate_real(compliance_of);
    // The response at the origin to a unit load there, from the rank that holds it.
    GridField impulse(heights_.size(), 0.);
    if (transform.holds_first_row())
      impulse[0] = 1;
    transform.apply(transform.tabulate(compliance_of), impulse, impulse);
    point_compliance = transform.sum(transform.holds_first_row() ? impulse[0] : 0);
    full_contact     = full_contact_pressure(transform, heights_, E_star);
    for (double &p : full_contact)
      p /= traction_unit;

    // The halved problems of nested iteration, built once for every solve.
    // With adhesion only while the halved grid keeps the cohesive zone over
    // min_process_zone_points spacings: a longer zone is a weaker adhesion
    // (strength w/rho), whose solution can lie on another branch (it let a
    // full contact held by adhesion open).
    const std::optional<PeriodicGrid> halved_grid = halved(transform.grid(), 128);
    if (halved_grid && (!adhesion.active() || adhesion.process_zone(E_star) / grid_spacing(*halved_grid) >=
                                                  min_process_zone_points * (1 - 1e-9)))
      {
        coarse_transform = std::make_unique<FourierTransform>(*halved_grid, transform.planning(),
                                                              transform.communicator(), split_of(transform));
        coarse           = std::make_unique<HalfSpaceContact>(
            *coarse_transform, resampled(transform, *coarse_transform, heights_), E_star, adhesion);
      }
  }

  ContactSolution HalfSpaceContact::solve(const double mean_pressure, const ContactSolverControl &control,
                                          const GridField &initial_gap) const
  {
    if (!std::isfinite(mean_pressure) || (!adhesion_.active() && !(mean_pressure > 0)))
      throw std::invalid_argument(
          formatted("contact solver: the mean pressure %g Pa is outside the allowed range "
                    "(0, inf) without adhesion, (-inf, inf) with it",
                    mean_pressure));
    // A rank may hold no rows: whether a gap was given is decided over all ranks.
    const bool given = on_any_rank(transform_, !initial_gap.empty());
    if (given && coarse && adhesion_.active())
      return solve_from(Control::mean_pressure, mean_pressure, control, initial_gap,
                        nested_start(Control::mean_pressure, mean_pressure, control, initial_gap));
    if (given || !coarse || adhesion_.active())
      return solve_from(Control::mean_pressure, mean_pressure, control,
                        given ? initial_gap : GridField(heights_.size(), 0.), std::nullopt);
    // Only a start: its accuracy beyond the interpolation's is wasted. Its
    // failure is the halved grid's, with that grid's tolerance.
    const ContactSolution start = [&] {
      try
        {
          return coarse->solve(mean_pressure, {control.max_iterations, std::max(control.tolerance, 1e-4)});
        }
      catch (const StartFailure &)
        {
          throw; // from a grid halved further, named there
        }
      catch (const ContactSolverFailure &failure)
        {
          const PeriodicGrid &grid = coarse_transform->grid();
          throw StartFailure(
              failure.what() +
              formatted(", on the halved %.0f x %.0f grid that starts nested iteration (solved "
                        "to the larger of the tolerance and 1e-4)",
                        grid.nx, grid.ny));
        }
    }();
    return solve_from(Control::mean_pressure, mean_pressure, control, {}, start);
  }

  ContactSolution HalfSpaceContact::solve_at_mean_gap(const double                mean_gap,
                                                      const ContactSolverControl &control,
                                                      const GridField            &initial_gap) const
  {
    if (!(mean_gap > 0) || !std::isfinite(mean_gap))
      throw std::invalid_argument(
          formatted("contact solver: the mean gap %g m is outside the allowed range (0, inf)", mean_gap));
    const bool given = on_any_rank(transform_, !initial_gap.empty());
    return solve_from(Control::mean_gap, mean_gap, control,
                      given ? initial_gap : GridField(heights_.size(), 0.),
                      given && coarse && adhesion_.active()
                          ? nested_start(Control::mean_gap, mean_gap, control, initial_gap)
                          : std::nullopt);
  }

  // With adhesion, the start from a given gap: the problem on the halved grid
  // from the given gap restricted to it, solved to the larger of the
  // tolerance and 1e-6 (recursively). None where the halved problem has no
  // solution (it can pull off or fail to converge where this one does not).
  std::optional<ContactSolution> HalfSpaceContact::nested_start(const Control               control_kind,
                                                                const double                value,
                                                                const ContactSolverControl &control,
                                                                const GridField            &initial_gap) const
  {
    check_start(initial_gap); // before the halved grid clips it
    GridField restricted = resampled(transform_, *coarse_transform, initial_gap);
    for (double &g : restricted)
      g = std::max(g, 0.);
    const ContactSolverControl coarse_control{control.max_iterations, std::max(control.tolerance, 1e-6)};
    try
      {
        return control_kind == Control::mean_pressure
                   ? coarse->solve(value, coarse_control, restricted)
                   : coarse->solve_at_mean_gap(value, coarse_control, restricted);
      }
    catch (const std::runtime_error &)
      {
        return std::nullopt;
      }
  }

  // The solve on this grid from the halved grid's solution `start`
  // interpolated (bilinear: it stays >= 0), or from `gap` where there is
  // none; at a prescribed mean gap scaled to it first.
  ContactSolution HalfSpaceContact::solve_from(const Control control_kind, const double value,
                                               const ContactSolverControl &control, GridField gap,
                                               const std::optional<ContactSolution> &start) const
  {
    if (start)
      gap = interpolated(*coarse_transform, start->gap, transform_);
    if (control_kind == Control::mean_gap)
      {
        const double current =
            on_any_rank(transform_, gap.size() != heights_.size()) ? 0 : mean(transform_, gap);
        for (double &g : gap)
          g = current > 0 ? g * value / current : value;
      }
    ContactSolution solution = minimise(control_kind, value, control, std::move(gap));
    if (start)
      solution.coarse_iterations = (start->iterations + start->coarse_iterations) *
                                   coarse_transform->grid().n_points() / transform_.grid().n_points();
    return solution;
  }

  std::vector<LoadStep> load_sweep(const HalfSpaceContact &contact, const std::vector<double> &mean_pressures,
                                   const ContactSolverControl &control)
  {
    if (contact.adhesion().active())
      throw std::invalid_argument(
          "load_sweep: with adhesion the equilibrium depends on the path (ContactPath)");
    std::vector<LoadStep> steps;
    for (const double p_bar : mean_pressures)
      {
        const ContactSolution solution = contact.solve(p_bar, control);
        steps.push_back({p_bar, 1 - solution.contact_fraction, solution.mean_gap, solution.iterations,
                         solution.residual});
      }
    return steps;
  }

} // namespace penny
