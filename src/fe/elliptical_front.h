// The front of a flat elliptical gap x^2/a^2 + y^2/b^2 < 1 on z = 0: its
// points, tangent, normal and curvature at a parametric angle, and the
// coordinates of any point relative to its nearest front point.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace penny
{
  // The front x^2/a^2 + y^2/b^2 = 1, z = 0, and coordinates local to it.
  class EllipticalFront
  {
  public:
    EllipticalFront(double semi_axis_a, double semi_axis_b);

    // Point at parametric angle phi: (a cos phi, b sin phi, 0).
    dealii::Point<3> point(double phi) const;
    // Unit tangent in the direction of increasing phi.
    dealii::Tensor<1, 3> unit_tangent(double phi) const;
    // Unit normal in the plane z = 0, pointing away from the gap (the
    // direction of crack advance).
    dealii::Tensor<1, 3> unit_normal(double phi) const;
    // |dx/dphi| = (a^2 sin^2 phi + b^2 cos^2 phi)^(1/2): arc length per radian.
    double arc_length_rate(double phi) const;
    // Curvature a b/|dx/dphi|^3; its largest value, a/b^2, is at phi = 0.
    double curvature(double phi) const;
    // a b/|dx/dphi|: the distance from the centre to the tangent at phi (a at
    // phi = 0, b at pi/2), also the step across the front per unit of the
    // stretched radius (a R cos phi, b R sin phi).
    double tangent_distance(double phi) const;
    // Its derivative in phi, -(a^2 - b^2) sin phi cos phi a b/|dx/dphi|^3.
    double tangent_distance_rate(double phi) const;
    // The front coordinate psi = (phi + alpha)/2, the mean of the parametric
    // angle and the angle alpha of the normal (tan alpha = (a/b) tan phi), in
    // which the mesh's columns and the weights along the front are evenly
    // spaced: d psi/d phi is (1 + a/b)/2 at phi = 0, where the front turns
    // fastest, and (1 + b/a)/2 (at least 1/2) at pi/2, where it is
    // straightest. psi = phi on the circle; psi(-phi) = -psi(phi),
    // psi(pi - phi) = pi - psi(phi).
    double front_coordinate(double phi) const;
    // d psi/d phi = (1 + a b/|dx/dphi|^2)/2.
    double front_coordinate_rate(double phi) const;
    // The parametric angle phi of front coordinate psi in [-pi/2, pi] (exact
    // at 0 and pi/2).
    double parametric_angle(double psi) const;
    // Whether x lies on the front, to rounding.
    bool   contains(const dealii::Point<3> &x) const;
    double semi_axis_a() const { return a; }
    double semi_axis_b() const { return b; }

    // Coordinates of x relative to its nearest front point: that point's
    // parametric angle phi, the distance from it (x lies in the plane normal to
    // the front there), and the angle theta in that plane from the crack
    // advance direction, 0 ahead of the front (ligament), pi behind it (gap
    // face), pi/2 straight above.
    struct Coordinates
    {
      double phi;
      double distance;
      double theta;
    };
    Coordinates local_coordinates(const dealii::Point<3> &x) const;

  private:
    const double a;
    const double b;
  };

  // Parametric angles of the front vertices of the active mesh, sorted, from 0
  // to pi/2; on a parallel::distributed::Triangulation those of all ranks.
  // Consecutive angles bound the front edges.
  std::vector<double> front_vertex_angles(const dealii::Triangulation<3> &triangulation,
                                          const EllipticalFront          &front);
} // namespace penny
