#include "output/field_output.h"

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <sstream>

namespace penny
{
  using namespace dealii;

  namespace
  {
    class StressPostprocessor : public DataPostprocessor<2>
    {
    public:
      StressPostprocessor(const IsotropicElasticity &elasticity, const RingExtension<2> &ring)
          : elasticity(elasticity), ring(ring)
      {
      }

      void
      evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &inputs,
                            std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int k = 0; k < inputs.evaluation_points.size(); ++k)
          {
            Tensor<2, 2> grad_u;
            Tensor<1, 2> u;
            for (unsigned int i = 0; i < 2; ++i)
              {
                grad_u[i] = inputs.solution_gradients[k][i];
                u[i]      = inputs.solution_values[k][i];
              }
            const Point<2> &x = inputs.evaluation_points[k];
            const Strain    s = elasticity.stress(strain(Axisymmetric::gradient(grad_u, u, x)));
            computed[k][0]    = s[0][0];
            computed[k][1]    = s[1][1];
            computed[k][2]    = s[2][2];
            computed[k][3]    = s[0][1];
            computed[k][4]    = von_mises(s);
            computed[k][5]    = ring.weight(x);
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return { "sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz", "von_mises", "q_weight" };
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
            6, DataComponentInterpretation::component_is_scalar);
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values | update_gradients | update_quadrature_points;
      }

    private:
      const IsotropicElasticity elasticity;
      const RingExtension<2>    ring;
    };
  } // namespace

  // Every rank writes its cells into one file (MPI I/O) in the staging folder.
  void
  write_fields(const LinearElasticSystem<Axisymmetric> &system,
               const DisplacementVector                &displacement,
               const RingExtension<2>                  &ring,
               const ResultFolder                      &results)
  {
    const StressPostprocessor stresses(system.get_elasticity(), ring);
    DataOut<2>                data_out;
    data_out.attach_dof_handler(system.get_dof_handler());
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(2, "displacement"),
                             DataOut<2>::type_dof_data,
                             std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                                 2, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(displacement, stresses);
    data_out.build_patches(system.get_fe().degree);
    data_out.write_vtu_in_parallel((results.staging() / "solution.vtu").string(), system.get_communicator());

    std::ostringstream pvd;
    DataOutBase::write_pvd_record(pvd, { { 0., "solution.vtu" } });
    results.write("solution.pvd", pvd.str());
  }
} // namespace penny
