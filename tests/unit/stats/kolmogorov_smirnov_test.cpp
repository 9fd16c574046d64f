#include "pierre/stats/kolmogorov_smirnov.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>
#include "support/seeded_samples.hpp"

namespace pierre::stats {
namespace {

TEST(KolmogorovSmirnov, ThreePointStatisticByHand) {
  // Against U(0, 1) (F(x) = x), sorted sample 0.1, 0.5, 0.8:
  //   i/n - F:      1/3 - 0.1 = 0.2333, 2/3 - 0.5 = 0.1667, 1 - 0.8 = 0.2
  //   F - (i-1)/n:  0.1,                0.5 - 1/3 = 0.1667, 0.8 - 2/3 = 0.1333
  // D = 7/30.
  const std::vector<double> x{0.8, 0.1, 0.5};
  const auto t = kolmogorov_smirnov(x, [](double v) { return v; });
  ASSERT_TRUE(t) << t.error;
  EXPECT_NEAR(t->statistic, 7.0 / 30.0, 1e-15);
  EXPECT_EQ(t->n_effective, 3.0);
}

TEST(KolmogorovSmirnov, PValueAtClassicalCriticalValues) {
  // The Kolmogorov distribution's tabulated upper points: P(K > 1.3581) = 0.05 and
  // P(K > 1.6276) = 0.01. With n = 100 the asymptotic p-value of D = c/10 is that.
  EXPECT_NEAR(kolmogorov_p_value(1.3581 / 10, 100), 0.05, 2e-4);
  EXPECT_NEAR(kolmogorov_p_value(1.6276 / 10, 100), 0.01, 1e-4);
  // Stephens: the same tail at (√n + 0.12 + 0.11/√n) D = 10.131 D, i.e. D = 1.3581 / 10.131.
  EXPECT_NEAR(kolmogorov_p_value_stephens(1.3581 / 10.131, 100), 0.05, 2e-4);
  EXPECT_EQ(kolmogorov_p_value(0.0, 10), 1.0);
}

// Far in the tail (a million crossings and a poor fit) the p-value underflows to zero: +0, not
// −0, which the report and the console would print as "-0".
TEST(KolmogorovSmirnov, FarTailPValueIsPlusZero) {
  for (const double d : {0.05, 0.2, 0.5}) {
    const double p = kolmogorov_p_value(d, 1e6);
    EXPECT_EQ(p, 0.0) << d;
    EXPECT_FALSE(std::signbit(p)) << d;
    EXPECT_FALSE(std::signbit(kolmogorov_p_value_stephens(d, 1e6))) << d;
  }
}

TEST(KolmogorovSmirnov, TrueDistributionIsNotRejectedShiftedOneIs) {
  const double k = 1.37, lambda = 1.55;
  const auto cdf = [&](double x) { return x <= 0 ? 0.0 : 1 - std::exp(-std::pow(x / lambda, k)); };
  auto x = test::seeded_weibull(k, lambda, 2000, 4242);
  const auto good = kolmogorov_smirnov(x, cdf);
  ASSERT_TRUE(good);
  // Under the true F the p-value is uniform: below 0.01 for 1 % of seeds only.
  EXPECT_GT(good->p_value, 0.01);
  EXPECT_GT(good->p_value_stephens, 0.01);
  // Shifted by 0.2 m (~15 % of the median): D ≈ 0.1 at n = 2000, far in the tail.
  for (double& v : x) v += 0.2;
  const auto bad = kolmogorov_smirnov(x, cdf);
  ASSERT_TRUE(bad);
  EXPECT_LT(bad->p_value, 1e-6);
  EXPECT_GT(bad->statistic, good->statistic);
}

TEST(KolmogorovSmirnov, TwoSampleStatisticByHand) {
  // a = {1, 2, 3}, b = {2.5, 4}: at 2, F_a = 2/3 and F_b = 0 → D = 2/3.
  const std::vector<double> a{3, 1, 2}, b{4, 2.5};
  const auto t = kolmogorov_smirnov_two_sample(a, b);
  ASSERT_TRUE(t) << t.error;
  EXPECT_NEAR(t->statistic, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(t->n_effective, 3.0 * 2.0 / 5.0, 1e-15);
}

TEST(KolmogorovSmirnov, TwoSampleTiesStepTogether) {
  // a = {1, 2}, b = {2, 3}: F_a - F_b is 1/2 at 1 and 1 - 1/2 = 1/2 at 2, so D = 1/2
  // (stepping a's 2 before b's would report 1).
  const std::vector<double> a{1, 2}, b{2, 3};
  EXPECT_NEAR(kolmogorov_smirnov_two_sample(a, b)->statistic, 0.5, 1e-15);
  EXPECT_EQ(kolmogorov_smirnov_two_sample(a, a)->statistic, 0.0);
}

TEST(KolmogorovSmirnov, TwoSamplePValues) {
  const auto a = test::seeded_weibull(1.37, 1.55, 1500, 1);
  const auto b = test::seeded_weibull(1.37, 1.55, 1000, 2);
  auto c = test::seeded_weibull(1.37, 1.55, 1000, 3);
  for (double& v : c) v *= 1.2;
  EXPECT_GT(kolmogorov_smirnov_two_sample(a, b)->p_value, 0.01);  // same distribution
  EXPECT_LT(kolmogorov_smirnov_two_sample(a, c)->p_value, 1e-6);  // scale 20 % larger
}

TEST(KolmogorovSmirnov, EmptySampleIsAnError) {
  const std::vector<double> none, one{1.0};
  EXPECT_FALSE(kolmogorov_smirnov(none, [](double v) { return v; }));
  EXPECT_FALSE(kolmogorov_smirnov_two_sample(none, one));
}

}  // namespace
}  // namespace pierre::stats
