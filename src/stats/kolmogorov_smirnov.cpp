#include "pierre/stats/kolmogorov_smirnov.hpp"

#include <algorithm>
#include <boost/math/distributions/kolmogorov_smirnov.hpp>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

#include "pierre/stats/math_policy.hpp"

namespace pierre::stats {
namespace {

std::vector<double> sorted_without_nan(std::span<const double> sample) {
  std::vector<double> v;
  v.reserve(sample.size());
  std::copy_if(sample.begin(), sample.end(), std::back_inserter(v),
               [](double x) { return !std::isnan(x); });
  std::sort(v.begin(), v.end());
  return v;
}

KolmogorovSmirnovTest with_p_values(double d, double n_effective) {
  return KolmogorovSmirnovTest{d, kolmogorov_p_value(d, n_effective),
                               kolmogorov_p_value_stephens(d, n_effective), n_effective};
}

// P(K > x) of the Kolmogorov distribution: Boost's distribution with n = 1 is K itself.
double kolmogorov_survival(double x) {
  if (std::isnan(x)) return std::numeric_limits<double>::quiet_NaN();
  if (x <= 0) return 1.0;
  if (std::isinf(x)) return 0.0;
  const boost::math::kolmogorov_smirnov_distribution<double, MathPolicy> k(1.0);
  // + 0.0 turns a −0 from the far tail into 0: clamp keeps −0 (it is not less than 0), and a
  // p-value printed "-0" reads as a fault.
  return std::clamp(boost::math::cdf(boost::math::complement(k, x)), 0.0, 1.0) + 0.0;
}

}  // namespace

double kolmogorov_p_value(double d, double n_effective) {
  return kolmogorov_survival(std::sqrt(n_effective) * d);
}

double kolmogorov_p_value_stephens(double d, double n_effective) {
  const double r = std::sqrt(n_effective);
  return kolmogorov_survival((r + 0.12 + 0.11 / r) * d);
}

// Hand-written: the statistic is a single pass over the order statistics; Boost supplies
// only the distribution.
Outcome<KolmogorovSmirnovTest> kolmogorov_smirnov(std::span<const double> sample,
                                                  const std::function<double(double)>& cdf) {
  const std::vector<double> x = sorted_without_nan(sample);
  if (x.empty()) return Outcome<KolmogorovSmirnovTest>::failure("KS test of an empty sample");
  const double n = static_cast<double>(x.size());
  double d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = cdf(x[i]);
    if (std::isnan(f)) {
      return Outcome<KolmogorovSmirnovTest>::failure("KS test: the CDF returned NaN");
    }
    const double below = static_cast<double>(i) / n;   // F_n just below x_(i+1)
    const double at = static_cast<double>(i + 1) / n;  // F_n at x_(i+1)
    d = std::max({d, at - f, f - below});
  }
  return Outcome<KolmogorovSmirnovTest>::success(with_p_values(d, n));
}

Outcome<KolmogorovSmirnovTest> kolmogorov_smirnov_two_sample(std::span<const double> a,
                                                             std::span<const double> b) {
  const std::vector<double> x = sorted_without_nan(a);
  const std::vector<double> y = sorted_without_nan(b);
  if (x.empty() || y.empty()) {
    return Outcome<KolmogorovSmirnovTest>::failure("two-sample KS test with an empty sample");
  }
  const double nx = static_cast<double>(x.size()), ny = static_cast<double>(y.size());
  std::size_t i = 0, j = 0;
  double d = 0;
  // Walk the merged values; at each distinct value step past all its copies in both samples
  // before comparing (stepping one sample's tie first would overstate D).
  while (i < x.size() && j < y.size()) {
    const double v = std::min(x[i], y[j]);
    while (i < x.size() && x[i] == v) ++i;
    while (j < y.size() && y[j] == v) ++j;
    d = std::max(d, std::abs(static_cast<double>(i) / nx - static_cast<double>(j) / ny));
  }
  // Past the end of one sample the other's CDF only rises towards 1: the gap only shrinks.
  return Outcome<KolmogorovSmirnovTest>::success(with_p_values(d, nx * ny / (nx + ny)));
}

}  // namespace pierre::stats
