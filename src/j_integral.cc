#include "j_integral.h"

#include "axisymmetric_elasticity.h"
#include "gap_mesh.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace penny
{
  using namespace dealii;

  double RingWeight::value(const Point<2> &x) const
  {
    const double s = 1 - x.distance_square(tip) / (rho * rho);
    return s > 0 ? s * s * s * s : 0;
  }

  Tensor<1, 2> RingWeight::gradient(const Point<2> &x) const
  {
    const double s = 1 - x.distance_square(tip) / (rho * rho);
    return s > 0 ? Tensor<1, 2>(-8 * s * s * s / (rho * rho) * (x - tip)) : Tensor<1, 2>();
  }

  JIntegral::JIntegral(const PennyGapModel &model)
    : model(model)
  {}

  double JIntegral::energy_release_rate(const DisplacementVector &u, const FaceLoad &load, const double rho) const
  {
    return bilinear(u, load, u, load, rho);
  }

  double JIntegral::stress_intensity_factor(const DisplacementVector &u, const FaceLoad &load, const double rho) const
  {
    const double G = energy_release_rate(u, load, rho);
    return std::sqrt(model.parameters().material.plane_strain_modulus() * std::max(G, 0.));
  }

  double JIntegral::signed_stress_intensity_factor(const DisplacementVector &u,
                                                   const FaceLoad       &load,
                                                   const DisplacementVector &u_ref,
                                                   const FaceLoad       &load_ref,
                                                   const double          rho) const
  {
    const double e_prime = model.parameters().material.plane_strain_modulus();
    const double k_ref   = stress_intensity_factor(u_ref, load_ref, rho);
    if (!(k_ref > 0))
      throw std::runtime_error("J-integral: the reference load gives K_I = 0; it cannot sign K_I");
    return e_prime * bilinear(u, load, u_ref, load_ref, rho) / k_ref;
  }

  // Polarised integrands: sigma(u)_ij d_r v_i is replaced by the symmetric
  // mean of the (u, v) and (v, u) products, W by sigma(u):e(v)/2.
  double JIntegral::bilinear(const DisplacementVector &u,
                             const FaceLoad       &load_u,
                             const DisplacementVector &v,
                             const FaceLoad       &load_v,
                             const double          rho) const
  {
    const auto      &fe     = model.finite_element();
    const auto      &prm    = model.parameters();
    const double     c      = prm.geometry.gap_radius;
    const double     lambda = prm.material.lame_lambda();
    const double     mu     = prm.material.lame_mu();
    const RingWeight q{crack_tip(prm.geometry), rho};

    // The weight is smooth but only C1 at d = rho: a few extra points.
    const QGauss<2> quadrature(fe.degree + 4);
    const QGauss<1> face_quadrature(fe.degree + 4);
    FEValues<2>     fe_values(fe, quadrature, update_values | update_gradients | update_quadrature_points | update_JxW_values);
    FEFaceValues<2> fe_face(fe, face_quadrature, update_gradients | update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 2>> grad_u(quadrature.size()), grad_v(quadrature.size());
    std::vector<Tensor<1, 2>> value_u(quadrature.size()), value_v(quadrature.size());
    std::vector<Tensor<2, 2>> face_grad_u(face_quadrature.size()), face_grad_v(face_quadrature.size());

    double area_term = 0, hoop_term = 0, face_term = 0;
    for (const auto &cell : model.dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->center().distance(q.tip) > rho + cell->diameter())
          continue;
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(u, grad_u);
        fe_values[displacement].get_function_gradients(v, grad_v);
        fe_values[displacement].get_function_values(u, value_u);
        fe_values[displacement].get_function_values(v, value_v);
        for (const unsigned int k : fe_values.quadrature_point_indices())
          {
            const Point<2> &x = fe_values.quadrature_point(k);
            const double    r = x[0];
            const double    weight = q.value(x);
            if (weight == 0)
              continue;
            const Tensor<1, 2>       dq  = q.gradient(x);
            const AxisymmetricTensor e_u = strain(grad_u[k], value_u[k][0], r);
            const AxisymmetricTensor e_v = strain(grad_v[k], value_v[k][0], r);
            const AxisymmetricTensor s_u = stress(e_u, lambda, mu);
            const AxisymmetricTensor s_v = stress(e_v, lambda, mu);
            const double             W   = 0.5 * s_u.contract(e_v);

            // sigma_ij d_r u_i for j = r and j = z, polarised.
            const auto flux = [](const AxisymmetricTensor &s, const Tensor<2, 2> &g) {
              return Tensor<1, 2>({s.rr * g[0][0] + s.rz * g[1][0], s.rz * g[0][0] + s.zz * g[1][0]});
            };
            const Tensor<1, 2> sigma_grad = 0.5 * (flux(s_u, grad_v[k]) + flux(s_v, grad_u[k]));
            area_term += ((sigma_grad[0] - W) * dq[0] + sigma_grad[1] * dq[1]) * r * fe_values.JxW(k);
            hoop_term += (0.5 * (s_u.tt * e_v.tt + s_v.tt * e_u.tt) - W) * weight * fe_values.JxW(k);
          }

        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == boundary_id::gap_face)
            {
              fe_face.reinit(cell, face);
              fe_face[displacement].get_function_gradients(u, face_grad_u);
              fe_face[displacement].get_function_gradients(v, face_grad_v);
              for (const unsigned int k : fe_face.quadrature_point_indices())
                {
                  const Point<2> &x = fe_face.quadrature_point(k);
                  const double    r = x[0];
                  face_term += 0.5 * (load_u(r) * face_grad_v[k][1][0] + load_v(r) * face_grad_u[k][1][0]) *
                               q.value(x) * r * fe_face.JxW(k);
                }
            }
      }
    const double result =
      2 / c * Utilities::MPI::sum(area_term + hoop_term - face_term, model.triangulation().get_communicator());
    if (!std::isfinite(result))
      throw std::runtime_error("J-integral: the ring of radius " + std::to_string(rho / c) + " c gives NaN or Inf");
    return result;
  }
} // namespace penny
