#include "field_output.h"

#include "axisymmetric_elasticity.h"
#include "output_files.h"

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

namespace penny
{
  using namespace dealii;

  namespace
  {
    class StressPostprocessor : public DataPostprocessor<2>
    {
    public:
      StressPostprocessor(const MaterialParameters &material, const RingWeight &ring)
        : lambda(material.lame_lambda())
        , mu(material.lame_mu())
        , ring(ring)
      {}

      void evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &inputs,
                                 std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int k = 0; k < inputs.evaluation_points.size(); ++k)
          {
            Tensor<2, 2> grad_u;
            for (unsigned int i = 0; i < 2; ++i)
              grad_u[i] = inputs.solution_gradients[k][i];
            const Point<2>          &x = inputs.evaluation_points[k];
            const AxisymmetricTensor s = stress(strain(grad_u, inputs.solution_values[k][0], x[0]), lambda, mu);
            computed[k][0] = s.rr;
            computed[k][1] = s.zz;
            computed[k][2] = s.tt;
            computed[k][3] = s.rz;
            computed[k][4] = von_mises(s);
            computed[k][5] = ring.value(x);
          }
      }

      std::vector<std::string> get_names() const override
      {
        return {"sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz", "von_mises", "q_weight"};
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          6, DataComponentInterpretation::component_is_scalar);
      }

      UpdateFlags get_needed_update_flags() const override
      {
        return update_values | update_gradients | update_quadrature_points;
      }

    private:
      const double      lambda, mu;
      const RingWeight  ring;
    };
  } // namespace

  namespace
  {
    // Every rank writes its cells into one file (MPI I/O), renamed into place by rank 0.
    void write_vtu_atomically(const DataOut<2> &data_out, const std::filesystem::path &file, const MPI_Comm comm)
    {
      const std::string partial = file.string() + ".partial";
      data_out.write_vtu_in_parallel(partial, comm);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        std::filesystem::rename(partial, file);
      MPI_Barrier(comm);
    }
  } // namespace

  void write_fields(const PennyGapModel         &model,
                    const DisplacementVector    &displacement,
                    const RingWeight            &ring,
                    const std::filesystem::path &directory)
  {
    const StressPostprocessor stresses(model.parameters().material, ring);
    DataOut<2>                data_out;
    data_out.attach_dof_handler(model.dof_handler());
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(2, "displacement"),
                             DataOut<2>::type_dof_data,
                             std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                               2, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(displacement, stresses);
    data_out.build_patches(model.finite_element().degree);

    write_vtu_atomically(data_out, directory / "solution.vtu", model.triangulation().get_communicator());
    write_atomically(directory / "solution.pvd", [&](std::ostream &out) {
      DataOutBase::write_pvd_record(out, {{0., "solution.vtu"}});
    });
  }
} // namespace penny
