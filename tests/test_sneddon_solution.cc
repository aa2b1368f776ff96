// Sneddon's closed forms: the exact formulas against the adaptive quadrature,
// a load only the quadrature handles against hand-integrated values, and the
// far field of a gap.
#include "closed_forms/gap_far_field.h"
#include "closed_forms/sneddon_solution.h"
#include "input/input_error.h"

#include <boost/test/unit_test.hpp>

#include <cmath>

BOOST_AUTO_TEST_SUITE(test_sneddon_solution)

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

// The closed form of the load by quadrature: within `tolerance` of `expected`,
// and the quadrature's own error estimate at least the error it makes.
void check_quadrature(const ClosedForm &closed_form, const double expected, const double tolerance)
{
  BOOST_TEST(!closed_form.exact);
  BOOST_TEST(closed_form.value == expected, tt::tolerance(tolerance));
  BOOST_TEST(std::abs(closed_form.value - expected) <=
             closed_form.error_estimate + 1e-15 * std::abs(expected));
  BOOST_TEST(closed_form.relative_error_estimate() <= tolerance);
}

BOOST_AUTO_TEST_CASE(uniform_load, *boost::unit_test::tolerance(1e-13))
{
  const FaceLoad        p(load(LoadParameters::Type::uniform), c);
  const SneddonSolution exact(p, c, e_prime);
  BOOST_TEST(exact.stress_intensity_factor().exact);
  BOOST_TEST(exact.stress_intensity_factor().value == 2 * P * std::sqrt(c / pi));
  BOOST_TEST(exact.opening_at_centre().value == 4 * P * c / (pi * e_prime));
  BOOST_TEST(exact.gap_volume().value == 16 * P * c * c * c / (3 * e_prime));
  check_quadrature(exact.stress_intensity_factor_by_quadrature(), exact.stress_intensity_factor().value,
                   1e-13);
  check_quadrature(exact.opening_at_centre_by_quadrature(), exact.opening_at_centre().value, 1e-13);
  check_quadrature(exact.gap_volume_by_quadrature(), exact.gap_volume().value, 1e-13);
}

BOOST_AUTO_TEST_CASE(parabolic_load, *boost::unit_test::tolerance(1e-13))
{
  const double          a = 1.3 * c;
  const FaceLoad        p(load(LoadParameters::Type::parabolic, a), c);
  const SneddonSolution exact(p, c, e_prime);
  BOOST_TEST(exact.stress_intensity_factor().value ==
             2 * P * std::sqrt(c / pi) * (1 - 2 * c * c / (3 * a * a)));
  check_quadrature(exact.stress_intensity_factor_by_quadrature(), exact.stress_intensity_factor().value,
                   1e-13);
  check_quadrature(exact.opening_at_centre_by_quadrature(), exact.opening_at_centre().value, 1e-13);
  check_quadrature(exact.gap_volume_by_quadrature(), exact.gap_volume().value, 1e-13);
}

// K_I of the parabola vanishes at c/a = sqrt(3/2) and is negative beyond.
BOOST_AUTO_TEST_CASE(parabolic_root)
{
  const double   a_root = c / std::sqrt(1.5);
  const double   scale  = P * std::sqrt(c);
  const FaceLoad at_root(load(LoadParameters::Type::parabolic, a_root), c);
  BOOST_TEST(std::abs(SneddonSolution(at_root, c, e_prime).stress_intensity_factor().value) < 1e-15 * scale);
  BOOST_TEST(std::abs(SneddonSolution(at_root, c, e_prime).stress_intensity_factor_by_quadrature().value) <
             1e-13 * scale);
  const FaceLoad beyond(load(LoadParameters::Type::parabolic, 0.99 * a_root), c);
  BOOST_TEST(SneddonSolution(beyond, c, e_prime).stress_intensity_factor().value < 0);
  BOOST_TEST(SneddonSolution(beyond, c, e_prime).stress_intensity_factor_by_quadrature().value < 0);
}

// p = P (r/c)^4: int_0^c r p/sqrt(c^2 - r^2) dr = (8/15) P c, so K_I = (16/15) P sqrt(c/pi);
// w(0) = 32 P c/(75 pi E'); V = (16 P c^3/E') int_0^{pi/2} sin^5 cos^2 = 128 P c^3/(105 E').
BOOST_AUTO_TEST_CASE(quartic_load)
{
  const FaceLoad        p(load(LoadParameters::Type::expression, 1, "P * (r/c)^4"), c);
  const SneddonSolution exact(p, c, e_prime);
  check_quadrature(exact.stress_intensity_factor(), 16. / 15 * P * std::sqrt(c / pi), 1e-13);
  check_quadrature(exact.opening_at_centre(), 32 * P * c / (75 * pi * e_prime), 1e-13);
  check_quadrature(exact.gap_volume(), 128 * P * c * c * c / (105 * e_prime), 1e-13);
}

