// Type-7 percentiles checked against values worked by hand from the definition
// h = (n - 1) p / 100, P = x[floor h] + frac(h) (x[floor h + 1] - x[floor h]).
#include "pierre/stats/percentile.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace pierre::stats {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Percentile, OneToFiveByHand) {
  const std::vector<double> x{5, 3, 1, 4, 2};    // unsorted on purpose: 1..5
  EXPECT_EQ(percentile(x, 0), 1.0);              // h = 0: the minimum
  EXPECT_EQ(percentile(x, 100), 5.0);            // h = 4: the maximum
  EXPECT_EQ(percentile(x, 50), 3.0);             // h = 2
  EXPECT_EQ(percentile(x, 25), 2.0);             // h = 1
  EXPECT_NEAR(percentile(x, 10), 1.4, 1e-12);    // h = 0.4: 1 + 0.4 · 1
  EXPECT_NEAR(percentile(x, 95), 4.8, 1e-12);    // h = 3.8: 4 + 0.8 · 1
  EXPECT_NEAR(percentile(x, 62.5), 3.5, 1e-12);  // h = 2.5
}

TEST(Percentile, InputIsNotReordered) {
  const std::vector<double> x{5, 3, 1, 4, 2};
  const std::vector<double> before = x;
  (void)percentile(x, 50);
  EXPECT_EQ(x, before);
}

TEST(Percentile, UnevenGapsInterpolateLinearly) {
  // 0, 10, 100, 1000 (n = 4): p = 50 → h = 1.5 → 10 + 0.5 · 90 = 55;
  // p = 90 → h = 2.7 → 100 + 0.7 · 900 = 730.
  const std::vector<double> x{1000, 0, 100, 10};
  EXPECT_NEAR(percentile(x, 50), 55.0, 1e-12);
  EXPECT_NEAR(percentile(x, 90), 730.0, 1e-9);
}

TEST(Percentile, ManyAtOnceEqualOneAtATime) {
  const std::vector<double> x{7.5, -2, 3, 3, 11, 0.25, 9};
  const std::vector<double> ps{0, 5, 33.3, 50, 95, 99, 100};
  const std::vector<double> many = percentiles(x, ps);
  ASSERT_EQ(many.size(), ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) EXPECT_EQ(many[i], percentile(x, ps[i])) << ps[i];
}

// percentiles() places only the order statistics it needs (successive nth_element): on a large
// sample with ties, with the p's unsorted, repeated, next to each other and out of range, every
// value must be that of the sorted sample read by the definition.
TEST(Percentile, ManyAtOnceEqualTheSortedSample) {
  std::vector<double> x;
  std::uint64_t state = 12345;
  for (int i = 0; i < 10007; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    x.push_back(static_cast<double>((state >> 33) % 4001) / 8.0);  // ~2.5 values per level
  }
  const std::vector<double> ps{99, 50, 95, 0, 100, 95, 50.004, 50.005, 1e-9, 99.99999, -3, 12.5};
  std::vector<double> sorted = x;
  std::sort(sorted.begin(), sorted.end());
  const std::vector<double> many = percentiles(x, ps);
  ASSERT_EQ(many.size(), ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps[i] < 0) {
      EXPECT_TRUE(std::isnan(many[i]));
      continue;
    }
    EXPECT_EQ(many[i], percentile_of_sorted(sorted, ps[i])) << ps[i];
  }
}

TEST(Percentile, SortedVersionByHand) {
  const std::vector<double> s{1, 2, 3, 4, 5};
  EXPECT_NEAR(percentile_of_sorted(s, 95), 4.8, 1e-12);
  EXPECT_EQ(percentile_of_sorted(s, 75), 4.0);  // h = 3
}

TEST(Percentile, SingleValueIsEveryPercentile) {
  const std::vector<double> x{2.5};
  EXPECT_EQ(percentile(x, 0), 2.5);
  EXPECT_EQ(percentile(x, 95), 2.5);
  EXPECT_EQ(percentile(x, 100), 2.5);
}

TEST(Percentile, NaNIsLeftOut) {
  const std::vector<double> x{kNaN, 1, 2, kNaN, 3};  // as 1, 2, 3
  EXPECT_EQ(percentile(x, 50), 2.0);
  EXPECT_NEAR(percentile(x, 75), 2.5, 1e-12);
}

TEST(Percentile, InfinityIsBeyondEveryValue) {
  // A right-censored runout counts as +inf: the percentile that needs it is +inf, the
  // others stay finite (not NaN from inf - inf or 0 · inf).
  const std::vector<double> x{1, 2, kInf};
  EXPECT_EQ(percentile(x, 50), 2.0);   // h = 1 exactly
  EXPECT_EQ(percentile(x, 75), kInf);  // h = 1.5, between 2 and inf
  EXPECT_NEAR(percentile(x, 25), 1.5, 1e-12);
  const std::vector<double> y{1, kInf, kInf};
  EXPECT_EQ(percentile(y, 100), kInf);
  EXPECT_EQ(percentile(y, 75), kInf);  // between inf and inf: inf, not NaN
}

TEST(Percentile, EmptySampleOrBadPGivesNaN) {
  const std::vector<double> none;
  EXPECT_TRUE(std::isnan(percentile(none, 50)));
  const std::vector<double> x{1, 2, 3};
  EXPECT_TRUE(std::isnan(percentile(x, -1)));
  EXPECT_TRUE(std::isnan(percentile(x, 100.5)));
  EXPECT_TRUE(std::isnan(percentile(x, kNaN)));
}

}  // namespace
}  // namespace pierre::stats
