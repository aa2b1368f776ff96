#include "contact/extrapolation.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace penny
{
  namespace
  {
    // The weights w_k with A_0 = sum_k w_k A_k for A(h) = A_0 + sum_j c_j h^p_j
    // through the last exponents.size() + 1 points: the first row of the
    // inverse of the (Vandermonde-like) matrix [1, h_k^p_1, h_k^p_2, ...].
    Eigen::VectorXd weights(const std::vector<double> &h, const std::vector<double> &exponents)
    {
      const std::size_t m = exponents.size() + 1, first = h.size() - m;
      Eigen::MatrixXd   design(m, m);
      for (std::size_t k = 0; k < m; ++k)
        {
          design(k, 0) = 1;
          for (std::size_t j = 0; j < exponents.size(); ++j)
            design(k, j + 1) = std::pow(h[first + k], exponents[j]);
        }
      Eigen::VectorXd unit = Eigen::VectorXd::Zero(m);
      unit(0)              = 1;
      return design.transpose().fullPivLu().solve(unit);
    }
  } // namespace

  Extrapolated extrapolate(const std::vector<double> &h, const std::vector<double> &values,
                           const std::vector<double> &exponents, const std::vector<double> &errors)
  {
    if (h.size() != values.size() || (!errors.empty() && errors.size() != values.size()))
      throw std::invalid_argument("extrapolate: as many parameters, results and errors are needed");
    if (exponents.empty() || h.size() < exponents.size() + 1)
      throw std::invalid_argument("extrapolate: an expansion with n exponents needs at least n + 1 results");
    const auto combine = [&](const Eigen::VectorXd &w) {
      Extrapolated result{0, 0};
      for (long k = 0; k < w.size(); ++k)
        {
          const std::size_t index = values.size() - w.size() + k;
          result.value += w(k) * values[index];
          if (!errors.empty())
            result.error += std::abs(w(k)) * errors[index];
        }
      return result;
    };
    Extrapolated result = combine(weights(h, exponents));
    const double lower  = exponents.size() > 1
                              ? combine(weights(h, {exponents.begin(), exponents.end() - 1})).value
                              : values.back();
    result.error += std::abs(result.value - lower);
    return result;
  }

  Extrapolated extrapolate_in_both(const std::vector<double> &l, const std::vector<double> &h,
                                   const std::vector<std::vector<double>> &values,
                                   const std::vector<double>              &exponents_l,
                                   const std::vector<double>              &exponents_h)
  {
    std::vector<double> limits, errors;
    for (const std::vector<double> &row : values)
      {
        const Extrapolated limit = extrapolate(h, row, exponents_h);
        limits.push_back(limit.value);
        errors.push_back(limit.error);
      }
    return extrapolate(l, limits, exponents_l, errors);
  }

  double observed_order(const double coarse, const double middle, const double fine, const double ratio)
  {
    const double quotient = (coarse - middle) / (middle - fine);
    return quotient > 0 ? std::log(quotient) / std::log(ratio) : std::numeric_limits<double>::quiet_NaN();
  }
} // namespace penny