// Non-smooth loads, each integrated by hand (x = r/c):
// a step, p = P for x < 1/2: K_I = 2 P sqrt(c/pi) (1 - sqrt(3)/2),
// w(0) = 4 P c/(pi E') (pi/6 + 1 - sqrt(3)/2), V = 16 P c^3/(3 E') (1 - (3/4)^(3/2)).
BOOST_AUTO_TEST_CASE(step_load)
{
  const FaceLoad        p(load(LoadParameters::Type::expression, 1, "P * (r < c/2)"), c);
  const SneddonSolution exact(p, c, e_prime);
  check_quadrature(exact.stress_intensity_factor(), 2 * P * std::sqrt(c / pi) * (1 - std::sqrt(3.) / 2),
                   1e-12);
  check_quadrature(exact.opening_at_centre(), 4 * P * c / (pi * e_prime) * (pi / 6 + 1 - std::sqrt(3.) / 2),
                   1e-12);
  check_quadrature(exact.gap_volume(), 16 * P * c * c * c / (3 * e_prime) * (1 - std::pow(0.75, 1.5)), 1e-12);
}

// A square-root edge, p = P sqrt(1 - x^2): K_I = P sqrt(c/pi), w(0) = 4 P c/(pi E') (pi^2/16 + 1/4),
// V = 4 P c^3/E'.
BOOST_AUTO_TEST_CASE(square_root_edge_load)
{
  const FaceLoad        p(load(LoadParameters::Type::expression, 1, "P * sqrt(1 - (r/c)^2)"), c);
  const SneddonSolution exact(p, c, e_prime);
  check_quadrature(exact.stress_intensity_factor(), P * std::sqrt(c / pi), 1e-13);
  check_quadrature(exact.opening_at_centre(), 4 * P * c / (pi * e_prime) * (pi * pi / 16 + 0.25), 1e-13);
  check_quadrature(exact.gap_volume(), 4 * P * c * c * c / e_prime, 1e-13);
}

// A kink, p = P |x - 1/2|, from the antiderivatives of x^k/sqrt(1 - x^2),
// x^k arccos(x) and x^k sqrt(1 - x^2) on both sides of x = 1/2.
BOOST_AUTO_TEST_CASE(kinked_load)
{
  const double h  = 0.5;
  const auto   F1 = [](const double x) { return 1 - std::sqrt(1 - x * x); };
  const auto   F2 = [](const double x) { return (std::asin(x) - x * std::sqrt(1 - x * x)) / 2; };
  const auto   G0 = [](const double x) { return x * std::acos(x) - std::sqrt(1 - x * x) + 1; };
  const auto   G1 = [&](const double x) { return x * x / 2 * std::acos(x) + F2(x) / 2; };
  const auto   H1 = [](const double x) { return (1 - std::pow(1 - x * x, 1.5)) / 3; };
  const auto   H2 = [](const double x) {
    return (std::asin(x) - x * std::sqrt(1 - x * x) * (1 - 2 * x * x)) / 8;
  };
  const double K = (F1(h) / 2 - F2(h)) + (F2(1) - F2(h) - (F1(1) - F1(h)) / 2);
  const double w = (h * G0(h) - G1(h)) + (G1(1) - G1(h) - h * (G0(1) - G0(h)));
  const double V = (h * H1(h) - H2(h)) + (H2(1) - H2(h) - h * (H1(1) - H1(h)));

  const FaceLoad        p(load(LoadParameters::Type::expression, 1, "P * abs(r/c - 0.5)"), c);
  const SneddonSolution exact(p, c, e_prime);
  check_quadrature(exact.stress_intensity_factor(), 2 * P * c / std::sqrt(pi * c) * K, 1e-12);
  check_quadrature(exact.opening_at_centre(), 4 * P * c / (pi * e_prime) * w, 1e-12);
  check_quadrature(exact.gap_volume(), 16 * P * c * c * c / e_prime * V, 1e-12);
}

