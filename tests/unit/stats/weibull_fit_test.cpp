// Weibull maximum-likelihood fit and distribution functions.
#include "pierre/stats/weibull_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>
#include "support/seeded_samples.hpp"

namespace pierre::stats {
namespace {

TEST(WeibullFit, RecoversKnownParametersWithinFourStandardErrors) {
  // Asymptotic ML standard errors (inverse Fisher information of the Weibull):
  //   sd(k̂) = k √(6/π² / n) = 0.7797 k / √n,  sd(λ̂) = (λ/k) √(1.1087 / n).
  const double k = 1.37, lambda = 1.55;  // Table D.2, screen 1 heights
  const std::size_t n = 5000;
  const auto fit = fit_weibull(test::seeded_weibull(k, lambda, n, 20240501));
  ASSERT_TRUE(fit) << fit.error;
  const double sd_k = 0.7797 * k / std::sqrt(double(n));
  const double sd_l = lambda / k * std::sqrt(1.1087 / double(n));
  EXPECT_NEAR(fit->shape, k, 4 * sd_k);
  EXPECT_NEAR(fit->scale, lambda, 4 * sd_l);
  EXPECT_EQ(fit->used, n);
  EXPECT_EQ(fit->excluded, 0u);
}

TEST(WeibullFit, LargeScaleValuesDoNotOverflow) {
  // Energies in J are ~1e6: x^k would overflow for large k without the shift by max x.
  const auto fit = fit_weibull(test::seeded_weibull(8.0, 2.0e6, 2000, 7));
  ASSERT_TRUE(fit) << fit.error;
  EXPECT_NEAR(fit->shape, 8.0, 4 * 0.7797 * 8.0 / std::sqrt(2000.0));
  EXPECT_NEAR(fit->scale, 2.0e6, 4 * 2.0e6 / 8.0 * std::sqrt(1.1087 / 2000.0));
}

TEST(WeibullFit, SatisfiesTheLikelihoodEquations) {
  // At the ML estimate both score equations hold (checked here independently of the
  // profile equation the fit solves):
  //   ∂ℓ/∂λ = 0  ⇔  mean((x/λ)^k) = 1
  //   ∂ℓ/∂k = 0  ⇔  1/k + mean(ln(x/λ)) - mean((x/λ)^k ln(x/λ)) = 0
  const auto x = test::seeded_weibull(0.8, 3.0, 40, 99);
  const auto fit = fit_weibull(x);
  ASSERT_TRUE(fit) << fit.error;
  const double k = fit->shape, l = fit->scale;
  double a = 0, b = 0, c = 0;
  for (double v : x) {
    const double r = std::log(v / l), p = std::pow(v / l, k);
    a += p;
    b += r;
    c += p * r;
  }
  const double n = static_cast<double>(x.size());
  EXPECT_NEAR(a / n, 1.0, 1e-9);
  EXPECT_NEAR(1.0 / k + b / n - c / n, 0.0, 1e-9);
}

// Newton from a shape hint finds the same root as the fit from Menon's estimate, to the
// iteration's 1e-12 (relative), whether the hint is near (a bootstrap resample's case), far
// within the factor of 4 it searches, or outside it (the fit then falls back); and the score
// equations hold at it (as above, independently of the equation solved).
TEST(WeibullFit, AShapeHintGivesTheSameFit) {
  for (const double k_true : {0.8, 1.37, 3.5, 8.0}) {
    const auto x = test::seeded_weibull(k_true, 2.0, 800, 5);
    const auto plain = fit_weibull(x);
    ASSERT_TRUE(plain) << plain.error;
    for (const double hint : {1.02, 0.5, 3.0, 0.1, 40.0}) {
      SCOPED_TRACE(::testing::Message() << "k " << k_true << ", hint " << hint << " × k̂");
      const auto f = fit_weibull(x, hint * plain->shape);
      ASSERT_TRUE(f) << f.error;
      EXPECT_NEAR(f->shape, plain->shape, 1e-11 * plain->shape);
      EXPECT_NEAR(f->scale, plain->scale, 1e-11 * plain->scale);
      double a = 0;
      for (double v : x) a += std::pow(v / f->scale, f->shape);
      EXPECT_NEAR(a / static_cast<double>(x.size()), 1.0, 1e-9);  // ∂ℓ/∂λ = 0
    }
  }
}

TEST(WeibullFit, NonPositiveAndNonFiniteValuesAreLeftOutAndCounted) {
  auto x = test::seeded_weibull(2.0, 1.0, 100, 3);
  const auto clean = fit_weibull(x);
  x.insert(x.end(), {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity()});
  const auto dirty = fit_weibull(x);
  ASSERT_TRUE(clean && dirty);
  EXPECT_EQ(dirty->used, 100u);
  EXPECT_EQ(dirty->excluded, 4u);
  EXPECT_EQ(dirty->shape, clean->shape);
  EXPECT_EQ(dirty->scale, clean->scale);
}

TEST(WeibullFit, TooFewOrEqualValuesAreErrors) {
  const std::vector<double> one{1.0, 0.0, -2.0};
  const auto a = fit_weibull(one);
  EXPECT_FALSE(a);
  EXPECT_FALSE(a.error.empty());
  const std::vector<double> same{2.0, 2.0, 2.0};
  EXPECT_FALSE(fit_weibull(same));
}

TEST(WeibullDistribution, MatchesTheClosedForms) {
  const WeibullFit w{.shape = 1.5, .scale = 2.0};
  const double x = 3.0;
  const double z = std::pow(x / 2.0, 1.5);
  EXPECT_NEAR(survival(w, x), std::exp(-z), 1e-15);
  EXPECT_NEAR(cdf(w, x), 1 - std::exp(-z), 1e-15);
  EXPECT_NEAR(pdf(w, x), 1.5 / 2.0 * std::pow(x / 2.0, 0.5) * std::exp(-z), 1e-15);
  // x_p = λ (-ln(1 - p))^(1/k)
  EXPECT_NEAR(quantile(w, 0.95), 2.0 * std::pow(-std::log(0.05), 1 / 1.5), 1e-13);
  EXPECT_EQ(cdf(w, -1.0), 0.0);
  EXPECT_EQ(survival(w, 0.0), 1.0);
  EXPECT_TRUE(std::isnan(quantile(w, 1.5)));  // no exception: NaN
}

}  // namespace
}  // namespace pierre::stats
