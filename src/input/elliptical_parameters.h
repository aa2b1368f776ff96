// Parameters of the 3D elliptical-gap model and of its scenes
// (doc/theory.md, section 8): the discretisation shared by every scene of
// the model ("Elliptical model": box, mesh, front J-integrals), one gap under
// uniform pressure ("Elliptical gap") and the summits of two radii
// ("Elliptical summits").
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace penny
{
  struct EllipticalModelParameters
  {
    double              box_width;          // R/a
    double              box_height;         // H/a
    unsigned int        cells_along_front;  // edges of the quarter front (even)
    unsigned int        sectors;            // sectors around the front (multiple of 4)
    double              front_cell_size;    // innermost ring, in units of b
    double              ring_ratio;         // of successive rings around the front
    unsigned int        global_refinements; // of the coarse mesh
    double              weight_half_width;  // of the front weight, in front cells
    std::vector<double> ring_radii;         // in units of b^2/a

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct EllipticalGapParameters
  {
    double       semi_axis_a;  // a (m)
    double       aspect_ratio; // b/a, in (0, 1]
    double       pressure;     // p (Pa), uniform on the gap faces
    unsigned int front_points; // K_I at phi = i pi/(2 (n - 1)), i = 0 ... n - 1

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  struct EllipticalSummitsParameters
  {
    std::vector<double> tension_aspect_ratios; // Ay/Ax, in (0, 1]
    unsigned int        front_points;          // K_I along the front of each gap found

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace penny
