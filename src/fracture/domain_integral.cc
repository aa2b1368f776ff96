#include "fracture/domain_integral.h"

#include "fe/boundary_faces.h"
#include "fe/boundary_ids.h"

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>

namespace penny
{
  using namespace dealii;

  template <typename Kinematics>
  DomainIntegral<Kinematics>::DomainIntegral(const LinearElasticSystem<Kinematics> &system,
                                             const double                           plane_strain_modulus)
      : system(system), e_prime(plane_strain_modulus)
  {
  }

  template <typename Kinematics>
  double DomainIntegral<Kinematics>::energy_release_rate(const DisplacementVector &u, const Traction &t,
                                                         const CrackExtension<dim> &q) const
  {
    return bilinear(u, t, u, t, q);
  }

  template <typename Kinematics>
  double DomainIntegral<Kinematics>::stress_intensity_factor(const DisplacementVector &u, const Traction &t,
                                                             const CrackExtension<dim> &q) const
  {
    return std::sqrt(e_prime * std::max(energy_release_rate(u, t, q), 0.));
  }

  template <typename Kinematics>
  double DomainIntegral<Kinematics>::signed_stress_intensity_factor(const DisplacementVector  &u,
                                                                    const Traction            &t,
                                                                    const DisplacementVector  &u_ref,
                                                                    const Traction            &t_ref,
                                                                    const CrackExtension<dim> &q) const
  {
    return signed_stress_intensity_factors({{&u, &t}}, u_ref, t_ref, {&q}).front().front();
  }

  template <typename Kinematics>
  std::vector<std::vector<double>> DomainIntegral<Kinematics>::signed_stress_intensity_factors(
      const std::vector<Load> &loads, const DisplacementVector &u_ref, const Traction &t_ref,
      const std::vector<const CrackExtension<dim> *> &qs) const
  {
    std::vector<double> k_ref = bilinear(u_ref, t_ref, u_ref, t_ref, qs);
    for (double &k : k_ref)
      {
        k = std::sqrt(e_prime * std::max(k, 0.));
        if (!(k > 0))
          throw std::runtime_error("J-integral: the reference load gives K_I = 0; it cannot sign K_I");
      }
    std::vector<std::vector<double>> K;
    for (const Load &load : loads)
      {
        K.push_back(bilinear(*load.u, *load.t, u_ref, t_ref, qs));
        for (unsigned int i = 0; i < qs.size(); ++i)
          K.back()[i] *= e_prime / k_ref[i];
      }
    return K;
  }

  template <typename Kinematics>
  double DomainIntegral<Kinematics>::bilinear(const DisplacementVector &u, const Traction &t_u,
                                              const DisplacementVector &v, const Traction &t_v,
                                              const CrackExtension<dim> &q) const
  {
    return bilinear(u, t_u, v, t_v, {&q}).front();
  }

