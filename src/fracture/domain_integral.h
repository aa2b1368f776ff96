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
// polarisation, so that B(u, u_ref) also gives a signed K_I. Every field,
// extension and pair of fields is evaluated in one pass over the cells.
#pragma once

#include "fe/linear_elastic_system.h"
#include "fracture/crack_extension.h"

#include <algorithm>
#include <cmath>
#include <utility>
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

    // A displacement and the traction on the gap faces that loads it.
    struct Load
    {
      const DisplacementVector *u;
      const Traction           *t;
    };

    // B(u_a, u_b) (J/m^2) for each pair (a, b) of `loads` and each extension,
    // in one pass over the cells that evaluates each field once per cell:
    // [pair][extension]. G = B(u, u).
    std::vector<std::vector<double>> bilinear(const std::vector<Load>                                  &loads,
                                              const std::vector<std::pair<unsigned int, unsigned int>> &pairs,
                                              const std::vector<const CrackExtension<dim> *> &qs) const;

    // K_I of several loads against a reference load whose K_ref is known to
    // be positive (a tension opening the gap, e.g. uniform pressure), for each
    // extension, in one pass.
    struct StressIntensities
    {
      std::vector<double>              reference;            // K_ref = sqrt(E' B(u_ref, u_ref)) (Pa m^1/2)
      std::vector<std::vector<double>> signed_sifs;          // [load][extension]: E' B(u, u_ref)/K_ref
      std::vector<std::vector<double>> energy_release_rates; // [load][extension]: B(u, u), if asked for
    };
    StressIntensities stress_intensities(const std::vector<Load> &loads, const Load &reference,
                                         const std::vector<const CrackExtension<dim> *> &qs,
                                         bool with_energy_release_rates = false) const;

    // |K_I| = sqrt(E' G) (Pa m^1/2).
    double stress_intensity_factor(const double G) const { return std::sqrt(e_prime * std::max(G, 0.)); }

  private:
    const LinearElasticSystem<Kinematics> &system;
    const double                           e_prime;
  };
} // namespace penny
