// Summits of a random field on a periodic grid and their statistics over
// realisations (doc/theory.md, sections 4 and 7), beside their expectation for a
// Gaussian field (Nayak's 1971 closed forms when the spectrum is isotropic).
// For the full-contact pressure the heights are in Pa, the curvatures in
// Pa/m^2 and the densities in 1/m^2; the same code serves any field (heights
// in m give curvatures in 1/m).
//
// R_p: the layer's gap law needs p = P - r^2/(2 R_p) near a summit, an
// axisymmetric paraboloid. A real summit has two principal curvatures
// k1 <= k2 of -p; we take their mean (k1 + k2)/2 = -lap(p)/2 as the summit's
// 1/R_p, the quantity whose expectation over summits Nayak gives as
// (8/3) sqrt(m4/pi) and pressure_summits() (consistent) inverts into R_p.
#pragma once

#include "statistics/random_field.h"

#include <vector>

namespace penny
{
  struct Summit
  {
    double x, y;                         // position (m)
    double height;                       // field value at the summit
    double curvature_min, curvature_max; // principal curvatures of -f (positive at a summit)

    double mean_curvature() const { return (curvature_min + curvature_max) / 2; }
  };

  // Summits: grid points above their 8 neighbours (ties go to the lower
  // index), each followed to the maximum of the field by Newton's method on
  // its cubic Taylor model about the nearest grid point, built from spectral
  // derivatives (exact for a band-limited field; a 3 x 3 finite-difference fit
  // would underestimate curvatures by sinc^2(q dx/2), 5 % at 8 points per
  // wavelength). Height and principal curvatures are the model's at the
  // maximum, errors O((q dx)^4) and O((q dx)^2) relative for a wavenumber q.
  // A grid maximum whose iteration does not reach a maximum (-H positive
  // definite) within two cells is not a summit: on a nearly flat ridge oblique
  // to the grid the samples rise and fall with the distance from the crest.
  // Grid maxima that reach the same summit count once. The whole field:
  // std::invalid_argument on a grid split over ranks.
  std::vector<Summit> find_summits(const FourierTransform &transform, const GridField &field);

  // Equal height bins [min, max) for the summit height distribution.
  struct HeightBins
  {
    double       min, max;
    unsigned int n;

    double width() const { return (max - min) / n; }
  };

  // What one realisation contributes: summit count on its area, the sum of
  // the summits' mean curvatures, and per height bin the count and the sums
  // of mean curvature and its square. pack()/unpack() turn it into a row of
  // doubles for MPI.
  struct SummitSample
  {
    double              area;
    double              n_summits;
    double              curvature_sum;
    std::vector<double> bin_counts, bin_curvature_sums, bin_curvature_squares;

    std::vector<double> pack() const;
    static SummitSample unpack(const std::vector<double> &row, unsigned int n_bins);
  };
  SummitSample summarise_summits(const std::vector<Summit> &summits, double area, const HeightBins &bins);

  struct Estimate
  {
    double value, standard_error;
  };

  // Over realisations: the summit density (mean of the realisations'
  // densities, standard error from their scatter), the mean curvature over
  // all summits (a ratio estimate; its standard error from the realisations'
  // scatter, so correlations within a realisation are accounted for), and per
  // height bin the summit density per unit height (1/(m^2 unit)) and the
  // mean curvature of the bin's summits (standard error from their spread).
  struct SummitEnsemble
  {
    struct Bin
    {
      double   height_low, height_high;
      double   n_summits;
      Estimate density_per_height;
      Estimate mean_curvature;
    };
    unsigned int     n_realisations;
    double           n_summits;
    Estimate         density;
    Estimate         mean_curvature;
    std::vector<Bin> bins;
  };
  SummitEnsemble summit_ensemble(const std::vector<SummitSample> &samples, const HeightBins &bins);

