#include "pierre/stats/empirical_cdf.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace pierre::stats {

std::vector<double> empirical_cdf(std::span<const double> sample, std::span<const double> breaks) {
  std::vector<double> v;
  v.reserve(sample.size());
  std::copy_if(sample.begin(), sample.end(), std::back_inserter(v),
               [](double x) { return !std::isnan(x); });
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  out.reserve(breaks.size());
  const double n = static_cast<double>(v.size());
  for (double b : breaks) {
    if (v.empty() || std::isnan(b)) {
      out.push_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    // upper_bound: the count of values <= b (right-continuous F).
    const auto count = std::upper_bound(v.begin(), v.end(), b) - v.begin();
    out.push_back(static_cast<double>(count) / n);
  }
  return out;
}

}  // namespace pierre::stats
