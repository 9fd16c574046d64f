#include "pierre/stats/lognormal_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace pierre::stats {
namespace {

TEST(LognormalFit, IsTheMeanAndMlStandardDeviationOfTheLogs) {
  // logs {0, 1, 2}: μ = 1, σ² = (1 + 0 + 1) / 3 (ML divisor n).
  const std::vector<double> x{1.0, std::numbers::e, std::numbers::e * std::numbers::e};
  const auto fit = fit_lognormal(x);
  ASSERT_TRUE(fit) << fit.error;
  EXPECT_NEAR(fit->mu, 1.0, 1e-15);
  EXPECT_NEAR(fit->sigma, std::sqrt(2.0 / 3.0), 1e-15);
}

TEST(LognormalFit, LeavesOutNonPositiveValues) {
  const std::vector<double> x{0.0, 1.0, -3.0, std::exp(2.0)};  // logs {0, 2}
  const auto fit = fit_lognormal(x);
  ASSERT_TRUE(fit) << fit.error;
  EXPECT_EQ(fit->used, 2u);
  EXPECT_EQ(fit->excluded, 2u);
  EXPECT_NEAR(fit->mu, 1.0, 1e-15);
  EXPECT_NEAR(fit->sigma, 1.0, 1e-15);
}

TEST(LognormalFit, DegenerateSamplesAreErrors) {
  const std::vector<double> one{3.0};
  EXPECT_FALSE(fit_lognormal(one));
  const std::vector<double> same{3.0, 3.0};
  EXPECT_FALSE(fit_lognormal(same));
}

TEST(LognormalDistribution, MatchesStandardNormalValues) {
  const LognormalFit f{.mu = 0.5, .sigma = 0.8};
  EXPECT_NEAR(cdf(f, std::exp(0.5)), 0.5, 1e-15);  // the median is e^μ
  // Φ(1) = 0.841344746068543 (tabulated): x = e^(μ + σ) sits there.
  EXPECT_NEAR(cdf(f, std::exp(0.5 + 0.8)), 0.841344746068543, 1e-14);
  EXPECT_NEAR(survival(f, std::exp(0.5 + 0.8)), 1 - 0.841344746068543, 1e-14);
  EXPECT_NEAR(quantile(f, 0.841344746068543), std::exp(1.3), 1e-12);
  // pdf = φ(z) / (x σ), z = 1: φ(1) = e^{-1/2} / √(2π)
  const double x = std::exp(1.3);
  EXPECT_NEAR(pdf(f, x), std::exp(-0.5) / std::sqrt(2 * std::numbers::pi) / (x * 0.8), 1e-15);
  EXPECT_EQ(cdf(f, 0.0), 0.0);
  EXPECT_EQ(survival(f, -1.0), 1.0);
}

}  // namespace
}  // namespace pierre::stats
