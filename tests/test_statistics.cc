// The statistical layer: PSD moments, summit statistics in both conventions,
// the aggregation over Gaussian summits against its closed form, the theta
// fit, and the area-load curve with the FE g at test size.
#include "closed_forms/adhesive_gap.h"
#include "input/input_error.h"
#include "problems/rough_surface.h"
#include "scenes/scene.h"
#include "statistics/contact_area.h"
#include "statistics/roughness.h"
#include "test_support.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

BOOST_AUTO_TEST_SUITE(test_statistics)

namespace tt = boost::test_tools;
using namespace penny;

namespace
{
  const double H = 0.7, q0 = 2e3, zeta = 300, h0 = 3e-6;

  // Profile moment m_n = int int (q cos theta)^n C(q) q dq dtheta by 2D
  // quadrature of the paper's power law, independent of the angular factors.
  double moment_by_quadrature(const int n, const double weight_power = 0)
  {
    using boost::math::quadrature::gauss_kronrod;
    const auto C = [](const double q) {
      return H / (2 * M_PI) * std::pow(h0 / q0, 2) * std::pow(q / q0, -2 * (H + 1));
    };
    const double angular = gauss_kronrod<double, 61>::integrate(
        [n](const double theta) { return std::pow(std::cos(theta), n); }, 0., 2 * M_PI, 10, 1e-15);
    // Integrate in log q: the integrand spans many decades.
    const double radial = gauss_kronrod<double, 61>::integrate(
        [&](const double log_q) {
          const double q = std::exp(log_q);
          return std::pow(q, n + weight_power + 2) * C(q);
        },
        std::log(q0), std::log(zeta * q0), 15, 1e-14);
    return angular * radial;
  }

  // Surface and pressure moments for the consistent-convention check.
  SpectralMoments test_moments()
  {
    return spectral_moments(power_law_spectrum(H, q0, zeta, h0));
  }
} // namespace

