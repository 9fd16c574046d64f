// Thesis Eq 4.1, RMSE = sqrt((1/n) Σ (Ŷ_i - Y_i)²), worked by hand.
#include "pierre/stats/cdf_rmse.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pierre::stats {
namespace {

TEST(CdfRmse, ThreeBreaksByHand) {
  const std::vector<double> predicted{0.1, 0.5, 1.0};
  const std::vector<double> observed{0.2, 0.5, 0.9};
  const auto r = cdf_rmse(predicted, observed);
  ASSERT_TRUE(r) << r.error;
  EXPECT_NEAR(*r, std::sqrt((0.01 + 0.0 + 0.01) / 3.0), 1e-15);  // 0.0816...
}

TEST(CdfRmse, IdenticalCdfsGiveZero) {
  const std::vector<double> y{0, 0.3, 0.7, 1};
  EXPECT_EQ(*cdf_rmse(y, y), 0.0);
}

TEST(CdfRmse, FromSamplesOnBreakPoints) {
  // simulated {1, 2, 3, 4}: F at breaks {1.5, 3.5} = {0.25, 0.75};
  // observed {1, 1, 3, 5}:  F = {0.5, 0.75}. RMSE = sqrt(0.25² / 2) = 0.25 / √2.
  const std::vector<double> sim{1, 2, 3, 4}, obs{1, 1, 3, 5}, breaks{1.5, 3.5};
  const auto r = cdf_rmse(sim, obs, breaks);
  ASSERT_TRUE(r) << r.error;
  EXPECT_NEAR(*r, 0.25 / std::sqrt(2.0), 1e-15);
}

TEST(CdfRmse, MismatchedOrEmptyIsAnError) {
  const std::vector<double> a{0.1, 0.2}, b{0.1}, none;
  EXPECT_FALSE(cdf_rmse(a, b));
  EXPECT_FALSE(cdf_rmse(none, none));
}

}  // namespace
}  // namespace pierre::stats
