// Log-normal with right-censored values and a point mass of zeros (design-checks.md §2).
#include "pierre/stats/censored_lognormal_fit.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "pierre/stats/lognormal_fit.hpp"
#include "support/seeded_samples.hpp"

namespace pierre::stats {
namespace {

// Standard normal by inversion: Φ^{-1}(u) = -√2 erfc^{-1}(2u).

struct RunoutSample {
  std::vector<double> values;  // zeros and observed positives
  std::vector<double> censored_at;
};

// Runouts: a share `p0` stop above the toe (0), the rest log-normal(μ, σ); those beyond
// `profile_end` leave the profile and are censored there.
RunoutSample runout_sample(double p0, double mu, double sigma, double profile_end, std::size_t n,
                           std::uint64_t seed) {
  std::mt19937_64 g(seed);
  RunoutSample s;
  for (std::size_t i = 0; i < n; ++i) {
    if (test::seeded_uniform(g) < p0) {
      s.values.push_back(0.0);
      continue;
    }
    const double x = std::exp(mu + sigma * test::seeded_normal(g));
    if (x > profile_end) {
      s.censored_at.push_back(profile_end);
    } else {
      s.values.push_back(x);
    }
  }
  return s;
}

TEST(CensoredLognormalFit, RecoversParametersFromACensoredSample) {
  // μ = 1, σ = 0.5, profile end 4: P(X > 4) = Q((ln 4 - 1)/0.5) = Q(0.77) = 22 % censored.
  // Inverse of the expected Fisher information of the type-I censored normal at ξ = 0.77
  // (per value: ∫^ξ s sᵀ φ + Q(ξ) s_c s_cᵀ, scores s = (z, z² - 1)/σ and
  // s_c = (h, ξ h)/σ, h = φ(ξ)/Q(ξ)) for n_pos = 16 000 positive values:
  // sd(μ̂) = 0.0041, sd(σ̂) = 0.0033 (1.04 and 1.19 times the uncensored ones). 4 sd each.
  const double mu = 1.0, sigma = 0.5, p0 = 0.2;
  const auto s = runout_sample(p0, mu, sigma, 4.0, 20000, 12345);
  ASSERT_GT(s.censored_at.size(), 2500u);  // the censoring really is there
  const auto fit = fit_censored_lognormal(s.values, s.censored_at);
  ASSERT_TRUE(fit) << fit.error;
  EXPECT_NEAR(fit->positive.mu, mu, 4 * 0.0041);
  EXPECT_NEAR(fit->positive.sigma, sigma, 4 * 0.0033);
  // p0: binomial sd √(0.2 · 0.8 / 20000) = 0.0028; 4 sd = 0.011.
  EXPECT_NEAR(fit->zero_share, p0, 0.011);
  EXPECT_EQ(fit->zeros + fit->observed + fit->censored, 20000u);

  // The test can fail: ignoring the censoring (fitting the observed values alone) is off
  // by more than the tolerance.
  std::vector<double> positives;
  for (double v : s.values) {
    if (v > 0) positives.push_back(v);
  }
  const auto naive = fit_lognormal(positives);
  ASSERT_TRUE(naive);
  EXPECT_GT(std::abs(naive->sigma - sigma), 4 * 0.0033);
  EXPECT_GT(std::abs(naive->mu - mu), 4 * 0.0041);
}

TEST(CensoredLognormalFit, IsALocalMaximumOfTheCensoredLikelihood) {
  // Checked on the log-likelihood written out here with erfc (independent of the GSL
  // functions and the gradient the fit uses): moving either parameter lowers it.
  const auto s = runout_sample(0.0, 0.3, 0.9, 2.5, 300, 777);
  ASSERT_FALSE(s.censored_at.empty());
  const auto fit = fit_censored_lognormal(s.values, s.censored_at);
  ASSERT_TRUE(fit) << fit.error;
  auto loglik = [&](double mu, double sigma) {
    double l = 0;
    for (double x : s.values) {
      const double z = (std::log(x) - mu) / sigma;
      l += -std::log(sigma) - 0.5 * z * z;
    }
    for (double c : s.censored_at) {
      const double w = (std::log(c) - mu) / sigma;
      l += std::log(0.5 * std::erfc(w / std::sqrt(2.0)));
    }
    return l;
  };
  const double mu = fit->positive.mu, sigma = fit->positive.sigma;
  const double best = loglik(mu, sigma);
  for (double step : {1e-3, -1e-3}) {
    EXPECT_LT(loglik(mu + step, sigma), best);
    EXPECT_LT(loglik(mu, sigma + step), best);
  }
  // And the library's own log-likelihood agrees with it up to its dropped constant
  // (-Σ ln x - m ln √(2π) is not included in either).
  EXPECT_NEAR(censored_lognormal_log_likelihood(s.values, s.censored_at, mu, sigma), best,
              1e-9 * std::abs(best));
}

TEST(CensoredLognormalFit, WithoutCensoringIsTheClosedForm) {
  const std::vector<double> x{0.0, 1.0, std::exp(1.0), std::exp(2.0), 0.0};
  const auto fit = fit_censored_lognormal(x, {});
  ASSERT_TRUE(fit) << fit.error;
  EXPECT_NEAR(fit->positive.mu, 1.0, 1e-15);
  EXPECT_NEAR(fit->positive.sigma, std::sqrt(2.0 / 3.0), 1e-15);
  EXPECT_EQ(fit->zero_share, 0.4);  // 2 zeros of 5
}

TEST(CensoredLognormalFit, MixtureExceedanceAndItsInverseByHand) {
  // p0 = 0.2, standard log-normal (median 1): P(X > 1) = 0.8 · 0.5 = 0.4.
  CensoredLognormalFit f;
  f.positive = LognormalFit{.mu = 0.0, .sigma = 1.0};
  f.zero_share = 0.2;
  EXPECT_NEAR(exceedance_probability(f, 1.0), 0.4, 1e-15);
  EXPECT_EQ(exceedance_probability(f, -1.0), 1.0);
  EXPECT_NEAR(exceedance_probability(f, 0.0), 0.8, 1e-15);
  EXPECT_NEAR(value_at_exceedance(f, 0.4), 1.0, 1e-12);
  // P(X > e) = 0.8 · Q(1) = 0.8 · 0.158655253931457
  EXPECT_NEAR(exceedance_probability(f, std::exp(1.0)), 0.8 * 0.158655253931457, 1e-14);
  EXPECT_NEAR(value_at_exceedance(f, 0.8 * 0.158655253931457), std::exp(1.0), 1e-11);
  // Probabilities the zeros already cover give distance 0.
  EXPECT_EQ(value_at_exceedance(f, 0.8), 0.0);
  EXPECT_EQ(value_at_exceedance(f, 0.95), 0.0);
  EXPECT_TRUE(std::isnan(value_at_exceedance(f, 1.2)));
}

TEST(CensoredLognormalFit, NoObservedPositiveValueIsAnError) {
  const std::vector<double> zeros{0.0, 0.0};
  const std::vector<double> censored{5.0, 5.0};
  const auto fit = fit_censored_lognormal(zeros, censored);
  EXPECT_FALSE(fit);
  EXPECT_FALSE(fit.error.empty());
}

}  // namespace
}  // namespace pierre::stats
