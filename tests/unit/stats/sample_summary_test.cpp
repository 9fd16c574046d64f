#include "pierre/stats/sample_summary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace pierre::stats {
namespace {

TEST(SampleSummary, OneToFourByHand) {
  const std::vector<double> x{3, 1, 4, 2};
  const SampleSummary s = summarize(x);
  EXPECT_EQ(s.count, 4u);
  EXPECT_EQ(s.mean, 2.5);
  // Σ(x - 2.5)² = 2.25 + 0.25 + 0.25 + 2.25 = 5; divisor n - 1 = 3.
  EXPECT_NEAR(s.standard_deviation, std::sqrt(5.0 / 3.0), 1e-15);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
}

TEST(SampleSummary, LargeOffsetKeepsItsSpread) {
  // 1e9 + {1, 2, 3}: sd exactly 1. A one-pass Σx² - n·mean² loses it to cancellation.
  const std::vector<double> x{1e9 + 1, 1e9 + 2, 1e9 + 3};
  EXPECT_NEAR(summarize(x).standard_deviation, 1.0, 1e-9);
}

TEST(SampleSummary, NaNLeftOutSmallSamples) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> x{kNaN, 2.0};
  const SampleSummary s = summarize(x);
  EXPECT_EQ(s.count, 1u);
  EXPECT_EQ(s.mean, 2.0);
  EXPECT_TRUE(std::isnan(s.standard_deviation));  // undefined with one value
  const std::vector<double> none;
  const SampleSummary e = summarize(none);
  EXPECT_EQ(e.count, 0u);
  EXPECT_TRUE(std::isnan(e.mean));
  EXPECT_TRUE(std::isnan(e.max));
}

}  // namespace
}  // namespace pierre::stats