// p = P/sqrt(1 - x) is integrable, but K_I is infinite: an error, not a
// number (the Load subsection refuses such a load where it is read).
BOOST_AUTO_TEST_CASE(load_infinite_at_the_tip_is_an_error)
{
  const FaceLoad        p(load(LoadParameters::Type::expression, 1, "P / sqrt(1 - r/c)"), c);
  const SneddonSolution exact(p, c, e_prime);
  BOOST_CHECK_THROW(exact.stress_intensity_factor(), std::runtime_error);
}

// A load that oscillates ever faster towards the tip: the quadrature stops at
// its bound on evaluations and says how far it got.
BOOST_AUTO_TEST_CASE(unresolved_load_is_reported_not_hidden)
{
  const FaceLoad        p(load(LoadParameters::Type::expression, 1, "P * sin(1/(1 - r/c + 1e-9))"), c);
  const SneddonSolution exact(p, c, e_prime);
  BOOST_TEST(exact.stress_intensity_factor().relative_error_estimate() > 1e-8);
}

BOOST_AUTO_TEST_CASE(bad_expression_is_an_input_error)
{
  BOOST_CHECK_THROW(FaceLoad(load(LoadParameters::Type::expression, 1, "P * (r/"), c), InputError);
  BOOST_CHECK_THROW(FaceLoad(load(LoadParameters::Type::expression, 1, "P * x"), c), InputError);
}

// The far field of a gap (closed_forms/gap_far_field.h): a displacement whose
// gradient is the one returned (central differences), its stress in equilibrium, with the
// symmetry of an opening about z = 0 (u_z and the shear tractions vanish
// there), and the tail of Sneddon's penny crack on its axis,
//   u_z(0, z) = 2 (1 + nu) p/(pi E) {2 (1 - nu) [c - z atan(c/z)] + z [atan(c/z) - c z/(c^2 + z^2)]},
// with the volume D = 16 (1 - nu^2) p c^3/(3 E), to (c/z)^2.
BOOST_AUTO_TEST_CASE(gap_far_field)
{
  const double      E = 7e10, nu = 0.3, volume = 2e-3;
  const GapFarField far(volume, nu);
  const double      lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const auto        stress = [&](const dealii::Point<3> &x) {
    const auto strain = dealii::symmetrize(far.displacement_gradient(x));
    return lambda * dealii::trace(strain) * dealii::unit_symmetric_tensor<3>() + 2 * mu * strain;
  };
  const double h = 1e-4;
  for (const dealii::Point<3> &x : {dealii::Point<3>(1.3, -0.4, 0.9), dealii::Point<3>(-0.2, 2.1, -1.7)})
    {
      dealii::Tensor<2, 3> gradient;
      for (unsigned int j = 0; j < 3; ++j)
        {
          dealii::Tensor<1, 3> dx;
          dx[j]                 = h;
          const auto derivative = (far.displacement(x + dx) - far.displacement(x - dx)) / (2 * h);
          for (unsigned int i = 0; i < 3; ++i)
            gradient[i][j] = derivative[i];
        }
      const auto exact = far.displacement_gradient(x);
      BOOST_TEST((gradient - exact).norm() <= 1e-7 * exact.norm());

      dealii::Tensor<1, 3> divergence;
      for (unsigned int j = 0; j < 3; ++j)
        {
          dealii::Tensor<1, 3> dx;
          dx[j] = h;
          divergence += (stress(x + dx) - stress(x - dx)) / (2 * h) * dealii::Point<3>::unit_vector(j);
        }
      BOOST_TEST(divergence.norm() <= 1e-7 * stress(x).norm() / x.norm());
    }

  const dealii::Point<3> on_plane(0.8, -1.1, 0);
  BOOST_TEST(std::abs(far.displacement(on_plane)[2]) <= 1e-15 * far.displacement(on_plane).norm());
  BOOST_TEST(std::abs(stress(on_plane)[0][2]) + std::abs(stress(on_plane)[1][2]) <=
             1e-15 * stress(on_plane).norm());

  const double      p = 1e6, gap_radius = 0.01;
  const GapFarField penny(16 * (1 - nu * nu) * p * std::pow(gap_radius, 3) / (3 * E), nu);
  for (const double z : {10 * gap_radius, 100 * gap_radius})
    {
      const double t     = std::atan(gap_radius / z);
      const double exact = 2 * (1 + nu) * p / (pi * E) *
                           (2 * (1 - nu) * (gap_radius - z * t) +
                            z * (t - gap_radius * z / (gap_radius * gap_radius + z * z)));
      BOOST_TEST(penny.displacement({0, 0, z})[2] == exact, tt::tolerance(2 * std::pow(gap_radius / z, 2)));
    }
}

BOOST_AUTO_TEST_SUITE_END()