BOOST_AUTO_TEST_CASE(power_law_moments_closed_form)
{
  // m_k = gamma_k H h0^2 q0^k (zeta^(k-2H) - 1)/(k - 2H), gamma = 1, 1/2, 3/8, 5/16.
  const SpectralMoments m       = test_moments();
  const double          got[]   = {m.m0, m.m2, m.m4, m.m6};
  const double          gamma[] = {1, 0.5, 0.375, 0.3125};
  for (int i = 0; i < 4; ++i)
    {
      const int    k = 2 * i;
      const double exact =
          gamma[i] * H * h0 * h0 * std::pow(q0, k) * (std::pow(zeta, k - 2 * H) - 1) / (k - 2 * H);
      BOOST_TEST(got[i] == exact, tt::tolerance(1e-13));
      BOOST_TEST(got[i] == moment_by_quadrature(k), tt::tolerance(1e-10));
    }
  BOOST_TEST(m.m0 == h0 * h0 * (1 - std::pow(zeta, -2 * H)) / 2, tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(tabulated_spectrum_moments)
{
  // A power law sampled at many points is the same piecewise power law.
  PowerSpectrum       sampled;
  const PowerSpectrum law = power_law_spectrum(H, q0, zeta, h0);
  for (int i = 0; i <= 40; ++i)
    {
      const double q = q0 * std::pow(zeta, i / 40.);
      sampled.wavenumbers.push_back(q);
      sampled.densities.push_back(law.densities[0] * std::pow(q / q0, -2 * (H + 1)));
    }
  const SpectralMoments a = spectral_moments(sampled), b = spectral_moments(law);
  BOOST_TEST(a.m0 == b.m0, tt::tolerance(1e-12));
  BOOST_TEST(a.m6 == b.m6, tt::tolerance(1e-12));

  // A roll-off plateau C0 on [q0, 10 q0], then q^-3: m0 by hand.
  const double        C0 = 1e-20;
  const PowerSpectrum roll_off{{q0, 10 * q0, 100 * q0}, {C0, C0, C0 * 1e-3}};
  const double        plateau = 2 * M_PI * C0 * (std::pow(10 * q0, 2) - q0 * q0) / 2;
  const double        tail    = 2 * M_PI * C0 * std::pow(10 * q0, 3) * (1 / (10 * q0) - 1 / (100 * q0));
  BOOST_TEST(spectral_moments(roll_off).m0 == plateau + tail, tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(spectrum_file)
{
  const ScratchFolder scratch;
  const auto          file =
      scratch.path /
      ("psd-" + std::to_string(dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)) + ".txt");
  std::ofstream(file) << "# q C(q)\n1e3 2e-20\n\n1e4 2e-23  # comment\n";
  const PowerSpectrum spectrum = read_power_spectrum(file.string());
  BOOST_TEST(spectrum.wavenumbers.size() == 2u);
  BOOST_TEST(spectrum.densities[1] == 2e-23);
  // A UTF-8 byte-order mark before the first row is no text.
  std::ofstream(file) << "\xEF\xBB\xBF"
                      << "1e3 2e-20\n1e4 2e-23\n";
  BOOST_TEST(read_power_spectrum(file.string()).wavenumbers.front() == 1e3);

  std::ofstream(file) << "1e3 2e-20\n1e2 2e-23\n";
  BOOST_CHECK_EXCEPTION(read_power_spectrum(file.string()), InputError, [](const InputError &e) {
    return std::string(e.what()).find("line 2") != std::string::npos;
  });
  std::ofstream(file) << "1e3 abc\n";
  BOOST_CHECK_THROW(read_power_spectrum(file.string()), InputError);
  std::filesystem::remove(file);
  BOOST_CHECK_THROW(read_power_spectrum(file.string()), InputError);
}

BOOST_AUTO_TEST_CASE(pressure_summits_both_conventions)
{
  const SpectralMoments m      = test_moments();
  const double          E_star = 3e9;

  const PressureSummits paper = pressure_summits(m, E_star, Convention::paper);
  BOOST_TEST(paper.variance == E_star * E_star * m.m2 / 4, tt::tolerance(1e-14));
  BOOST_TEST(paper.density == m.m6 / (6 * std::sqrt(M_PI) * m.m4), tt::tolerance(1e-14));
  BOOST_TEST(paper.summit_radius == 0.375 * std::sqrt(2 * M_PI / m.m6) / E_star, tt::tolerance(1e-14));

  // Consistent: the pressure field's own profile moments, by quadrature of its
  // PSD (E*^2/4) q^2 C(q), then Nayak's summit formulas.
  const PressureSummits consistent = pressure_summits(m, E_star, Convention::consistent);
  const double          scale      = E_star * E_star / 4;
  const double          m0_p = scale * moment_by_quadrature(0, 2), m2_p = scale * moment_by_quadrature(2, 2),
               m4_p = scale * moment_by_quadrature(4, 2);
  BOOST_TEST(consistent.variance == m0_p, tt::tolerance(1e-10));
  BOOST_TEST(consistent.variance == E_star * E_star * m.m2 / 2, tt::tolerance(1e-13));
  BOOST_TEST(consistent.density == m4_p / (6 * M_PI * std::sqrt(3.) * m2_p), tt::tolerance(1e-10));
  BOOST_TEST(1 / consistent.summit_radius == 8. / 3 * std::sqrt(m4_p / M_PI), tt::tolerance(1e-10));

  const double K_Ic = 2e5;
  BOOST_TEST(adhesion_ratio(paper, K_Ic) == 1.2020809449045589 *
                                                std::pow(std::pow(K_Ic, 4) / paper.summit_radius, 0.2) /
                                                std::sqrt(paper.variance),
             tt::tolerance(1e-13));
  BOOST_TEST(surface_population(paper, K_Ic, Convention::paper).prefactor == std::sqrt(2 * M_PI));
  BOOST_TEST(surface_population(consistent, K_Ic, Convention::consistent).prefactor ==
                 3 * M_PI * consistent.summit_radius * consistent.density * std::sqrt(consistent.variance),
             tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(theta_fit)
{
  // Over zeta in [1e12, 1e16] the finite-bandwidth corrections are below 1e-3 (2e-4 at H = 0.9).
  for (const double hurst : {0.25, 0.4, 0.5, 0.6, 0.75, 0.9})
    for (const Convention convention : {Convention::paper, Convention::consistent})
      BOOST_TEST(std::abs(fitted_scaling_exponent(hurst, 1e12, 1e16, 41, convention) -
                          scaling_exponent(hurst)) < 1e-3);
  BOOST_TEST(scaling_exponent(0.75) == 0.2, tt::tolerance(1e-15));
}

// The consistent prefactor 3 pi R_p eta sqrt(V) of a power law is that of its
// shape alone: the same for any q0, h0, E* and K_Ic.
BOOST_AUTO_TEST_CASE(power_law_prefactor_free_of_scales)
{
  for (const double hurst : {0.3, 0.75})
    {
      const auto moments = spectral_moments(power_law_spectrum(hurst, 1e3, 300, 2e-5));
      const auto scaled  = surface_population(pressure_summits(moments, 3e9, Convention::consistent), 1e6,
                                              Convention::consistent);
      BOOST_TEST(power_law_prefactor(hurst, 300, Convention::consistent) == scaled.prefactor,
                 tt::tolerance(1e-12));
      BOOST_TEST(power_law_prefactor(hurst, 300, Convention::paper) == std::sqrt(2 * M_PI),
                 tt::tolerance(1e-15));
    }
}

BOOST_AUTO_TEST_CASE(linear_law_closed_form_against_quadrature)
{
  for (const double adhesion : {0., 0.3, 1., 2.5, 5.})
    for (double p_bar = -4; p_bar <= 6; p_bar += 0.5)
      {
        const GapPopulation gaps{std::sqrt(2 * M_PI), adhesion};
        BOOST_TEST(noncontact_area(gaps, linear_gap_law(adhesion), p_bar) ==
                       linear_law_noncontact_area(gaps, p_bar),
                   tt::tolerance(1e-10));
      }
}

BOOST_AUTO_TEST_CASE(paper_normalisation)
{
  // No adhesion, no load: all of the nominal area is gap.
  BOOST_TEST(linear_law_noncontact_area({paper_population(0.5, 1e3).prefactor, 0}, 0) == 1,
             tt::tolerance(1e-15));
  BOOST_TEST(paper_population(0.75, 1).adhesion == 1);
  BOOST_TEST(paper_population(0.75, 1e5).adhesion == 10, tt::tolerance(1e-14));
  // exp(-x^2/2) - x sqrt(pi/2) erfc(x/sqrt 2) at x = 5: full contact.
  const double area = linear_law_noncontact_area({std::sqrt(2 * M_PI), 5}, 0);
  BOOST_TEST(area == std::exp(-12.5) - 5 * std::sqrt(M_PI / 2) * std::erfc(5 / std::sqrt(2.)),
             tt::tolerance(1e-9));
  BOOST_TEST(area < 1e-6);
  BOOST_TEST(area > 0);
}

BOOST_AUTO_TEST_CASE(exact_gap_law_properties)
{
  // At P = p0 the gap has c_min, and c_min^2/(3 R_p p0) = 1/5 exactly.
  for (const double adhesion : {0.1, 1., 5.})
    {
      const GapAreaLaw law = penny::exact_gap_law(adhesion);
      BOOST_TEST(law(adhesion) == adhesion / 5, tt::tolerance(1e-10));
      // The exact gap is larger than the linear law's and tends to c^2 = 3 R_p P.
      BOOST_TEST(law(adhesion + 1) > 1.);
      BOOST_TEST(law(1e4 * adhesion) / (1e4 * adhesion) == 1, tt::tolerance(2e-2 / std::sqrt(1e4)));
      const GapPopulation gaps{std::sqrt(2 * M_PI), adhesion};
      BOOST_TEST(noncontact_area(gaps, law, 0) > linear_law_noncontact_area(gaps, 0));
    }
  BOOST_TEST(penny::exact_gap_law(0)(2.) == 2.);
}

// The paper's fit p_hat = c_hat^2/5 + 1/2 follows the exact branch within
// 0.12 p0 from p_hat = 1.3 to 4, where its linear law pi c^2 = 3 pi R_p (P -
// p0) is off by 0.35 p0 or more; summed over the summits the fit adds
// (p0/2) erfc(x/sqrt 2)/2, x = p_bar + p0, to the linear law's area.
BOOST_AUTO_TEST_CASE(fitted_gap_law_against_the_exact_branch_and_the_linear_law)
{
  for (const double adhesion : {0.5, 1., 3.})
    {
      const GapAreaLaw exact = exact_gap_law(adhesion), fitted = fitted_gap_law(adhesion),
                       linear = linear_gap_law(adhesion);
      for (double p_hat = 1.3; p_hat <= 4; p_hat += 0.1)
        {
          const double P = p_hat * adhesion;
          BOOST_TEST(std::abs(exact(P) - fitted(P)) <= 0.12 * adhesion);
          BOOST_TEST(exact(P) - linear(P) >= 0.35 * adhesion);
        }
      const GapPopulation gaps{std::sqrt(2 * M_PI), adhesion};
      for (double p_bar = -2; p_bar <= 4; p_bar += 0.5)
        BOOST_TEST(noncontact_area(gaps, fitted, p_bar) ==
                       linear_law_noncontact_area(gaps, p_bar) +
                           gaps.prefactor * adhesion / 4 * std::erfc((p_bar + adhesion) / std::sqrt(2.)),
                   tt::tolerance(1e-10));
    }
}

// Weak adhesion puts the stable gap millions of c_min out (the search had
// stopped at 2^21 c_min): the exact law then tends to the adhesionless P.
BOOST_AUTO_TEST_CASE(exact_gap_law_at_weak_adhesion)
{
  for (const double adhesion : {1e-12, 1e-30})
    BOOST_TEST(exact_gap_law(adhesion)(1.) == 1., tt::tolerance(1e-6));
}

BOOST_AUTO_TEST_CASE(tabulated_gap_law_accuracy)
{
  // Chebyshev interpolation in t reproduces a polynomial in t exactly and the
  // exact g to far below the FE accuracy.
  const double adhesion = 1, t_max = 4;
  const auto   tensions = chebyshev_tensions(adhesion, t_max, 20);
  BOOST_TEST(tensions.front() == adhesion);
  BOOST_TEST(tensions.back() == adhesion + t_max * t_max, tt::tolerance(1e-15));
  std::vector<double> linear, exact;
  const auto          exact_law = penny::exact_gap_law(adhesion);
  for (const double P : tensions)
    linear.push_back(P - adhesion), exact.push_back(exact_law(P));
  const auto linear_table = tabulated_gap_law(adhesion, t_max, linear);
  const auto exact_table  = tabulated_gap_law(adhesion, t_max, exact);
  for (double P = adhesion; P < adhesion + t_max * t_max; P += 0.37)
    {
      BOOST_TEST(linear_table(P) == P - adhesion, tt::tolerance(1e-12));
      BOOST_TEST(exact_table(P) == exact_law(P), tt::tolerance(1e-8));
    }
  BOOST_CHECK_THROW(exact_table(adhesion + 1.1 * t_max * t_max), std::out_of_range);
}

BOOST_AUTO_TEST_CASE(persson_variant)
{
  BOOST_TEST(persson_contact_area(0, 0) == 0);
  BOOST_TEST(persson_contact_area(1, -1) == 0);
  BOOST_TEST(persson_contact_area(1, -3) == 0);
  BOOST_TEST(persson_contact_area(0.5, 0.5) == std::erf(1 / std::sqrt(2.)), tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(toughness_and_amplitude_parameters)
{
  dealii::ParameterHandler prm;
  RoughSurfaceProblem      surface;
  Sections                 declaring(prm, false);
  rough_surface_sections(declaring, surface);
  prm.parse_input_from_string(
      "subsection Material\n set Young's modulus E = 1e7\n set Poisson's ratio nu = 0.49\nend\n"
      "subsection Adhesion\n set Toughness given by = G_c\n set Work of adhesion G_c = 0.05\nend\n"
      "subsection Roughness\n set Amplitude given by = rms height\n set Rms height = 2e-6\nend\n");
  Sections reading(prm, true);
  rough_surface_sections(reading, surface);
  BOOST_TEST(surface.critical_stress_intensity == std::sqrt(1e7 / (1 - 0.49 * 0.49) * 0.05),
             tt::tolerance(1e-15));
  const auto &r = surface.roughness;
  BOOST_TEST(std::sqrt(spectral_moments(power_law_spectrum(r.hurst, r.q0, r.zeta, r.amplitude)).m0) == 2e-6,
             tt::tolerance(1e-13));
}

// zero-load-gap-area reads no curve lists: in the consistent convention it
// ran only once the unused Area-load/Magnifications were set above 1.
BOOST_AUTO_TEST_CASE(zero_load_gap_area_in_the_consistent_convention)
{
  const ScratchFolder scratch;
  const Verdict       verdict = run_scene_text("set Scene = zero-load-gap-area\n"
                                                     "subsection Area-load\n set Convention = consistent\nend\n"
                                                     "subsection Zero-load gap area\n set Number of points = 3\nend\n",
                                               scratch.path);
  BOOST_TEST(verdict.passed, verdict.message);
  BOOST_TEST(std::filesystem::is_regular_file(scratch.path / "results" / "zero-load-gap-area.csv"));
}

// The scene at test size: the FE g at 8 tensions, A_nc within 1e-4 of the
// closed-form g's, and its tables.
BOOST_AUTO_TEST_CASE(fe_gap_function_aggregation)
{
  const ScratchFolder scratch;
  const Verdict       verdict = run_scene_text("set Scene = fe-gap-area\n"
                                                     "subsection Mesh\n set Tip refinement levels = 16\nend\n"
                                                     "subsection Finite element\n set Polynomial degree = 3\nend\n"
                                                     "subsection FE gap area\n set Tabulated tensions = 8\nend\n"
                                                     "subsection Area-load\n set Number of points = 4\nend\n"
                                                     "subsection Verification\n set Tolerance = 1e-4\nend\n",
                                               scratch.path);
  BOOST_TEST(verdict.passed, verdict.message);
  BOOST_TEST(std::filesystem::is_regular_file(scratch.path / "results" / "fe-gap-area.csv"));
}

BOOST_AUTO_TEST_SUITE_END()
