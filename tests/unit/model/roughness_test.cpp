// model-2d.md §7 test 8: the truncated-normal roughness sampler and the size factor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "pierre/model/roughness.hpp"

using namespace pierre::model;

namespace {
// Uniforms for the sampler: a plain 64-bit LCG mapped to (0, 1), independent of the code
// under test (the sampler itself is what is tested).
struct Lcg {
  unsigned long long s = 12345;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return (static_cast<double>(s >> 11) + 0.5) * 0x1.0p-53;
  }
};
}  // namespace

TEST(Roughness, NormalQuantileInvertsTheCdf) {
  for (double p : {1e-300, 1e-10, 0.01, 0.1587, 0.5, 0.77, 0.975, 1 - 1e-12}) {
    EXPECT_NEAR(normal_cdf(normal_quantile(p)), p, 1e-14 * std::max(p, 1e-3)) << p;
  }
  EXPECT_NEAR(normal_quantile(0.975), 1.959963984540054, 1e-14);
}

TEST(Roughness, TruncatedNormalMomentsMatchClosedForm) {
  RoughnessModel r;  // μ = σ = 0.5, truncated to X > 0
  const double kept = r.kept_mass();
  const double lo = 1.0 - kept;
  Lcg u;
  const int n = 1'000'000;
  std::vector<double> x(n);
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    x[i] = r.sample(u.next(), kept);
    ASSERT_GT(x[i], 0.0);
    sum += x[i];
  }
  const double mean = sum / n;
  for (double v : x) sum2 += (v - mean) * (v - mean);
  const double var = sum2 / (n - 1);
  // mean 0.5 + 0.5 φ(1)/Φ(1) = 0.64380; variance 0.25 (1 − 0.28760 − 0.28760²) = 0.15742.
  const double phi1 = std::exp(-0.5) / std::sqrt(2 * M_PI), Phi1 = normal_cdf(1.0);
  const double lam = phi1 / Phi1;
  EXPECT_NEAR(0.5 + 0.5 * lam, 0.64380, 5e-6);
  EXPECT_NEAR(mean, 0.5 + 0.5 * lam, 0.005 * 0.64380);
  EXPECT_NEAR(var, 0.25 * (1 - lam - lam * lam), 0.005 * 0.15742);

  // KS against the truncated-normal CDF: D below the 0.1 % critical value 1.95/√n.
  std::sort(x.begin(), x.end());
  double d = 0;
  for (int i = 0; i < n; ++i) {
    const double F = (normal_cdf((x[i] - 0.5) / 0.5) - lo) / (1 - lo);
    d = std::max({d, std::abs(F - double(i) / n), std::abs(F - double(i + 1) / n)});
  }
  EXPECT_LT(d, 1.95 / std::sqrt(double(n)));
}

// A mean far below 0 (μ/σ = −10): the truncated normal keeps Φ(−10) ≈ 7.6e-24 of the normal, so
// 1 − Φ(10) rounds to 1 and a sampler that inverts from the lower end draws +∞ every time. Its
// mean is μ + σ φ(α)/Φ(−α) with α = −μ/σ (the inverse Mills ratio), 0.049047 here, and its CDF
// F(x) = 1 − Φ(−(x − μ)/σ) / Φ(μ/σ), both evaluated from the upper tail where they keep digits.
TEST(Roughness, TruncatedNormalFarBelowZeroIsStillDrawn) {
  RoughnessModel r;
  r.mean = -5.0;
  r.sd = 0.5;
  const double kept = r.kept_mass();
  EXPECT_NEAR(kept / 7.6198530241605e-24, 1.0, 1e-9);  // Φ(−10), tables of the normal
  Lcg u;
  const int n = 200'000;
  std::vector<double> x(n);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    x[i] = r.sample(u.next(), kept);
    ASSERT_TRUE(std::isfinite(x[i]));
    ASSERT_GE(x[i], 0.0);
    sum += x[i];
  }
  const double alpha = 10.0;
  const double mills = std::exp(-0.5 * alpha * alpha) / std::sqrt(2 * M_PI) / normal_cdf(-alpha);
  const double mean = r.mean + r.sd * mills;
  EXPECT_NEAR(mean, 0.049047, 1e-6);
  // The variance of this near-exponential law is about mean², so the standard error of the
  // sample mean is about mean/√n = 0.22 % of it: 1 % is over four standard errors.
  EXPECT_NEAR(sum / n, mean, 0.01 * mean);
  std::sort(x.begin(), x.end());
  double d = 0;
  for (int i = 0; i < n; ++i) {
    const double F = 1.0 - normal_cdf(-(x[i] - r.mean) / r.sd) / kept;
    d = std::max({d, std::abs(F - double(i) / n), std::abs(F - double(i + 1) / n)});
  }
  EXPECT_LT(d, 1.95 / std::sqrt(double(n)));  // KS at 0.1 %
}

TEST(Roughness, UniformIsTheDrawItself) {
  RoughnessModel r;
  r.distribution = RoughnessDistribution::uniform;
  EXPECT_EQ(r.sample(0.25, r.kept_mass()), 0.25);
}

TEST(Roughness, SizeFactorFollowsEq66AndFloorsAt03) {
  RoughnessModel r;
  EXPECT_NEAR(r.size_factor(1.2), 1.0, 1e-15);  // Eq 4.4: 1 at the Vaujany mean diameter
  EXPECT_NEAR(r.size_factor(0.5), 1.36 - 0.15, 1e-15);
  EXPECT_EQ(r.size_factor(4.0), 0.3);  // 1.36 − 1.2 = 0.16 → floor
  r.size_reduction = false;
  EXPECT_EQ(r.size_factor(4.0), 1.0);
}
