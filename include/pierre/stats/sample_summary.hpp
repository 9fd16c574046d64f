// Count, mean, standard deviation, minimum and maximum of a sample. NaN values are left
// out. The standard deviation is the sample one (divisor n - 1), computed in two passes
// (mean first, then squared deviations) so that values with a large common offset keep
// their spread; it is NaN for fewer than two values, and every field but `count` is NaN
// for an empty sample. Hand-written: two loops.
#pragma once

#include <cstddef>
#include <span>

namespace pierre::stats {

struct SampleSummary {
  std::size_t count = 0;
  double mean = 0;
  double standard_deviation = 0;
  double min = 0;
  double max = 0;
};

SampleSummary summarize(std::span<const double> sample);

}  // namespace pierre::stats
