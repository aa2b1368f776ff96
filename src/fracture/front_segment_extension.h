// The virtual crack extension of the 3D domain integral localised on a
// segment of the elliptical front (doc/theory.md, section 8):
//
//   q(x) = f(phi) w(d) n(phi),
//
// with (phi, d) the parametric angle of the nearest front point and the
// distance from it, n(phi) the in-plane normal of the front (the direction of
// advance), w = (1 - (d/rho)^2)^4 the ring profile of the penny model across
// the front, and f a weight along the front centred on phi_i, a bump in the
// front coordinate psi (EllipticalFront::front_coordinate, in which the
// mesh's columns are evenly spaced):
//
//   f(phi) = k((psi(phi) - psi_i)/h),   k(t) = (1 - t^2)^4 p(t^2)  (|t| < 1),
//
// whose moments of orders 1 to m vanish (the odd ones by symmetry), m = 5 or
// 7: p(u) = 1 - 10 u + 17 u^2 or 1 - 17 u + (323/5) u^2 (1 - u). The domain
// integral then gives the average of G with the weight
// k((psi - psi_i)/h) |dx/dpsi| dpsi over the front, and that average is
// G(phi_i) + O(h^(m+1)) (the O(h^2) bias of a positive bump, several 1e-3 in
// G for the slicing of the meshes here, is gone; with m = 7 that of m = 5,
// 3e-6 at b/a = 0.25 over two front cells, too, but its three sign changes on
// each side need finer meshes: doc/elliptical.md); in psi, where G varies on
// a scale of order 1 even near phi = 0 of a slender gap, the bias is far
// smaller than in phi
// (postprocess/front_weight_bias.py). The quarter
// model holds the front 0 <= phi <= pi/2; a weight that reaches past a
// symmetry plane is folded back (its mirror images about psi = phi = 0 and
// pi/2 are added), which is the weight of the whole front restricted to the
// quarter: symmetric fields give a symmetric q, and the front measure is the
// quarter's share, int_0^(pi/2) f(phi) |dx/dphi| dphi. At phi_i = 0 and pi/2
// the weight is the half of a bump centred on the symmetry plane, doubled.
//
// The ring radius rho must stay below the smallest radius of curvature of the
// front, b^2/a, where the nearest front point stops being unique inside the
// ellipse.
#pragma once

#include "fe/elliptical_gap_mesh.h"
#include "fracture/crack_extension.h"

#include <limits>
#include <memory>

namespace penny
{
  // The nearest front point of a point x, its coordinates relative to it, and
  // the front's frame there.
  struct FrontFrame
  {
    EllipticalFront::Coordinates local;
    dealii::Point<3>             point;
    dealii::Tensor<1, 3>         normal;
    dealii::Tensor<1, 3>         tangent;
    double                       speed; // |dx/dphi|
    double                       curvature;
    double                       psi;      // the front coordinate
    double                       psi_rate; // d psi/d phi
  };

  // The front frame of the last point asked for. The domain integral asks
  // every extension that touches a cell for its value and gradient at the
  // same quadrature point in turn: extensions that share one of these find the
  // nearest front point (an iteration) and its frame once per point, not once
  // per extension.
  class NearestFrontPoint
  {
  public:
    explicit NearestFrontPoint(const EllipticalFront &front) : front(front) {}

    const FrontFrame &operator()(const dealii::Point<3> &x) const;

    const EllipticalFront front;

  private:
    mutable dealii::Point<3> last_point{std::numeric_limits<double>::quiet_NaN(), 0, 0};
    mutable FrontFrame       last_frame{};
  };

  class FrontSegmentExtension : public CrackExtension<3>
  {
  public:
    // The weight centred on the front point at parametric angle `centre`
    // (0 <= centre <= pi/2), half-width `half_width` in the front coordinate psi
    // (EllipticalFront::front_coordinate; at most pi/2: then
    // the images about the two symmetry planes are all the folding needs),
    // its moments of orders 1 to `vanishing_moments` (5 or 7) zero, ring
    // radius `ring_radius` (m), on the front of `nearest`. Throws
    // std::invalid_argument out of range.
    FrontSegmentExtension(std::shared_ptr<const NearestFrontPoint> nearest, double centre, double half_width,
                          unsigned int vanishing_moments, double ring_radius);

    dealii::Tensor<1, 3> value(const dealii::Point<3> &x) const override;
    dealii::Tensor<2, 3> gradient(const dealii::Point<3> &x) const override;
    bool                 may_touch(const dealii::Triangulation<3>::cell_iterator &cell) const override;
    // Where the tube d = rho around the front may cross the box.
    bool   edge_crosses(const dealii::BoundingBox<3> &box) const override;
    double front_measure() const override { return measure; }

    // f(phi), the mirror images included.
    double front_weight(double phi) const;

  private:
    // f and df/dphi at front coordinate psi, d psi/d phi = psi_rate.
    std::pair<double, double> weight_and_slope(double psi, double psi_rate) const;
    const EllipticalFront    &front() const { return nearest->front; }

    const std::shared_ptr<const NearestFrontPoint> nearest;
    const double                                   centre;
    const double                                   half_width;
    const unsigned int                             moments;
    const double                                   rho;
    double                                         centre_coordinate; // psi at the centre
    // The parametric angles in [0, pi/2] between which f may not vanish.
    double support_begin;
    double support_end;
    double measure;
  };
} // namespace penny
