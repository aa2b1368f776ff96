// The elliptical-gap problem (doc/theory.md, section 8): the subsections of
// the 3D model and of one gap under a uniform or quadratic face traction, and
// the solve-and-measure routine of that gap: K_I(phi) along the front from
// the front-localised domain integral beside the closed form (Galin's, which
// for the uniform pressure is Green and Sneddon's and Irwin's), the opening
// at the centre and the gap volume.
#pragma once

#include "closed_forms/elliptical_crack.h"
#include "fe/elliptical_gap_model.h"
#include "fracture/front_stress_intensity.h"
#include "input/entries.h"
#include "output/result_folder.h"

#include <deal.II/base/timer.h>

#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  // The discretisation every elliptical scene shares: the model (its
  // semi-axes are the scene's) and the front J-integrals.
  struct EllipticalModel
  {
    EllipticalGapModelParameters model;
    FrontWeight                  front_weight;
    std::vector<double>          ring_radii; // in units of b^2/a

    // The model of the gap with semi-axes a and b (m).
    EllipticalGapModelParameters with_semi_axes(double a, double b) const;
    // The cells along the front of the refined mesh.
    unsigned int front_cells() const { return model.mesh.cells_along_front << model.global_refinements; }
  };

  // Material, Elliptical model, Finite element and Linear solver.
  void elliptical_model_sections(Sections &sections, EllipticalModel &model);

  // One gap under the face traction p (1 + c_x x^2/a^2 + c_y y^2/b^2), K_I at
  // `front_points` front points.
  struct EllipticalGap
  {
    double       semi_axis_a;  // a (m)
    double       aspect_ratio; // b/a, in (0, 1]
    double       pressure;     // p (Pa), the traction at the centre
    double       x_term;       // c_x >= -1
    double       y_term;       // c_y >= -1
    unsigned int front_points; // K_I at phi = i pi/(2 (n - 1)), i = 0 ... n - 1

    bool              uniform() const { return x_term == 0 && y_term == 0; }
    QuadraticTraction traction() const;
  };

  // Refuses, on every rank and before it is refined, a model the memory of
  // this machine cannot hold, naming the entries that make it large.
  void check_elliptical_model_size(const EllipticalGapModelParameters &model);

  // Elliptical gap; its front points must fall on the vertices of `model`'s
  // front, so it is read after elliptical_model_sections.
  void elliptical_gap_section(Sections &sections, EllipticalGap &gap, const EllipticalModel &model);

  struct EllipticalGapMeasurement
  {
    std::vector<double>              angles;            // parametric angles phi of the front points
    std::vector<double>              ring_radii;        // in units of b^2/a
    std::vector<std::vector<double>> signed_sifs;       // per ring and point (Pa m^1/2)
    std::vector<double>              exact_sifs;        // the closed form's, per point
    std::vector<double>              axisymmetric_sifs; // the axisymmetric FE model's, for b/a = 1 under p
    double                           largest_error;     // |K_FE/K_exact - 1| over rings and points
    double                           opening_at_centre, exact_opening_at_centre; // w(0) (m)
    double                           gap_volume, exact_gap_volume;               // m^3
    unsigned long long               n_cells, n_dofs;
    unsigned int                     iterations;
    double                           relative_residual;
    std::string                      solver;
    double                           peak_memory; // sum over the ranks of the peak resident size (MB)
  };

  // One solve of the face traction; K_I at every front point and ring. The
  // circle under uniform pressure is solved with the axisymmetric model too, at that model's
  // defaults (degree, mesh, rings) in a cylinder of the box's radius and
  // height: the 3D model checked against a second model. The fields (and K_I
  // at the front points) go to `fields` unless it is null.
  EllipticalGapMeasurement measure_elliptical_gap(const EllipticalModel &model, const EllipticalGap &gap,
                                                  dealii::TimerOutput &timer, std::ostream &log,
                                                  const ResultFolder *fields);

  // A ring radius as its column names show it, e.g. "ring 0.2 b^2/a".
  std::string ring_name(double rho);
} // namespace penny
