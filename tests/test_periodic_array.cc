// The closed forms of Johnson's sinusoid as a periodic array of gaps, checked
// independently: K_I against the periodic-array weight function by
// quadrature, Johnson's curve and its extremes against numerical extremes,
// the critical alpha in 50-digit arithmetic, the small-alpha law, and
// Westergaard's contact pressure.
#include "closed_forms/periodic_array.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <limits>

BOOST_AUTO_TEST_SUITE(test_periodic_array)

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  // K_I of the gap |x| < c of the collinear array of period lambda under the
  // symmetric face load t(x), from the periodic-array weight function
  //   K_I = 2 sqrt(tan(theta)/lambda) int_0^c t(x) cos(pi x/lambda) dx / sqrt(sin^2 theta - sin^2(pi
  //   x/lambda)),
  // theta = pi c/lambda (Koiter; Tada's handbook), integrated with
  // sin(pi x/lambda) = sin(theta) sin(phi), which removes the singularity.
  double weight_function_sif(const double c, const double lambda, const std::function<double(double)> &t)
  {
    const double theta     = M_PI * c / lambda;
    const auto   integrand = [&](const double phi) {
      return t(lambda / M_PI * std::asin(std::sin(theta) * std::sin(phi)));
    };
    const double integral =
        lambda / M_PI *
        boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, 0., M_PI / 2, 15, 1e-15);
    return 2 * std::sqrt(std::tan(theta) / lambda) * integral;
  }
} // namespace

BOOST_AUTO_TEST_CASE(stress_intensity_factor_against_weight_function)
{
  const double lambda = 2e-3, p_star = 3e6;
  for (const double ratio : {0.01, 0.1, 0.25, 0.4, 0.49})
    for (const double p_bar : {0., 0.3 * p_star, -0.5 * p_star})
      {
        const double c = ratio * lambda;
        const double K = weight_function_sif(
            c, lambda, [&](const double x) { return p_star * std::cos(2 * M_PI * x / lambda) - p_bar; });
        BOOST_TEST(periodic_array::stress_intensity_factor(c, lambda, p_star, p_bar) == K,
                   tt::tolerance(1e-12));
      }
  // A short gap is an isolated crack: K_I -> p sqrt(pi c) under uniform tension p.
  const double c = 1e-6;
  BOOST_TEST(periodic_array::stress_intensity_factor(c, 1., 0, -1) == std::sqrt(M_PI * c),
             tt::tolerance(1e-11));
}

BOOST_AUTO_TEST_CASE(johnson_and_westergaard_curves)
{
  BOOST_TEST(periodic_array::johnson_load(0.1, 0) == std::pow(std::sin(0.1 * M_PI), 2), tt::tolerance(1e-15));
  BOOST_TEST(periodic_array::johnson_load(0.25, 0.2) == 0.3, tt::tolerance(1e-14));
  BOOST_TEST(periodic_array::johnson_load(0.5 - 1e-9, 0.2) < -100);
  for (const double load : {0.01, 0.3, 0.99})
    BOOST_TEST(periodic_array::johnson_load(periodic_array::westergaard_contact_ratio(load), 0) == load,
               tt::tolerance(1e-14));
  // K_I = K_Ic on Johnson's curve: c = lambda/2 - a, alpha = K_Ic/(p* sqrt(lambda)).
  const double lambda = 0.5, p_star = 2e6, alpha = 0.3, a = 0.17 * lambda;
  const double p_bar = p_star * periodic_array::johnson_load(a / lambda, alpha);
  BOOST_TEST(periodic_array::stress_intensity_factor(lambda / 2 - a, lambda, p_star, p_bar) ==
                 alpha * p_star * std::sqrt(lambda),
             tt::tolerance(1e-13));
}

// The extremes against Brent's method on the curve itself; Brent places a
// flat extremum only to about sqrt(epsilon) relative.
BOOST_AUTO_TEST_CASE(extremes_against_numerical_extremes)
{
  using boost::math::tools::brent_find_minima;
  for (const double alpha : {1e-4, 0.01, 0.2, 0.5, 0.6, 1.0})
    {
      const auto   jump  = periodic_array::jump_into_contact(alpha);
      const auto   pull  = periodic_array::pull_off(alpha);
      const double split = std::atan(std::sqrt(std::sqrt(0.6))) / M_PI; // the merging point, u^4 = 3/5
      const auto [a_max, minus_max] = brent_find_minima(
          [&](const double a) { return -periodic_array::johnson_load(a, alpha); }, split, 0.5 - 1e-12, 40);
      const auto [a_min, min] = brent_find_minima(
          [&](const double a) { return periodic_array::johnson_load(a, alpha); }, 1e-12, split, 40);
      BOOST_TEST(jump.load_ratio == -minus_max, tt::tolerance(1e-13));
      BOOST_TEST(jump.contact_ratio == a_max, tt::tolerance(1e-5));
      BOOST_TEST(pull.load_ratio == min, tt::tolerance(1e-11));
      BOOST_TEST(pull.contact_ratio == a_min, tt::tolerance(1e-5));
    }
  BOOST_TEST(periodic_array::jump_into_contact(0).load_ratio == 1.);
  BOOST_CHECK_THROW(periodic_array::jump_into_contact(1.1), std::invalid_argument);
}

