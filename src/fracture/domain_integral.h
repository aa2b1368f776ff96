// The domain J-integral of a half model z >= 0 whose gap faces carry a
// normal traction t (doc/theory.md, section 3). With the virtual crack
// extension q and the volume measure dmu of the kinematics,
//
//   G int_front q.n ds = 2 int [sigma_ij v_i,k q_k,j - W q_k,k] dmu     (area)
//                      - 2 int_{gap face} t v_z,k q_k dmu               (loaded faces)
//
// where all gradients are 3x3 in physical components (fe/elasticity.h): for
// the axisymmetric model their hoop entries give the hoop term, in plane
// strain and 3D there is none. The factor 2 counts the lower half. G is
// evaluated as B(u, u) of the symmetric bilinear form B obtained by
// polarisation, so that B(u, u_ref) also gives a signed K_I.
#pragma once

#include "fe/linear_elastic_system.h"
#include "fracture/crack_extension.h"

#include <vector>

namespace penny
{
  template <typename Kinematics> class DomainIntegral
  {
  public:
    static constexpr int dim = Kinematics::dim;
    using Traction           = typename LinearElasticSystem<Kinematics>::Traction;

    // E' = E/(1 - nu^2) converts J to K_I.
    DomainIntegral(const LinearElasticSystem<Kinematics> &system, double plane_strain_modulus);

    // B(u, v) for displacements u, v loaded by the tractions t_u, t_v (J/m^2).
    double bilinear(const DisplacementVector &u, const Traction &t_u, const DisplacementVector &v,
                    const Traction &t_v, const CrackExtension<dim> &q) const;

    // G = B(u, u) (J/m^2).
    double energy_release_rate(const DisplacementVector &u, const Traction &t,
                               const CrackExtension<dim> &q) const;

    // |K_I| = sqrt(E' G) (Pa m^1/2).
    double stress_intensity_factor(const DisplacementVector &u, const Traction &t,
                                   const CrackExtension<dim> &q) const;

    // Signed K_I = E' B(u, u_ref)/K_ref, with a reference solution u_ref on the
    // same mesh whose K_ref = sqrt(E' B(u_ref, u_ref)) is known to be positive
    // (a tension opening the gap, e.g. uniform pressure).
    double signed_stress_intensity_factor(const DisplacementVector &u, const Traction &t,
                                          const DisplacementVector &u_ref, const Traction &t_ref,
                                          const CrackExtension<dim> &q) const;

    // The same for many extensions (e.g. points along a 3D front) in one pass
    // over the cells: each cell's field values are computed once for all the
    // extensions that touch it. Each result equals that of the single-q call.
    std::vector<double> bilinear(const DisplacementVector &u, const Traction &t_u,
                                 const DisplacementVector &v, const Traction &t_v,
                                 const std::vector<const CrackExtension<dim> *> &qs) const;
    // Signed K_I of several loads (u, t) against one reference, per load and
    // extension: the reference's integral is evaluated once.
    struct Load
    {
      const DisplacementVector *u;
      const Traction           *t;
    };
    std::vector<std::vector<double>>
    signed_stress_intensity_factors(const std::vector<Load> &loads, const DisplacementVector &u_ref,
                                    const Traction                                 &t_ref,
                                    const std::vector<const CrackExtension<dim> *> &qs) const;

  private:
    const LinearElasticSystem<Kinematics> &system;
    const double                           e_prime;
  };
} // namespace penny
