// Axisymmetric linear elasticity in (u_r, u_z)(r, z): the four strain and
// stress components, the hoop one included. One place for the kinematics, used
// by assembly, J-integral and field output alike.
#pragma once

#include <deal.II/base/tensor.h>

#include <cmath>

namespace penny
{
  // Tensor components; rz is the tensor shear e_rz = (d_z u_r + d_r u_z)/2.
  struct AxisymmetricTensor
  {
    double rr, zz, rz, tt;

    double trace() const { return rr + zz + tt; }

    // Full contraction a:b, the shear counted twice.
    double contract(const AxisymmetricTensor &b) const
    {
      return rr * b.rr + zz * b.zz + 2 * rz * b.rz + tt * b.tt;
    }
  };

  // grad_u[i][j] = d u_i / d x_j with x = (r, z); u_r the radial displacement.
  inline AxisymmetricTensor
  strain(const dealii::Tensor<2, 2> &grad_u, const double u_r, const double r)
  {
    // On the axis u_r/r tends to d_r u_r.
    return {grad_u[0][0], grad_u[1][1], 0.5 * (grad_u[0][1] + grad_u[1][0]), r > 0 ? u_r / r : grad_u[0][0]};
  }

  inline AxisymmetricTensor
  stress(const AxisymmetricTensor &e, const double lambda, const double mu)
  {
    const double volumetric = lambda * e.trace();
    return {volumetric + 2 * mu * e.rr,
            volumetric + 2 * mu * e.zz,
            2 * mu * e.rz,
            volumetric + 2 * mu * e.tt};
  }

  inline double von_mises(const AxisymmetricTensor &s)
  {
    return std::sqrt(0.5 * ((s.rr - s.zz) * (s.rr - s.zz) + (s.zz - s.tt) * (s.zz - s.tt) +
                            (s.tt - s.rr) * (s.tt - s.rr)) +
                     3 * s.rz * s.rz);
  }
} // namespace penny