  // Polarised integrands: sigma(u)_ij v_i,k q_k,j is replaced by the mean of
  // the (u, v) and (v, u) products, W by sigma(u):e(v)/2. A cell's fields are
  // evaluated once, on the finer quadrature if the edge of any of the
  // extensions touching it crosses it.
  template <typename Kinematics>
  std::vector<double>
  DomainIntegral<Kinematics>::bilinear(const DisplacementVector &u, const Traction &t_u,
                                       const DisplacementVector &v, const Traction &t_v,
                                       const std::vector<const CrackExtension<dim> *> &qs) const
  {
    const auto &fe         = system.get_fe();
    const auto &elasticity = system.get_elasticity();
    // The weight is smooth but only C3 at the edge of its support: a few extra
    // points, and cells and faces that the edge crosses split into 4 x 4 (4)
    // in 2D, 2 x 2 x 2 (2 x 2) in 3D, where 64 sub-cells per crossed cell
    // would cost minutes per front point.
    const unsigned int       n_points = fe.degree + 4, subdivisions = dim == 3 ? 2 : 4;
    const QGauss<dim>        quadrature(n_points);
    const QIterated<dim>     edge_quadrature(QGauss<1>(n_points), subdivisions);
    const QGauss<dim - 1>    face_quadrature(n_points);
    const QIterated<dim - 1> edge_face_quadrature(QGauss<1>(n_points), subdivisions);
    const UpdateFlags flags = update_values | update_gradients | update_quadrature_points | update_JxW_values;
    const Mapping<dim> &mapping = system.get_mapping();
    FEValues<dim>       fe_values(mapping, fe, quadrature, flags),
        fe_edge_values(mapping, fe, edge_quadrature, flags);
    const UpdateFlags face_flags = update_gradients | update_quadrature_points | update_JxW_values;
    FEFaceValues<dim> fe_face(mapping, fe, face_quadrature, face_flags),
        fe_edge_face(mapping, fe, edge_face_quadrature, face_flags);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      grad_u, grad_v, face_grad_u, face_grad_v;
    std::vector<Tensor<1, dim>>      value_u, value_v;
    std::vector<unsigned int>        touching;

    // The extensions that may touch `cell`, and whether the edge of one crosses `box`.
    const auto touch = [&](const auto &cell, const BoundingBox<dim> &box) {
      touching.clear();
      bool crossing = false;
      for (unsigned int i = 0; i < qs.size(); ++i)
        if (qs[i]->may_touch(cell))
          {
            touching.push_back(i);
            crossing = crossing || qs[i]->edge_crosses(box);
          }
      return crossing;
    };

    std::vector<double> area_term(qs.size(), 0.), face_term(qs.size(), 0.);
    for (const auto &cell : system.get_dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const bool crossing = touch(cell, cell->bounding_box());
        if (touching.empty())
          continue;
        FEValues<dim> &values = crossing ? fe_edge_values : fe_values;
        values.reinit(cell);
        for (auto *vector : {&grad_u, &grad_v})
          vector->resize(values.n_quadrature_points);
        for (auto *vector : {&value_u, &value_v})
          vector->resize(values.n_quadrature_points);
        values[displacement].get_function_gradients(u, grad_u);
        values[displacement].get_function_gradients(v, grad_v);
        values[displacement].get_function_values(u, value_u);
        values[displacement].get_function_values(v, value_v);
        for (const unsigned int k : values.quadrature_point_indices())
          {
            const Point<dim> &x   = values.quadrature_point(k);
            const Tensor3     du  = Kinematics::gradient(grad_u[k], value_u[k], x);
            const Tensor3     dv  = Kinematics::gradient(grad_v[k], value_v[k], x);
            const Strain      s_u = elasticity.stress(strain(du));
            const Strain      s_v = elasticity.stress(strain(dv));
            const double      W   = 0.5 * (s_u * strain(dv));
            const double      dmu = Kinematics::measure(x) * values.JxW(k);
            for (const unsigned int i : touching)
              {
                const Tensor3 grad_q = Kinematics::gradient(qs[i]->gradient(x), qs[i]->value(x), x);
                if (grad_q.norm_square() == 0)
                  continue;
                const double flux = 0.5 * (scalar_product(Tensor3(s_u), dv * grad_q) +
                                           scalar_product(Tensor3(s_v), du * grad_q));
                area_term[i] += (flux - W * trace(grad_q)) * dmu;
              }
          }
      }

    // Two passes over the gap face: the faces no edge of an extension
    // crosses, then those crossed, each with its own quadrature.
    for (const bool crossed : {false, true})
      for_each_boundary_face(
          system.get_dof_handler(), boundary_id::gap_face, crossed ? fe_edge_face : fe_face,
          [&](const auto &cell, const FEFaceValues<dim> &face) {
            if (touch(cell, cell->face(face.get_face_number())->bounding_box()) != crossed ||
                touching.empty())
              return;
            face_grad_u.resize(face.n_quadrature_points);
            face_grad_v.resize(face.n_quadrature_points);
            face[displacement].get_function_gradients(u, face_grad_u);
            face[displacement].get_function_gradients(v, face_grad_v);
            for (const unsigned int k : face.quadrature_point_indices())
              {
                const Point<dim> &x  = face.quadrature_point(k);
                const double      tu = t_u(x), tv = t_v(x);
                const double      dmu = Kinematics::measure(x) * face.JxW(k);
                for (const unsigned int i : touching)
                  {
                    const Tensor<1, dim> qx = qs[i]->value(x);
                    face_term[i] +=
                        0.5 * (tu * (face_grad_v[k][dim - 1] * qx) + tv * (face_grad_u[k][dim - 1] * qx)) *
                        dmu;
                  }
              }
          });

    std::vector<double> result(qs.size());
    for (unsigned int i = 0; i < qs.size(); ++i)
      area_term[i] -= face_term[i];
    Utilities::MPI::sum(area_term, system.get_communicator(), area_term);
    for (unsigned int i = 0; i < qs.size(); ++i)
      {
        result[i] = 2 / qs[i]->front_measure() * area_term[i];
        if (!std::isfinite(result[i]))
          throw std::runtime_error("J-integral: the domain integral gives NaN or Inf");
      }
    return result;
  }

  template class DomainIntegral<Axisymmetric>;
  template class DomainIntegral<PlaneStrain>;
  template class DomainIntegral<Solid>;
} // namespace penny
