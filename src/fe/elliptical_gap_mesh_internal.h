// The pieces of the elliptical gap's mesh (fe/elliptical_gap_mesh.h) that its
// files share, for them alone: the columns' turn and the chart of the swept
// cells (fe/elliptical_front_chart.cc) and the reference octant with its
// lattice and shells (fe/elliptical_gap_octant.cc, with the rings around the
// front), from which fe/elliptical_gap_mesh.cc builds the mesh and counts its
// cells.
#pragma once

#include "fe/elliptical_front.h"
#include "fe/elliptical_gap_mesh.h"

#include <deal.II/base/derivative_form.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/manifold.h>

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace penny
{
  namespace internal
  {
    // The columns' turn S(phi, R, Z) towards the front's normal, with its
    // derivatives (what it is and why: fe/elliptical_front_chart.cc).
    class ColumnTurn
    {
    public:
      ColumnTurn(const double a, const double b) : a(a), b(b) {}

      struct Value
      {
        double turn     = 0; // S
        double d_radius = 0; // dS/dR
        double d_height = 0; // dS/dZ
        double d_phi    = 0; // dS/dphi
        double lean     = 0; // g, also -h'/h
      };

      // S and its derivatives at parametric angle phi (cos, sin given so that
      // they are exact on the symmetry planes), R and Z.
      Value operator()(double cp, double sp, double R, double Z) const;

    private:
      static constexpr double c = 0.5; // fraction of the distance to the centre of curvature
      static constexpr double k = 0.5; // bound of the largest turn's derivative in phi
      static constexpr double L = 1;   // largest turning depth, in units of r
      const double            a;
      const double            b;
    };

    // Stretched spherical coordinates (r, theta, psi), psi the front
    // coordinate (EllipticalFront::front_coordinate, in which the columns are
    // evenly spaced) of the parametric angle phi, with turned columns:
    // R = r cos(theta), Z = r sin(theta), beta = phi + S(phi, R, Z),
    // x = a R cos(beta), y = b R sin(beta), z = h(phi) Z,
    // h = EllipticalFront::tangent_distance. The front is r = 1, theta = 0.
    class EllipticalFrontChart : public dealii::ChartManifold<3>
    {
    public:
      EllipticalFrontChart(const double a, const double b) : a(a), b(b), front(a, b), turn(a, b) {}

      std::unique_ptr<dealii::Manifold<3>> clone() const override
      {
        return std::make_unique<EllipticalFrontChart>(a, b);
      }

      dealii::Point<3>                pull_back(const dealii::Point<3> &x) const override;
      dealii::Point<3>                push_forward(const dealii::Point<3> &chart) const override;
      dealii::DerivativeForm<1, 3, 3> push_forward_gradient(const dealii::Point<3> &chart) const override;

    private:
      const double          a;
      const double          b;
      const EllipticalFront front;
      const ColumnTurn      turn;
    };

    // Throws std::invalid_argument, the message naming make_elliptical_gap_mesh.
    inline void check(const bool condition, const std::string &message)
    {
      if (!condition)
        throw std::invalid_argument("make_elliptical_gap_mesh: " + message);
    }

    // The reference octant (front = unit circle) as a cube-sphere: a lattice
    // of nodes (s, i, j, l), s the shell (0 = the core cube, whose nodes fill
    // the lattice 0 <= i, j <= m, 0 <= l <= rows), and on each shell the nodes
    // of the cube surface i = m (X patch), j = m (Y patch), l = rows (Z patch).
    // The X and Y patches meet the equator in the columns e = 0 ... 2m
    // (front coordinates psi_e = e pi/(4m)); their first `tube_rows` rows lie at fixed
    // latitudes and hold the spider web between shells tube_inner and
    // tube_outer.
    class ReferenceOctant
    {
    public:
      explicit ReferenceOctant(const EllipticalGapMeshParameters &p);

      // Physical position of lattice node (s, i, j, l).
      dealii::Point<3> lattice_point(unsigned int s, unsigned int i, unsigned int j, unsigned int l) const;

      // Physical position of the web node (t, zeta) = (r - 1, theta) on column e.
      dealii::Point<3> web_point(unsigned int e, const dealii::Point<2> &node) const;

      // Lattice indices (i, j) of column e of the X and Y patches.
      std::array<unsigned int, 2> column(const unsigned int e) const
      {
        return e <= m ? std::array<unsigned int, 2>{{m, e}} : std::array<unsigned int, 2>{{2 * m - e, m}};
      }

      // Web node k (0 ... n-1 rings, n the tube boundary), sector node i, in (t, zeta).
      dealii::Point<2> web_node(unsigned int e, unsigned int k, unsigned int i) const;

      const dealii::Tensor<1, 3>             scale;
      const unsigned int                     m;
      const unsigned int                     sectors;
      const unsigned int                     tube_rows;
      const unsigned int                     upper_rows;
      const unsigned int                     rows;
      const std::vector<std::vector<double>> rings;
      const dealii::Tensor<1, 3>             box;
      unsigned int                           tube_inner;
      unsigned int                           tube_outer;
      unsigned int                           n_shells;
      std::vector<double>                    radii;
      double                                 core;

    private:
      double u(const unsigned int i) const { return i == m ? 1. : std::tan(i * M_PI / (4 * m)); }

      double               row_latitude(unsigned int l) const;
      double               row_height(double u, unsigned int l) const;
      dealii::Point<3>     cube_point(unsigned int i, unsigned int j, unsigned int l) const;
      dealii::Tensor<1, 3> direction(unsigned int i, unsigned int j, unsigned int l) const;
      dealii::Point<3>     physical(const dealii::Point<3> &reference, double weight) const;

      const EllipticalFront front;
      const ColumnTurn      turn;
    };
  } // namespace internal
} // namespace penny