  // Expected summits of a stationary Gaussian field whose spectrum has the
  // symmetry of the square (x <-> y, x -> -x): isotropic spectra and the
  // lattice sums of a periodic grid (FieldMoments m0, m2, m4, m22). By the
  // Kac-Rice formula the summits per area at height z with mean curvature s
  // are N(z; 0, m0)/(2 pi m2) (zero gradient) times the density of s given z
  // times E[det(-H) 1{-H positive definite}] over the deviatoric part of the
  // Hessian H. With s = -(f_xx + f_yy)/2, d1 = (f_xx - f_yy)/2, d2 = f_xy:
  //   s | z ~ N(m2 z/m0, (m4 + m22)/2 - m2^2/m0),  d1 ~ N(0, (m4 - m22)/2),  d2 ~ N(0, m22),
  // independent, and det(-H) = s^2 - d1^2 - d2^2. The integrals over s and
  // the radius of (d1, d2) are closed forms (truncated Gaussian moments), the
  // angle of (d1, d2) is summed by the trapezoidal rule (periodic, so
  // spectrally accurate; exact when isotropic). For an isotropic spectrum
  // (m22 = m4/3) these are Nayak's (1971) results: density
  // m4/(6 pi sqrt(3) m2) and mean curvature (8/3) sqrt(m4/pi), the consistent
  // convention's eta and 1/R_p. Needs (m4 + m22)/2 > m2^2/m0 (a spectrum wider
  // than one ring).
  // Whether `moments` admit these expectations: (m4 + m22)/2 > m2^2/m0 and
  // 0 < m22 < m4 (false for a lattice whose wavevectors all have one length).
  bool summits_have_expectation(const FieldMoments &moments);

  struct ExpectedSummits
  {
    double density;        // summits per area
    double mean_curvature; // of (k1 + k2)/2, averaged over the summits
  };
  ExpectedSummits expected_summits(const FieldMoments &moments);

  // Resolved by height z (the field's mean is zero): summits per area per
  // unit height, and the mean curvature of the summits at z.
  double summit_height_density(const FieldMoments &moments, double height);
  double summit_mean_curvature_at(const FieldMoments &moments, double height);

  // The layer's adhesionless isolated-gap law (doc/theory.md, section 1: a summit
  // of peak tension P = z - p_bar > 0 holds a penny gap of area 3 pi R_p P)
  // summed over the summits of a Gaussian tension field with these moments,
  // each with its own height and R_p = 1/kappa, kappa its mean curvature:
  //   A_nc/A_0 = int_{p_bar}^inf 3 pi (z - p_bar) n(z) E[1/kappa | z] dz,
  // n(z) and the law of kappa given z as above (adaptive Gauss-Kronrod in z
  // and kappa). The layer's closed forms instead weight the heights with the
  // field's own Gaussian and use one R_p for all summits.
  double expected_gap_area(const FieldMoments &moments, double mean_pressure);

  // The same law, with adhesion, summed over sampled summits of a tension
  // field (Pa; -p_fc for the full-contact pressure p_fc): a summit of height z
  // and mean curvature kappa holds, at mean pressure p_bar, a penny gap of
  // peak tension P = z - p_bar and R_p = 1/kappa, of radius the stable
  // branch of K_I = K_Ic (closed_forms/adhesive_gap.h; none where P < p0 of
  // that summit; c^2 = 3 R_p P without adhesion, K_Ic = 0). Returns the gaps'
  // area over `area`.
  double sampled_gap_area(const std::vector<Summit> &summits, double area, double mean_pressure, double K_Ic);

  // The tension field -p_fc of the surface `heights` (m) on a half-space of
  // modulus E* (Pa): its moments (m0 = V), its summits and their mean
  // curvature (of (k1 + k2)/2, Pa/m^2; 0 without summits). The whole field,
  // as find_summits.
  struct TensionSummits
  {
    FieldMoments        moments;
    std::vector<Summit> summits;
    double              mean_curvature;
  };
  TensionSummits tension_summits(const FourierTransform &transform, const GridField &heights, double E_star);
} // namespace penny
