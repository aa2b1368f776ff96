// Virtual crack extensions q(x) of the domain J-integral (doc/theory.md,
// section 3): a vector field equal to the direction of crack advance on the
// front, smooth, and zero outside a domain around it. The energy released per
// unit front length is the domain integral over q divided by the front
// measure int_front q.n ds of the extension.
#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>

namespace penny
{
  template <int dim> class CrackExtension
  {
  public:
    virtual ~CrackExtension() = default;

    virtual dealii::Tensor<1, dim> value(const dealii::Point<dim> &x) const    = 0;
    virtual dealii::Tensor<2, dim> gradient(const dealii::Point<dim> &x) const = 0;

    // False for cells that lie surely outside the support of q.
    virtual bool may_touch(const typename dealii::Triangulation<dim>::cell_iterator &cell) const = 0;

    // True where the edge of the support of q crosses the box of a cell or
    // face: q is only finitely differentiable across it, and the domain
    // integral subdivides its quadrature there. Extensions that do not say
    // get the plain quadrature everywhere.
    virtual bool edge_crosses(const dealii::BoundingBox<dim> &) const { return false; }

    // int_front q.n ds in the volume measure of the model (for the penny, r at
    // the tip: the 2 pi is dropped throughout).
    virtual double front_measure() const = 0;
  };

  // In a plane section through a straight or circular front, q = w(d) e_x with
  // d = |x - tip| and the ring profile w = (1 - (d/rho)^2)^4: 1 at the tip, 0
  // at d = rho with three vanishing derivatives. The (...)^2 profile is only
  // C1 there, and Gauss quadrature across that kink costs about 1e-6 in K_I.
  template <int dim> class RingExtension : public CrackExtension<dim>
  {
  public:
    // front_measure: r at the tip for the axisymmetric model, 1 in plane strain.
    RingExtension(const dealii::Point<dim> &tip, const double rho, const double front_measure)
        : tip(tip), rho(rho), measure(front_measure)
    {
    }

    // The ring profile w(x).
    double weight(const dealii::Point<dim> &x) const
    {
      const double s = 1 - x.distance_square(tip) / (rho * rho);
      return s > 0 ? s * s * s * s : 0;
    }

    dealii::Tensor<1, dim> value(const dealii::Point<dim> &x) const override
    {
      dealii::Tensor<1, dim> q;
      q[0] = weight(x);
      return q;
    }

    dealii::Tensor<2, dim> gradient(const dealii::Point<dim> &x) const override
    {
      dealii::Tensor<2, dim> grad_q;
      const double           s = 1 - x.distance_square(tip) / (rho * rho);
      if (s > 0)
        grad_q[0] = -8 * s * s * s / (rho * rho) * (x - tip);
      return grad_q;
    }

    bool may_touch(const typename dealii::Triangulation<dim>::cell_iterator &cell) const override
    {
      return cell->center().distance(tip) <= rho + cell->diameter();
    }

    // The circle d = rho passes between the nearest and the farthest point of the box.
    bool edge_crosses(const dealii::BoundingBox<dim> &box) const override
    {
      double nearest = 0, farthest = 0;
      for (unsigned int i = 0; i < dim; ++i)
        {
          const double below = box.lower_bound(i) - tip[i], above = tip[i] - box.upper_bound(i);
          nearest += std::pow(std::max({below, above, 0.}), 2);
          farthest += std::pow(std::max(std::abs(below), std::abs(above)), 2);
        }
      return std::sqrt(nearest) < rho * (1 - 1e-12) && std::sqrt(farthest) > rho * (1 + 1e-12);
    }

    double front_measure() const override { return measure; }

  private:
    const dealii::Point<dim> tip;
    const double             rho;
    const double             measure;
  };
} // namespace penny
