#include "fracture/domain_integral.h"

#include "fe/boundary_faces.h"
#include "fe/boundary_ids.h"

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/matrix_free/fe_evaluation.h>

#include <cmath>
#include <memory>

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
  typename DomainIntegral<Kinematics>::StressIntensities
  DomainIntegral<Kinematics>::stress_intensities(const std::vector<Load> &loads, const Load &reference,
                                                 const std::vector<const CrackExtension<dim> *> &qs,
                                                 const bool with_energy_release_rates) const
  {
    // The fields are the loads, then the reference; the pairs (ref, ref),
    // then (load, ref) and, if asked for, (load, load) for each load.
    std::vector<Load> fields = loads;
    fields.push_back(reference);
    const unsigned int                                 r     = loads.size();
    std::vector<std::pair<unsigned int, unsigned int>> pairs = {{r, r}};
    for (unsigned int l = 0; l < r; ++l)
      pairs.push_back({l, r});
    if (with_energy_release_rates)
      for (unsigned int l = 0; l < r; ++l)
        pairs.push_back({l, l});
    const std::vector<std::vector<double>> B = bilinear(fields, pairs, qs);

    StressIntensities result;
    for (const double b : B[0])
      {
        result.reference.push_back(stress_intensity_factor(b));
        if (!(result.reference.back() > 0))
          throw std::runtime_error(
              "J-integral: the reference load gives K_I = 0 on a ring, so it cannot sign "
              "K_I (is a value of the entry Ring radii far smaller than the cells at the tip?)");
      }
    for (unsigned int l = 0; l < r; ++l)
      {
        result.signed_sifs.emplace_back();
        for (unsigned int i = 0; i < qs.size(); ++i)
          result.signed_sifs.back().push_back(e_prime * B[1 + l][i] / result.reference[i]);
        if (with_energy_release_rates)
          result.energy_release_rates.push_back(B[1 + r + l]);
      }
    return result;
  }

  // Polarised integrands: sigma(u)_ij v_i,k q_k,j is replaced by the mean of
  // the (u, v) and (v, u) products, W by sigma(u):e(v)/2. A cell's fields are
  // evaluated once, on the finer quadrature if the edge of any of the
  // extensions touching it crosses it.
  template <typename Kinematics>
  std::vector<std::vector<double>>
  DomainIntegral<Kinematics>::bilinear(const std::vector<Load>                                  &loads,
                                       const std::vector<std::pair<unsigned int, unsigned int>> &pairs,
                                       const std::vector<const CrackExtension<dim> *>           &qs) const
  {
    const auto &fe         = system.get_fe();
    const auto &elasticity = system.get_elasticity();
    // The weight is smooth but only C3 at the edge of its support: a few extra
    // points, and cells and faces that the edge crosses split into 4 x 4 (4)
    // in 2D, 2 x 2 x 2 (2 x 2) in 3D, where 64 sub-cells per crossed cell
    // would cost minutes per front point.
    // Per element of the collection: degree + 4 points per direction. The
    // fields at a cell's points come from FEEvaluation without MatrixFree:
    // sum factorisation on the tensor-product points instead of FEValues'
    // tables of every shape function at every point (the phase 19.5 s ->
    // 8.9 s on the default elliptical-gap scene, one rank; 99 s -> 31 s at
    // b/a = 0.1, degree 4, two ranks).
    using CellEvaluation =
        FEEvaluation<dim, -1, 0, dim, double, VectorizedArray<double, 1>>; // one cell at a time
    const unsigned int subdivisions = dim == 3 ? 2 : 4;
    const UpdateFlags flags = update_values | update_gradients | update_quadrature_points | update_JxW_values;
    const Mapping<dim>                          &mapping = system.get_mapping()[0];
    std::vector<std::unique_ptr<CellEvaluation>> plain_cells, edge_cells;
    hp::QCollection<dim - 1>                     face_quadrature, edge_face_quadrature;
    for (unsigned int i = 0; i < fe.size(); ++i)
      {
        const QGauss<1> points(fe[i].degree + 4);
        plain_cells.push_back(std::make_unique<CellEvaluation>(mapping, fe[i], points, flags));
        edge_cells.push_back(
            std::make_unique<CellEvaluation>(mapping, fe[i], QIterated<1>(points, subdivisions), flags));
        face_quadrature.push_back(QGauss<dim - 1>(points.size()));
        edge_face_quadrature.push_back(QIterated<dim - 1>(points, subdivisions));
      }
    const UpdateFlags     face_flags = update_gradients | update_quadrature_points | update_JxW_values;
    hp::FEFaceValues<dim> fe_face(system.get_mapping(), fe, face_quadrature, face_flags),
        fe_edge_face(system.get_mapping(), fe, edge_face_quadrature, face_flags);
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n_fields = loads.size();
    // Per field: gradients and values at the quadrature points, then the
    // 3x3 gradient and the stress at the current point.
    std::vector<std::vector<Tensor<2, dim>>> grads(n_fields);
    std::vector<std::vector<Tensor<1, dim>>> values_at(n_fields);
    std::vector<Tensor3>                     d(n_fields);
    std::vector<Strain>                      sigma(n_fields);
    std::vector<double>                      t(n_fields);
    std::vector<Tensor3>                     flux(pairs.size());
    std::vector<double>                      energy(pairs.size());
    std::vector<unsigned int>                touching;

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

    // [pair][extension]
    std::vector<std::vector<double>> area_term(pairs.size(), std::vector<double>(qs.size(), 0.)),
        face_term = area_term;
    for (const auto &cell : system.get_dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const bool crossing = touch(cell, cell->bounding_box());
        if (touching.empty())
          continue;
        CellEvaluation &values = *(crossing ? edge_cells : plain_cells)[cell->active_fe_index()];
        values.reinit(cell);
        for (unsigned int f = 0; f < n_fields; ++f)
          {
            values.read_dof_values(*loads[f].u);
            values.evaluate(EvaluationFlags::values | EvaluationFlags::gradients);
            grads[f].resize(values.n_q_points);
            values_at[f].resize(values.n_q_points);
            for (const unsigned int k : values.quadrature_point_indices())
              {
                const auto value = values.get_value(k);
                const auto grad  = values.get_gradient(k);
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    values_at[f][k][i] = value[i][0];
                    for (unsigned int j = 0; j < dim; ++j)
                      grads[f][k][i][j] = grad[i][j][0];
                  }
              }
          }
        for (const unsigned int k : values.quadrature_point_indices())
          {
            Point<dim> x;
            for (unsigned int i = 0; i < dim; ++i)
              x[i] = values.quadrature_point(k)[i][0];
            for (unsigned int f = 0; f < n_fields; ++f)
              {
                d[f]     = Kinematics::gradient(grads[f][k], values_at[f][k], x);
                sigma[f] = elasticity.stress(strain(d[f]));
              }
            // sigma_ij v_i,k q_k,j = (grad v^T sigma) : grad q, polarised, per pair.
            for (unsigned int p = 0; p < pairs.size(); ++p)
              {
                const auto [a, b] = pairs[p];
                energy[p]         = 0.5 * (sigma[a] * strain(d[b]));
                flux[p] = 0.5 * (transpose(d[b]) * Tensor3(sigma[a]) + transpose(d[a]) * Tensor3(sigma[b]));
              }
            const double dmu = Kinematics::measure(x) * values.JxW(k)[0];
            for (const unsigned int i : touching)
              {
                const Tensor3 grad_q = Kinematics::gradient(qs[i]->gradient(x), qs[i]->value(x), x);
                if (grad_q.norm_square() == 0)
                  continue;
                for (unsigned int p = 0; p < pairs.size(); ++p)
                  area_term[p][i] += (scalar_product(flux[p], grad_q) - energy[p] * trace(grad_q)) * dmu;
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
            for (unsigned int f = 0; f < n_fields; ++f)
              {
                grads[f].resize(face.n_quadrature_points);
                face[displacement].get_function_gradients(*loads[f].u, grads[f]);
              }
            for (const unsigned int k : face.quadrature_point_indices())
              {
                const Point<dim> &x = face.quadrature_point(k);
                for (unsigned int f = 0; f < n_fields; ++f)
                  t[f] = (*loads[f].t)(x);
                const double dmu = Kinematics::measure(x) * face.JxW(k);
                for (const unsigned int i : touching)
                  {
                    const Tensor<1, dim> qx = qs[i]->value(x);
                    for (unsigned int p = 0; p < pairs.size(); ++p)
                      {
                        const auto [a, b] = pairs[p];
                        face_term[p][i] +=
                            0.5 * (t[a] * (grads[b][k][dim - 1] * qx) + t[b] * (grads[a][k][dim - 1] * qx)) *
                            dmu;
                      }
                  }
              }
          });

    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        for (unsigned int i = 0; i < qs.size(); ++i)
          area_term[p][i] -= face_term[p][i];
        Utilities::MPI::sum(area_term[p], system.get_communicator(), area_term[p]);
        for (unsigned int i = 0; i < qs.size(); ++i)
          {
            area_term[p][i] *= 2 / qs[i]->front_measure();
            if (!std::isfinite(area_term[p][i]))
              throw std::runtime_error("J-integral: the domain integral gives NaN or Inf");
          }
      }
    return area_term;
  }

  template class DomainIntegral<Axisymmetric>;
  template class DomainIntegral<PlaneStrain>;
  template class DomainIntegral<Solid>;
} // namespace penny
