// The elasticity operator of the axisymmetric model: a uniform stress state is
// reproduced exactly at every quadrature point, with one degree and with
// degrees graded towards the tip, and carries no energy release rate; the hoop strain on the axis; plane
// strain has no out-of-plane strain.
#include "fe/elasticity.h"
#include "fe/penny_gap_model.h"
#include "fracture/crack_extension.h"
#include "fracture/domain_integral.h"
#include "test_support.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <iostream>

BOOST_AUTO_TEST_SUITE(test_stress_operator)

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
    UniformStrain(const double a, const double b) : Function<2>(2), a(a), b(b) {}
    double value(const Point<2> &x, const unsigned int component) const override
    {
      return component == 0 ? a * x[0] : b * x[1];
    }
  };
} // namespace

// With one degree, and with degrees 1 ... 4 graded towards the tip (hp).
BOOST_DATA_TEST_CASE(uniform_stress_state, boost::unit_test::data::make({0u, 2u}), levels_per_degree)
{
  auto model                   = test_size_model(8, 4);
  model.geometry.domain_radius = 20;
  model.geometry.domain_height = 20;
  model.levels_per_degree      = levels_per_degree;
  TimerOutput   timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  PennyGapModel gap(model, timer);

  const auto                   &system = gap.get_system();
  const double                  lambda = system.get_elasticity().lambda;
  const double                  mu     = system.get_elasticity().mu;
  const double                  a      = 1e-3;
  const double                  b      = -2 * lambda * a / (lambda + 2 * mu);
  const auto                   &dofs   = system.get_dof_handler();
  TrilinosWrappers::MPI::Vector owned(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
  VectorTools::interpolate(dofs, UniformStrain(a, b), owned);
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dofs, relevant);
  DisplacementVector u(dofs.locally_owned_dofs(), relevant, MPI_COMM_WORLD);
  u = owned;

  const double              s_rr = lambda * (2 * a + b) + 2 * mu * a;
  hp::FEValues<2>           hp_values(system.get_mapping(), system.get_fe(), system.gauss(1),
                                      update_values | update_gradients | update_quadrature_points);
  std::vector<Tensor<2, 2>> grad;
  std::vector<Tensor<1, 2>> value;
  double                    deviation = 0;
  std::vector<unsigned int> cells_of_degree(5, 0);
  for (const auto &cell : dofs.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        hp_values.reinit(cell);
        const FEValues<2> &fe_values = hp_values.get_present_fe_values();
        ++cells_of_degree[cell->get_fe().degree];
        grad.resize(fe_values.n_quadrature_points);
        value.resize(fe_values.n_quadrature_points);
        fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(u, grad);
        fe_values[FEValuesExtractors::Vector(0)].get_function_values(u, value);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Strain s = system.get_elasticity().stress(
                strain(Axisymmetric::gradient(grad[q], value[q], fe_values.quadrature_point(q))));
            deviation = std::max({deviation, std::abs(s[0][0] - s_rr), std::abs(s[2][2] - s_rr),
                                  std::abs(s[1][1]), std::abs(s[0][1])});
          }
      }
  BOOST_TEST(Utilities::MPI::max(deviation, MPI_COMM_WORLD) < 1e-9 * s_rr);
  // Graded: 4 on cells c/2 or wider, down to 1 on the cells c/2^6 and smaller.
  Utilities::MPI::sum(cells_of_degree, MPI_COMM_WORLD, cells_of_degree);
  const auto n_degrees =
      std::count_if(cells_of_degree.begin(), cells_of_degree.end(), [](unsigned n) { return n > 0; });
  BOOST_TEST(n_degrees == (levels_per_degree == 0 ? 1 : 4));

  const DomainIntegral<Axisymmetric>::Traction no_load = [](const Point<2> &) { return 0.; };
  const DomainIntegral<Axisymmetric>           j_integral(system, model.material.plane_strain_modulus());
  const double                                 c       = model.geometry.gap_radius;
  const double                                 j_scale = s_rr * s_rr / model.material.youngs_modulus * c;
  for (const double rho : {0.25, 0.5, 0.75})
    {
      const RingExtension<2> ring(gap.crack_tip(), rho * c, c);
      BOOST_TEST(std::abs(j_integral.bilinear({{&u, &no_load}}, {{0, 0}}, {&ring})[0][0]) < 1e-10 * j_scale);
    }
}

// The hoop strain u_r/r tends to d_r u_r on the axis.
BOOST_AUTO_TEST_CASE(hoop_strain_on_axis)
{
  Tensor<2, 2> grad;
  grad[0][0] = 0.25;
  BOOST_TEST(Axisymmetric::gradient(grad, Tensor<1, 2>({0., 0.}), Point<2>(0, 1))[2][2] == 0.25);
  BOOST_TEST(Axisymmetric::gradient(grad, Tensor<1, 2>({0.5, 0.}), Point<2>(2, 1))[2][2] == 0.25);
  BOOST_TEST(PlaneStrain::gradient(grad, Tensor<1, 2>({0.5, 0.}), Point<2>(2, 1))[2][2] == 0.);
}

// sigma = lambda tr(e) I + 2 mu e, and von Mises of a uniaxial stress is its value.
BOOST_AUTO_TEST_CASE(hooke_and_von_mises)
{
  const IsotropicElasticity elasticity{2., 3.};
  Strain                    e;
  e[0][0]            = 1e-3;
  e[0][1]            = 2e-3;
  const Strain sigma = elasticity.stress(e);
  BOOST_TEST(sigma[0][0] == 2 * 1e-3 + 2 * 3 * 1e-3, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(sigma[1][1] == 2 * 1e-3, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(sigma[0][1] == 2 * 3 * 2e-3, boost::test_tools::tolerance(1e-15));
  Strain uniaxial;
  uniaxial[1][1] = -7;
  BOOST_TEST(von_mises(uniaxial) == 7., boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
