// The axisymmetric domain J-integral (physics.md section 3). Per unit length of
// the circular front of radius c, for the half model,
//   G = (2/c) int_A [(s_rr d_r u_r + s_rz d_r u_z - W) d_r q + (s_rz d_r u_r + s_zz d_r u_z) d_z q] r dA
//     + (2/c) int_A (s_tt e_tt - W) q dA                      (hoop term)
//     - (2/c) int_{z=0, r<c} p d_r u_z q r dr                 (loaded faces)
// It is evaluated as B(u, u) of the symmetric bilinear form B obtained by
// polarisation, so that B(u, u_ref) also gives a signed K_I.
#pragma once

#include "penny_gap_model.h"

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace penny
{
  // q = (1 - (d/rho)^2)^4 with d the distance to the tip: 1 at the tip, 0 at
  // d = rho with three vanishing derivatives. The (...)^2 profile is only C1
  // there, and Gauss quadrature across that kink costs about 1e-6 in K_I.
  struct RingWeight
  {
    dealii::Point<2> tip;
    double           rho;

    double              value(const dealii::Point<2> &x) const;
    dealii::Tensor<1, 2> gradient(const dealii::Point<2> &x) const;
  };

  class JIntegral
  {
  public:
    explicit JIntegral(const PennyGapModel &model);

    // B(u, v) over the ring of radius rho (m), u and v loaded by load_u, load_v.
    double bilinear(const DisplacementVector &u,
                    const FaceLoad               &load_u,
                    const DisplacementVector     &v,
                    const FaceLoad               &load_v,
                    double                        rho) const;

    // G = B(u, u) (J/m^2).
    double energy_release_rate(const DisplacementVector     &u, const FaceLoad &load, double rho) const;

    // |K_I| = sqrt(E' G) (Pa m^1/2).
    double stress_intensity_factor(const DisplacementVector     &u, const FaceLoad &load, double rho) const;

    // Signed K_I = E' B(u, u_ref)/K_ref, with a reference solution u_ref on the
    // same mesh whose K_ref = sqrt(E' B(u_ref, u_ref)) is known to be positive
    // (a tension opening the gap, e.g. uniform pressure).
    double signed_stress_intensity_factor(const DisplacementVector     &u,
                                          const FaceLoad               &load,
                                          const DisplacementVector     &u_ref,
                                          const FaceLoad               &load_ref,
                                          double                        rho) const;

  private:
    const PennyGapModel &model;
  };
} // namespace penny
