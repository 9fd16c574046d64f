#include "pierre/stats/sample_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pierre::stats {

SampleSummary summarize(std::span<const double> sample) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  SampleSummary s;
  double sum = 0;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -std::numeric_limits<double>::infinity();
  for (double x : sample) {
    if (std::isnan(x)) continue;
    ++s.count;
    sum += x;
    s.min = std::min(s.min, x);
    s.max = std::max(s.max, x);
  }
  if (s.count == 0) return SampleSummary{0, kNaN, kNaN, kNaN, kNaN};
  s.mean = sum / static_cast<double>(s.count);
  if (s.count < 2) {
    s.standard_deviation = kNaN;
    return s;
  }
  double ss = 0;  // second pass: deviations from the mean, no cancellation
  for (double x : sample) {
    if (std::isnan(x)) continue;
    ss += (x - s.mean) * (x - s.mean);
  }
  s.standard_deviation = std::sqrt(ss / static_cast<double>(s.count - 1));
  return s;
}

}  // namespace pierre::stats
