// Sneddon's closed forms: the exact formulas against the adaptive quadrature,
// and a load only the quadrature handles against hand-integrated values.
#define BOOST_TEST_MODULE sneddon_solution
#define BOOST_TEST_NO_MAIN
#include "fracture/sneddon_solution.h"
#include "input/input_error.h"

#include <boost/test/unit_test.hpp>

#include <cmath>

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  const double pi      = M_PI;
  const double c       = 0.7;
  const double P       = 3e5;
  const double e_prime = 2e9;

  LoadParameters load(const LoadParameters::Type type, const double a = 1, const std::string &expression = "")
  {
    LoadParameters parameters;
    parameters.type           = type;
    parameters.peak_tension   = P;
    parameters.tension_radius = a;
    parameters.expression     = expression;
    return parameters;
  }
} // namespace

BOOST_AUTO_TEST_CASE(uniform_load, *boost::unit_test::tolerance(1e-12))
{
  const FaceLoad        p(load(LoadParameters::Type::uniform), c);
  const SneddonSolution exact(p, c, e_prime);
  BOOST_TEST(exact.stress_intensity_factor() == 2 * P * std::sqrt(c / pi));
  BOOST_TEST(exact.stress_intensity_factor_by_quadrature() == exact.stress_intensity_factor());
  for (const double r : {0., 0.3 * c, 0.9 * c, 0.999 * c})
    BOOST_TEST(exact.opening_by_quadrature(r) == exact.opening(r));
  BOOST_TEST(exact.gap_volume() == 16 * P * c * c * c / (3 * e_prime));
  BOOST_TEST(exact.gap_volume_by_quadrature() == exact.gap_volume());
}

BOOST_AUTO_TEST_CASE(parabolic_load, *boost::unit_test::tolerance(1e-12))
{
  const double          a = 1.3 * c;
  const FaceLoad        p(load(LoadParameters::Type::parabolic, a), c);
  const SneddonSolution exact(p, c, e_prime);
  BOOST_TEST(exact.stress_intensity_factor() == 2 * P * std::sqrt(c / pi) * (1 - 2 * c * c / (3 * a * a)));
  BOOST_TEST(exact.stress_intensity_factor_by_quadrature() == exact.stress_intensity_factor());
  for (const double r : {0., 0.5 * c, 0.99 * c})
    BOOST_TEST(exact.opening_by_quadrature(r) == exact.opening(r));
  BOOST_TEST(exact.gap_volume_by_quadrature() == exact.gap_volume());
}

// K_I of the parabola vanishes at c/a = sqrt(3/2) and is negative beyond.
BOOST_AUTO_TEST_CASE(parabolic_root)
{
  const double   a_root = c / std::sqrt(1.5);
  const double   scale  = P * std::sqrt(c);
  const FaceLoad at_root(load(LoadParameters::Type::parabolic, a_root), c);
  BOOST_TEST(std::abs(SneddonSolution(at_root, c, e_prime).stress_intensity_factor()) < 1e-15 * scale);
  BOOST_TEST(std::abs(SneddonSolution(at_root, c, e_prime).stress_intensity_factor_by_quadrature()) <
             1e-13 * scale);
  const FaceLoad beyond(load(LoadParameters::Type::parabolic, 0.99 * a_root), c);
  BOOST_TEST(SneddonSolution(beyond, c, e_prime).stress_intensity_factor() < 0);
  BOOST_TEST(SneddonSolution(beyond, c, e_prime).stress_intensity_factor_by_quadrature() < 0);
}

// p = P (r/c)^4: int_0^c r p/sqrt(c^2 - r^2) dr = (8/15) P c, so K_I = (16/15) P sqrt(c/pi);
// the inner opening integral is (8/15) P t^5/c^4, so w(0) = 32 P c/(75 pi E').
BOOST_AUTO_TEST_CASE(quartic_load_by_quadrature, *boost::unit_test::tolerance(1e-12))
{
  const FaceLoad        p(load(LoadParameters::Type::expression, 1, "P * (r/c)^4"), c);
  const SneddonSolution exact(p, c, e_prime);
  BOOST_TEST(exact.stress_intensity_factor() == 16. / 15 * P * std::sqrt(c / pi));
  BOOST_TEST(exact.opening(0) == 32 * P * c / (75 * pi * e_prime));
}

BOOST_AUTO_TEST_CASE(bad_expression_is_an_input_error)
{
  BOOST_CHECK_THROW(FaceLoad(load(LoadParameters::Type::expression, 1, "P * (r/"), c), InputError);
  BOOST_CHECK_THROW(FaceLoad(load(LoadParameters::Type::expression, 1, "P * x"), c), InputError);
}