// alpha_c = 3^(3/4)/4 in 50 digits: the double constant, the double root
// f(pi/3) = f'(pi/3) = 0 of f = sin^2 theta - alpha_c sqrt(tan theta), and
// the maximum of sin^2 theta/sqrt(tan theta) found by Brent's method.
BOOST_AUTO_TEST_CASE(critical_alpha_in_fifty_digits)
{
  using Real         = boost::multiprecision::cpp_bin_float_50;
  const Real pi      = boost::math::constants::pi<Real>();
  const Real alpha_c = pow(Real(3), Real(3) / 4) / 4;
  const Real theta   = pi / 3;
  const Real f       = pow(sin(theta), 2) - alpha_c * sqrt(tan(theta));
  const Real f_prime = sin(2 * theta) - alpha_c / (2 * sqrt(tan(theta)) * pow(cos(theta), 2));
  const Real eps     = std::numeric_limits<Real>::epsilon();
  BOOST_TEST(static_cast<double>(abs(f)) <= static_cast<double>(100 * eps));
  BOOST_TEST(static_cast<double>(abs(f_prime)) <= static_cast<double>(100 * eps));
  BOOST_TEST(periodic_array::critical_alpha == static_cast<double>(alpha_c), tt::tolerance(1e-16));
  BOOST_TEST(static_cast<double>(abs(alpha_c - Real("0.56987676423869441049839081299090900154764"))) < 1e-40);

  const auto [theta_max, minus_alpha] =
      boost::math::tools::brent_find_minima([](const Real t) { return Real(-pow(sin(t), 2) / sqrt(tan(t))); },
                                            Real(0.1), Real(1.5), std::numeric_limits<Real>::digits / 2);
  BOOST_TEST(static_cast<double>(abs(-minus_alpha - alpha_c)) < 1e-40);
  BOOST_TEST(static_cast<double>(theta_max / pi) == periodic_array::critical_contact_ratio,
             tt::tolerance(1e-20));
  // At alpha_c the maximum of Johnson's curve is zero, at a = lambda/3.
  const auto jump = periodic_array::jump_into_contact(periodic_array::critical_alpha);
  BOOST_TEST(std::abs(jump.load_ratio) < 1e-15);
  BOOST_TEST(jump.contact_ratio == 1. / 3, tt::tolerance(1e-7));
}

// 1 - p_bar_max/p* = 5 (alpha/4)^(4/5) (1 + O((alpha/4)^(4/5))) (doc/theory.md, section 6).
BOOST_AUTO_TEST_CASE(small_alpha_law)
{
  double previous = 1;
  for (const double alpha : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10})
    {
      const double deviation = std::abs((1 - periodic_array::jump_into_contact(alpha).load_ratio) /
                                            periodic_array::small_alpha_jump(alpha) -
                                        1);
      BOOST_TEST(deviation < std::pow(alpha / 4, 0.8));
      BOOST_TEST(deviation < previous);
      previous = deviation;
    }
}

BOOST_AUTO_TEST_CASE(westergaard_closed_form)
{
  // The pressure integrates to p_bar over a period and is the full-contact
  // pressure at p_bar = p*.
  for (const double ratio : {0.1, 0.5, 0.9})
    {
      const double a    = periodic_array::westergaard_contact_ratio(ratio);
      double       mean = 0;
      const int    n    = 200000;
      for (int k = 0; k < n; ++k)
        mean += periodic_array::westergaard_pressure(-0.5 + (k + 0.5) / n, ratio) / n;
      BOOST_TEST(mean == ratio, tt::tolerance(1e-6));
      BOOST_TEST(std::pow(std::sin(M_PI * a), 2) == ratio, tt::tolerance(1e-14));
    }
  BOOST_TEST(periodic_array::westergaard_pressure(0.2, 1) == 1 + std::cos(2 * M_PI * 0.2),
             tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
