// Closed forms for the periodic array of gaps of Johnson's adhesive sinusoid
// (doc/theory.md, section 6). No FE here: the sinusoid-contact scene and the
// FE scenes of the periodic model print these beside their results.
//
// A sinusoid of wavelength lambda pressed flat needs the full-contact pressure
// p_bar - p* cos(2 pi x/lambda); each gap |x| < c is a crack of a collinear
// array of period lambda whose faces carry t = p* cos(2 pi x/lambda) - p_bar.
// a = lambda/2 - c is the contact half-width, alpha = K_Ic/(p* sqrt(lambda)).
#pragma once

namespace penny::periodic_array
{
  // K_I = sqrt(lambda) [p* cos^2(pi c/lambda) - p_bar] sqrt(tan(pi c/lambda))
  // (Pa m^1/2); p* = 0, p_bar = -1 is Koiter's sqrt(lambda tan(pi c/lambda)).
  double stress_intensity_factor(double c, double wavelength, double peak_tension, double mean_pressure);

  // Johnson's curve at K_I = K_Ic, p_bar/p* = sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda)),
  // for a/lambda in (0, 1/2); alpha = 0 is Westergaard's adhesionless sin^2(pi a/lambda).
  double johnson_load(double contact_ratio, double alpha);

  // Westergaard's contact half-width a/lambda = arcsin(sqrt(p_bar/p*))/pi, 0 <= p_bar/p* <= 1.
  double westergaard_contact_ratio(double load_ratio);

  // Westergaard's contact pressure p(s)/p* = 2 cos(pi s/lambda) sqrt(sin^2(pi a/lambda) - sin^2(pi s/lambda))
  // at s/lambda from the centre of the contact strip (zero outside it), for
  // 0 < p_bar/p* <= 1; it integrates to p_bar lambda over a period.
  double westergaard_pressure(double position, double load_ratio);

  // A stationary point of Johnson's curve.
  struct LoadExtremum
  {
    double contact_ratio; // a/lambda
    double load_ratio;    // p_bar/p*
  };

  // With u^2 = tan(pi a/lambda) the curve is stationary where
  // 4 u^3 = alpha (1 + u^4)^2: a minimum (pull-off, u^4 < 3/5) and a maximum
  // (jump into full contact, u^4 > 3/5) for alpha below
  // largest_alpha_with_extremes = (25/16) (3/5)^(3/4), where they merge.
  double largest_alpha_with_extremes();

  // The largest p_bar/p* with a gap, above which the surfaces jump into full
  // contact; alpha = 0 gives a/lambda = 1/2, p_bar/p* = 1.
  LoadExtremum jump_into_contact(double alpha);

  // The smallest p_bar/p* (the largest tension) in contact; alpha = 0 gives (0, 0).
  LoadExtremum pull_off(double alpha);

  // 1 - p_bar_max/p* ~ 5 (alpha/4)^(4/5) as alpha -> 0.
  double small_alpha_jump(double alpha);

  // The alpha at which the maximum of Johnson's curve is p_bar = 0: where
  // sin^2(theta) = alpha sqrt(tan(theta)) has a double root, theta = pi/3,
  // alpha_c = sin^2(pi/3)/sqrt(tan(pi/3)) = 3^(3/4)/4 (spontaneous full
  // contact at zero load for alpha < alpha_c).
  constexpr double critical_alpha         = 0.56987676423869441; // 0.5698767642386944104983908129909...
  constexpr double critical_contact_ratio = 1. / 3;              // a/lambda at alpha_c
} // namespace penny::periodic_array
