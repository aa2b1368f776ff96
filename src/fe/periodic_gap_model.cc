#include "fe/periodic_gap_model.h"

#include "fe/boundary_ids.h"
#include "fe/tip_graded_mesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // u_x = 0 on both symmetry lines, u_z = 0 on the ligament.
    std::vector<ZeroDisplacement> zero_displacements()
    {
      const ComponentMask u_x(std::vector<bool>{true, false}), u_z(std::vector<bool>{false, true});
      return {
          {boundary_id::symmetry, u_x}, {boundary_id::second_symmetry, u_x}, {boundary_id::ligament, u_z}};
    }

    // The coarse grid has square cells of width s = b 2^m, b = min(c, lambda/2 - c),
    // the largest such width not above min(lambda/2, D)/2. They are laid from
    // the symmetry line nearer the tip, so the tip is a dyadic point of the
    // coarse cell at that line and becomes a vertex of the quadtree; the
    // remainder of lambda/2 widens the cell at the other line (by less than s).
    // At least two columns and a few rows of coarse cells, whatever c/lambda:
    // a grid of cells about b wide would need (lambda/2b)(D/b) of them, 15000 at
    // c = lambda/100 and D = 3 lambda, where this one has 54.
    void make_periodic_gap_mesh(Triangulation<2> &triangulation, const PeriodicGapModelParameters &model)
    {
      const double        half = model.wavelength / 2;
      const double        c    = model.gap_half_width;
      const double        b    = model.tip_distance();
      const double        s = b * std::pow(2., std::floor(std::log2(std::min(half, model.depth) / (2 * b))));
      std::vector<double> x_steps = coarse_steps(half, s);
      if (c > half - c)
        std::reverse(x_steps.begin(), x_steps.end());
      const double tip_width = b / std::pow(2., model.tip_levels);
      make_tip_graded_mesh(triangulation, x_steps, coarse_steps(model.depth, s), Point<2>(c, 0),
                           {tip_width, model.grading_distance});

      // The plane z = 0 is exact; faces off the symmetry lines have their
      // centres a good fraction of b away from them.
      const double x_tolerance = 1e-9 * b, z_tolerance = 1e-9 * tip_width;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            const Point<2> x = face->center();
            face->set_boundary_id(x[0] < x_tolerance          ? boundary_id::symmetry
                                  : x[0] > half - x_tolerance ? boundary_id::second_symmetry
                                  : x[1] > z_tolerance        ? boundary_id::far
                                  : x[0] < c                  ? boundary_id::gap_face
                                                              : boundary_id::ligament);
          }
    }

    // Meshed before the system that distributes its degrees of freedom on it.
    const Triangulation<2> &meshed(Triangulation<2> &triangulation, const PeriodicGapModelParameters &model,
                                   TimerOutput &timer)
    {
      if (!(model.gap_half_width > 0 && model.gap_half_width < model.wavelength / 2 && model.depth > 0))
        throw std::logic_error("periodic gap: needs 0 < c < lambda/2 and D > 0");
      TimerOutput::Scope scope(timer, "mesh");
      make_periodic_gap_mesh(triangulation, model);
      return triangulation;
    }
  } // namespace

  PeriodicGapModelParameters PeriodicGapModelParameters::with_gap_half_width(const double c) const
  {
    PeriodicGapModelParameters model = *this;
    model.gap_half_width             = c;
    return model;
  }

  double PeriodicGapModelParameters::tip_distance() const
  {
    return std::min(gap_half_width, wavelength / 2 - gap_half_width);
  }

  PeriodicGapModel::PeriodicGapModel(const PeriodicGapModelParameters &parameters, TimerOutput &timer)
      : parameters(parameters),
        triangulation(parameters.communicator, Triangulation<2>::limit_level_difference_at_vertices),
        system(meshed(triangulation, parameters, timer), parameters.degree, 1, parameters.material,
               parameters.linear_solver, zero_displacements(), timer,
               degree_graded_towards_tip(parameters.tip_distance(), parameters.degree,
                                         parameters.levels_per_degree))
  {
  }

  DisplacementVector PeriodicGapModel::solve(const BuecknerTension &t)
  {
    return system.solve(boundary_id::gap_face, t);
  }
} // namespace penny
