#include "output/field_output.h"

#include "closed_forms/sneddon_solution.h"
#include "fe/boundary_faces.h"
#include "fe/boundary_ids.h"
#include "output/table.h"
#include "output/vtu_writer.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    const std::vector<std::string> field_names = {"u_r",        "u_z",      "sigma_rr",  "sigma_zz",
                                                  "sigma_hoop", "sigma_rz", "von_mises", "q_weight"};

    // The fields at points given in a frame x = origin + scale * x_frame (the
    // physical frame: origin 0, scale 1), in which gradients are scale times
    // the physical ones.
    class FieldPostprocessor : public DataPostprocessor<2>
    {
    public:
      FieldPostprocessor(const IsotropicElasticity &elasticity, const RingExtension<2> &ring,
                         const Point<2> &origin, const double scale)
          : elasticity(elasticity), ring(ring), origin(origin), scale(scale)
      {
      }

      void evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &inputs,
                                 std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int k = 0; k < inputs.evaluation_points.size(); ++k)
          {
            Tensor<2, 2> grad_u;
            Tensor<1, 2> u;
            for (unsigned int i = 0; i < 2; ++i)
              {
                grad_u[i] = inputs.solution_gradients[k][i] / scale;
                u[i]      = inputs.solution_values[k][i];
              }
            const Point<2> x = origin + scale * inputs.evaluation_points[k];
            const Strain   s = elasticity.stress(strain(Axisymmetric::gradient(grad_u, u, x)));
            computed[k][0]   = u[0];
            computed[k][1]   = u[1];
            computed[k][2]   = s[0][0];
            computed[k][3]   = s[1][1];
            computed[k][4]   = s[2][2];
            computed[k][5]   = s[0][1];
            computed[k][6]   = von_mises(s);
            computed[k][7]   = ring.weight(x);
          }
      }

      std::vector<std::string> get_names() const override { return field_names; }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
            field_names.size(), DataComponentInterpretation::component_is_scalar);
      }

      UpdateFlags get_needed_update_flags() const override
      {
        return update_values | update_gradients | update_quadrature_points;
      }

    private:
      const IsotropicElasticity elasticity;
      const RingExtension<2>    ring;
      const Point<2>            origin;
      const double              scale;
    };

    // x -> (x - tip)/c - x: the displacement that maps a cell into the tip frame.
    class TipFrameShift : public Function<2>
    {
    public:
      TipFrameShift(const Point<2> &tip) : Function<2>(2), tip(tip) {}

      double value(const Point<2> &x, const unsigned int component) const override
      {
        return (x[component] - tip[component]) / tip[0] - x[component];
      }

    private:
      const Point<2> tip;
    };

    DataOutBase::VtkFlags field_vtk_flags()
    {
      DataOutBase::VtkFlags flags;
      flags.write_higher_order_cells = true;
      flags.physical_units           = {{"u", "m"}, {"u_r", "m"}, {"u_z", "m"}};
      for (const std::string stress : {"sigma_rr", "sigma_zz", "sigma_hoop", "sigma_rz", "von_mises"})
        flags.physical_units[stress] = "Pa";
      flags.physical_units["q_weight"] = "1";
      return flags;
    }

  } // namespace

  void write_fields(const LinearElasticSystem<Axisymmetric> &system, const DisplacementVector &displacement,
                    const RingExtension<2> &ring, const Point<2> &tip, const ResultFolder &results)
  {
    const auto        &dof_handler = system.get_dof_handler();
    const unsigned int degree      = system.degree();
    const auto         add_fields  = [&](VtuPieces<2> &data_out, const FieldPostprocessor &fields) {
      data_out.attach_dof_handler(dof_handler);
      data_out.add_data_vector(displacement, std::vector<std::string>(2, "u"), DataOut<2>::type_dof_data,
                                        std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                                   2, DataComponentInterpretation::component_is_part_of_vector));
      data_out.add_data_vector(displacement, fields);
    };

    const FieldPostprocessor physical(system.get_elasticity(), ring, Point<2>(), 1);
    VtuPieces<2>             whole;
    add_fields(whole, physical);
    whole.build_patches(degree);
    write_vtu(whole, "solution", field_vtk_flags(), results, system.get_communicator());

    // The tip frame: the same fields on the cells near the tip, drawn through
    // a mapping whose displacement is the affine map x -> (x - tip)/c, exact
    // in bilinear elements on the straight-sided cells.
    DoFHandler<2> frame_dofs(dof_handler.get_triangulation());
    frame_dofs.distribute_dofs(FESystem<2>(FE_Q<2>(1), 2));
    TrilinosWrappers::MPI::Vector owned_shift(frame_dofs.locally_owned_dofs(), system.get_communicator());
    VectorTools::interpolate(frame_dofs, TipFrameShift(tip), owned_shift);
    DisplacementVector shift(frame_dofs.locally_owned_dofs(),
                             DoFTools::extract_locally_relevant_dofs(frame_dofs), system.get_communicator());
    shift = owned_shift;
    const MappingQEulerian<2, DisplacementVector> tip_frame(1, frame_dofs, shift);
    const FieldPostprocessor                      in_tip_frame(system.get_elasticity(), ring, tip, tip[0]);
    VtuPieces<2>                                  near_tip;
    add_fields(near_tip, in_tip_frame);
    near_tip.set_cell_selection([&](const typename Triangulation<2>::cell_iterator &cell) {
      return cell->is_active() && cell->is_locally_owned() && std::abs(cell->center()[0] - tip[0]) < tip[0] &&
             cell->center()[1] < tip[0];
    });
    near_tip.build_patches(tip_frame, degree, DataOut<2>::curved_inner_cells);
    write_vtu(near_tip, "solution-tip", field_vtk_flags(), results, system.get_communicator());
  }

  void write_displacement(const LinearElasticSystem<PlaneStrain> &system,
                          const DisplacementVector &displacement, const ResultFolder &results)
  {
    VtuPieces<2> data_out;
    data_out.attach_dof_handler(system.get_dof_handler());
    data_out.add_data_vector(displacement, std::vector<std::string>(2, "u"), DataOut<2>::type_dof_data,
                             std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                                 2, DataComponentInterpretation::component_is_part_of_vector));
    data_out.build_patches(system.degree());
    DataOutBase::VtkFlags flags;
    flags.write_higher_order_cells = true;
    flags.physical_units           = {{"u", "m"}};
    write_vtu(data_out, "solution", flags, results, system.get_communicator());
  }

  void write_opening_profile(const LinearElasticSystem<Axisymmetric> &system,
                             const DisplacementVector &displacement, const FaceLoad &load,
                             const double gap_radius, const double plane_strain_modulus,
                             const ResultFolder &results)
  {
    // Each face's ends and middle, whatever the element's degree.
    hp::QCollection<1> ends_and_middle;
    for (unsigned int i = 0; i < system.get_fe().size(); ++i)
      ends_and_middle.push_back(QGaussLobatto<1>(3));
    hp::FEFaceValues<2>                    fe_face(system.get_mapping(), system.get_fe(), ends_and_middle,
                                                   update_values | update_quadrature_points);
    const FEValuesExtractors::Vector       u(0);
    std::vector<Tensor<1, 2>>              values(3);
    std::vector<std::pair<double, double>> profile; // (r, u_z)
    for_each_boundary_face(system.get_dof_handler(), boundary_id::gap_face, fe_face,
                           [&](const auto &, const FEFaceValues<2> &face) {
                             face[u].get_function_values(displacement, values);
                             for (const unsigned int q : face.quadrature_point_indices())
                               profile.emplace_back(face.quadrature_point(q)[0], values[q][1]);
                           });
    std::vector<std::pair<double, double>> all;
    for (const auto &part : Utilities::MPI::gather(system.get_communicator(), profile))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    all.erase(
        std::unique(all.begin(), all.end(), [](const auto &a, const auto &b) { return a.first == b.first; }),
        all.end());

    // The exact profile on rank 0 only: it may cost a quadrature per point.
    Table table({"r (m)", "r/c", "w FE (m)", "w exact (m)"});
    if (Utilities::MPI::this_mpi_process(system.get_communicator()) == 0)
      {
        const SneddonSolution exact(load, gap_radius, plane_strain_modulus);
        for (const auto &[r, w] : all)
          table.add_row({r, r / gap_radius, w, exact.opening(r).value});
      }
    results.write_csv("opening.csv", table);
  }
} // namespace penny
