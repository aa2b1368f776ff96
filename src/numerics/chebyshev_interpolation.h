// Polynomial interpolation on Chebyshev points (of the second kind, the
// ends included) by the barycentric formula: for a function analytic near
// the interval the error falls geometrically with the number of points, so
// a dozen samples of an expensive smooth function stand in for it to many
// digits. The values may be of any type with a weighted sum, hence the
// interpolant is given as its cardinal weights.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace penny
{
  class ChebyshevPoints
  {
  public:
    // n >= 2 points on [lo, hi], from hi down to lo.
    ChebyshevPoints(const double lo, const double hi, const unsigned int n) : lo(lo), hi(hi)
    {
      if (!(n >= 2 && lo < hi))
        throw std::invalid_argument("Chebyshev points: need n >= 2 on an interval lo < hi");
      for (unsigned int j = 0; j < n; ++j)
        points.push_back(lo + (hi - lo) * (1 + std::cos(M_PI * j / (n - 1))) / 2);
    }

    const std::vector<double> &nodes() const { return points; }

    // c_j(x), the interpolant at x of the data that are 1 at point j and 0 at
    // the others: the interpolant of f is sum_j c_j(x) f_j. An x beyond an
    // end by rounding (1e-14 of the interval) is taken as that end.
    std::vector<double> cardinal_weights(double x) const
    {
      const double rounding = 1e-14 * (hi - lo);
      if (!(x >= lo - rounding && x <= hi + rounding))
        throw std::out_of_range("Chebyshev interpolation: " + std::to_string(x) + " lies outside [" +
                                std::to_string(lo) + ", " + std::to_string(hi) + "]");
      x                     = std::clamp(x, lo, hi);
      const unsigned int  n = points.size();
      std::vector<double> c(n, 0.);
      double              sum = 0;
      for (unsigned int j = 0; j < n; ++j)
        {
          if (x == points[j])
            {
              std::fill(c.begin(), c.end(), 0.);
              c[j] = 1;
              return c;
            }
          // The barycentric weights (-1)^j, halved at the ends.
          const double w = (j % 2 ? -1. : 1.) * (j == 0 || j == n - 1 ? 0.5 : 1.);
          c[j]           = w / (x - points[j]);
          sum += c[j];
        }
      for (double &cj : c)
        cj /= sum;
      return c;
    }

  private:
    double              lo, hi;
    std::vector<double> points;
  };
} // namespace penny
