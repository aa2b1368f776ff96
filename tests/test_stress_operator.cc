// The axisymmetric stress operator: a uniform stress state is reproduced
// exactly at every quadrature point, and carries no energy release rate.
#define BOOST_TEST_MODULE stress_operator
#define BOOST_TEST_NO_MAIN
#include "axisymmetric_elasticity.h"
#include "j_integral.h"
#include "test_support.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using namespace penny;

namespace
{
  // u = (a r, b z): e_rr = e_tt = a, e_zz = b, no shear. With
  // b = -2 lambda a/(lambda + 2 mu) the state is s_rr = s_tt = const, s_zz = 0:
  // it satisfies u_r = 0 on the axis, u_z = 0 on z = 0, and loads no face.
  struct UniformStrain : Function<2>
  {
    double a, b;
    UniformStrain(const double a, const double b)
      : Function<2>(2), a(a), b(b)
    {}
    double value(const Point<2> &x, const unsigned int component) const override
    {
      return component == 0 ? a * x[0] : b * x[1];
    }
  };

  Parameters small_model()
  {
    Parameters parameters                 = default_parameters();
    parameters.geometry.domain_radius     = 20;
    parameters.geometry.domain_height     = 20;
    parameters.mesh.tip_levels            = 8;
    parameters.finite_element.degree      = 2;
    return parameters;
  }
} // namespace

BOOST_AUTO_TEST_CASE(uniform_stress_state)
{
  const Parameters parameters = small_model();
  TimerOutput      timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  PennyGapModel    model(parameters, timer);

  const double lambda = parameters.material.lame_lambda();
  const double mu     = parameters.material.lame_mu();
  const double a      = 1e-3;
  const double b      = -2 * lambda * a / (lambda + 2 * mu);
  const auto                   &dofs = model.dof_handler();
  TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
  VectorTools::interpolate(dofs, UniformStrain(a, b), owned);
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dofs, relevant);
  DisplacementVector u(dofs.locally_owned_dofs(), relevant, MPI_COMM_WORLD);
  u = owned;

  const double      s_rr = lambda * (2 * a + b) + 2 * mu * a;
  const QGauss<2>   quadrature(3);
  FEValues<2>       fe_values(model.finite_element(), quadrature, update_values | update_gradients | update_quadrature_points);
  std::vector<Tensor<2, 2>> grad(quadrature.size());
  std::vector<Tensor<1, 2>> value(quadrature.size());
  double            deviation = 0;
  for (const auto &cell : model.dof_handler().active_cell_iterators())
    {
      fe_values.reinit(cell);
      fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(u, grad);
      fe_values[FEValuesExtractors::Vector(0)].get_function_values(u, value);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const AxisymmetricTensor s = stress(strain(grad[q], value[q][0], fe_values.quadrature_point(q)[0]), lambda, mu);
          deviation = std::max({deviation, std::abs(s.rr - s_rr), std::abs(s.tt - s_rr), std::abs(s.zz), std::abs(s.rz)});
        }
    }
  BOOST_TEST(deviation < 1e-9 * s_rr);

  LoadParameters no_load  = parameters.load;
  no_load.type            = LoadParameters::Type::uniform;
  no_load.peak_tension    = 0;
  const FaceLoad  zero(no_load, parameters.geometry.gap_radius);
  const JIntegral j_integral(model);
  const double    c       = parameters.geometry.gap_radius;
  const double    j_scale = s_rr * s_rr / parameters.material.youngs_modulus * c;
  for (const double rho : {0.25, 0.5, 0.75})
    BOOST_TEST(std::abs(j_integral.energy_release_rate(u, zero, rho * c)) < 1e-10 * j_scale);
}

// The hoop strain u_r/r tends to d_r u_r on the axis.
BOOST_AUTO_TEST_CASE(hoop_strain_on_axis)
{
  Tensor<2, 2> grad;
  grad[0][0] = 0.25;
  BOOST_TEST(strain(grad, 0., 0.).tt == 0.25);
  BOOST_TEST(strain(grad, 0.5, 2.).tt == 0.25);
}
