// Richardson extrapolation: results A(h) computed at several values of a
// discretisation parameter h (a grid spacing, an interaction range), taken to
// h -> 0 under an assumed error expansion
//
//   A(h) = A_0 + c_1 h^p_1 + c_2 h^p_2 + ...    (p_1 < p_2 < ...).
//
// The error estimate is the change of the extrapolated value when the last
// term of the expansion is dropped (the same finest results, one fewer
// exponent), plus the uncertainties of the results themselves carried through
// the extrapolation's weights: a result from a previous extrapolation (in
// another parameter) brings its own error.
#pragma once

#include <vector>

namespace penny
{
  struct Extrapolated
  {
    double value;
    double error;
  };

  // A_0 from the last exponents.size() + 1 results (the finest), with h > 0
  // all different. A result's uncertainty is `errors[k]` (none if empty).
  // With one exponent the error estimate compares with the finest result
  // itself. Throws std::invalid_argument if there are too few results.
  Extrapolated extrapolate(const std::vector<double> &h, const std::vector<double> &values,
                           const std::vector<double> &exponents, const std::vector<double> &errors = {});

  // Results A(l, h) on a table, values[k][m] at (l[k], h[m]): each row
  // extrapolated to h -> 0 (exponents_h), then the row limits to l -> 0
  // (exponents_l), the rows' error estimates carried into the second step.
  Extrapolated extrapolate_in_both(const std::vector<double> &l, const std::vector<double> &h,
                                   const std::vector<std::vector<double>> &values,
                                   const std::vector<double>              &exponents_l,
                                   const std::vector<double>              &exponents_h);

  // The error exponent that three results at h, h/r, h/r^2 show:
  // log((A_0 - A_1)/(A_1 - A_2))/log(r) (NaN if the differences change sign).
  double observed_order(double coarse, double middle, double fine, double ratio);
} // namespace penny
