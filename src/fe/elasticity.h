// Isotropic linear elasticity in the three kinematic settings of the models.
// Every vector field v (the displacement, or the virtual crack extension of
// the J-integral) enters through its gradient as a 3x3 tensor in physical
// components, so one stress, one energy and one J integrand serve them all:
//
//   Axisymmetric (r, z):  the gradient in (r, z, theta), with the hoop entry
//                         v_r/r; volume element r dr dz (the 2 pi dropped).
//   PlaneStrain (x, z):   the 2x2 gradient, nothing out of plane; dx dz per
//                         unit thickness.
//   Solid (x, y, z):      the gradient itself; dV.
//
// The last coordinate is always the one normal to the crack plane z = 0.
// `strain_entries` lists the entries of the 3x3 strain a setting can make
// nonzero, as raw indices of Strain (0, 1, 2: 00, 11, 22; 3, 4, 5: 01, 02, 12).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace penny
{
  // An isotropic linear elastic solid.
  struct MaterialParameters
  {
    double youngs_modulus; // E (Pa)
    double poissons_ratio; // nu

    double plane_strain_modulus() const
    {
      return youngs_modulus / (1 - poissons_ratio * poissons_ratio);
    } // E' (Pa)
    double lame_lambda() const
    {
      return youngs_modulus * poissons_ratio / ((1 + poissons_ratio) * (1 - 2 * poissons_ratio));
    }
    double lame_mu() const { return youngs_modulus / (2 * (1 + poissons_ratio)); }
  };

  using dealii::Point;
  using Tensor3 = dealii::Tensor<2, 3>;
  using Strain  = dealii::SymmetricTensor<2, 3>;

  struct Axisymmetric
  {
    static constexpr int                         dim = 2;
    static constexpr std::array<unsigned int, 4> strain_entries{{0, 1, 2, 3}}; // rr, zz, theta theta, rz

    static Tensor3 gradient(const dealii::Tensor<2, 2> &grad_v, const dealii::Tensor<1, 2> &v,
                            const Point<2> &x)
    {
      Tensor3 g;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          g[i][j] = grad_v[i][j];
      // On the axis v_r/r tends to d_r v_r.
      g[2][2] = x[0] > 0 ? v[0] / x[0] : grad_v[0][0];
      return g;
    }

    static double measure(const Point<2> &x) { return x[0]; }
  };

  struct PlaneStrain
  {
    static constexpr int                         dim = 2;
    static constexpr std::array<unsigned int, 3> strain_entries{{0, 1, 3}}; // xx, zz, xz

    static Tensor3 gradient(const dealii::Tensor<2, 2> &grad_v, const dealii::Tensor<1, 2> &,
                            const Point<2> &)
    {
      Tensor3 g;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          g[i][j] = grad_v[i][j];
      return g;
    }

    static double measure(const Point<2> &) { return 1; }
  };

  struct Solid
  {
    static constexpr int                         dim = 3;
    static constexpr std::array<unsigned int, 6> strain_entries{{0, 1, 2, 3, 4, 5}};

    static Tensor3 gradient(const dealii::Tensor<2, 3> &grad_v, const dealii::Tensor<1, 3> &,
                            const Point<3> &)
    {
      return grad_v;
    }

    static double measure(const Point<3> &) { return 1; }
  };

  // Lame constants (Pa).
  struct IsotropicElasticity
  {
    double lambda, mu;

    Strain stress(const Strain &strain) const
    {
      return lambda * dealii::trace(strain) * dealii::unit_symmetric_tensor<3>() + 2 * mu * strain;
    }
  };

  inline Strain strain(const Tensor3 &gradient)
  {
    return dealii::symmetrize(gradient);
  }

  inline double von_mises(const Strain &s)
  {
    return std::sqrt(1.5 * (dealii::deviator(s) * dealii::deviator(s)));
  }
} // namespace penny
