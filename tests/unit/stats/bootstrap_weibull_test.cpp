// Bootstrap of the Weibull-ML quantile: the exact path is the plain bootstrap; the binned
// (Poisson, quantile bins) path agrees with it within the Monte Carlo error, matches the
// delta-method standard error, draws the empirical percentile with the right distribution,
// and is deterministic per seed.
#include "pierre/stats/bootstrap_weibull.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "pierre/stats/bootstrap.hpp"
#include "pierre/stats/kolmogorov_smirnov.hpp"
#include "pierre/stats/percentile.hpp"
#include "pierre/stats/weibull_fit.hpp"
#include "support/seeded_samples.hpp"

namespace pierre::stats {
namespace {

struct Interval {
  double lower, upper;
  double half_width() const { return (upper - lower) / 2; }
};

Interval ninety(const std::vector<double>& replicates) {
  const double ps[] = {5.0, 95.0};
  const auto q = percentiles(replicates, ps);
  return {q[0], q[1]};
}

std::vector<double> larger(const WeibullQuantileReplicates& r) {
  std::vector<double> out(r.weibull.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::max(r.weibull[i], r.empirical[i]);
  return out;
}

WeibullBootstrapOptions method(WeibullBootstrapMethod m) {
  WeibullBootstrapOptions o;
  o.method = m;
  return o;
}

TEST(BootstrapWeibull, ExactPathIsThePlainBootstrapOfTheFittedQuantile) {
  // Up to exact_up_to values the automatic choice is the plain bootstrap: what
  // bootstrap_replicates gives with the statistic "Weibull quantile (and max with the
  // empirical percentile) of the resample", the same resamples, each fit's Newton started from
  // the sample's shape instead of Menon's estimate: the same roots to the iteration's 1e-12.
  const auto x = test::seeded_weibull(1.37, 1.55, 3000, 11);
  WeibullBootstrapOptions o;
  o.resamples = 200;
  const auto r = bootstrap_weibull_quantile_replicates(x, 95, 17, o);
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r->method, WeibullBootstrapMethod::exact);
  EXPECT_EQ(r->values, x.size());
  const auto plain = bootstrap_replicates(
      x,
      [](std::span<double> v) {
        const auto w = fit_weibull(v);
        return w ? std::max(quantile(*w, 0.95), percentile(v, 95)) : 0.0;
      },
      17, 200);
  ASSERT_TRUE(plain);
  const auto ours = larger(*r);
  ASSERT_EQ(ours.size(), plain.value->size());
  for (std::size_t i = 0; i < ours.size(); ++i)
    EXPECT_NEAR(ours[i], (*plain.value)[i], 1e-10 * std::abs((*plain.value)[i])) << i;
}

TEST(BootstrapWeibull, BinnedIntervalAgreesWithTheExactOneOnFiftyThousandValues) {
  // 50 000 values of Table D.2's screen-1 heights (k = 1.37, λ = 1.55 m), P95, 1000
  // resamples each. The two paths use different random numbers, so their endpoints differ
  // by Monte Carlo error: an endpoint of a 90 % interval from 1000 replicates has sd ≈
  // 0.067 σ ≈ 4 % of the half-width, the difference of two ≈ 6 %. The binning error is
  // below 1e-4 of the half-width (bootstrap_weibull.hpp). Tolerance: 15 % of the half-width
  // (2.5 sd of the Monte Carlo difference).
  const auto x = test::seeded_weibull(1.37, 1.55, 50000, 2015);
  const auto exact = bootstrap_weibull_quantile_replicates(x, 95, 1, method(WeibullBootstrapMethod::exact));
  const auto binned = bootstrap_weibull_quantile_replicates(x, 95, 2, method(WeibullBootstrapMethod::binned));
  ASSERT_TRUE(exact && binned) << exact.error << binned.error;
  EXPECT_EQ(binned->method, WeibullBootstrapMethod::binned);
  EXPECT_GT(binned->bins, 3000u);
  EXPECT_LT(binned->bins, 6000u);
  for (bool with_empirical : {false, true}) {
    const Interval e = ninety(with_empirical ? larger(*exact) : exact->weibull);
    const Interval b = ninety(with_empirical ? larger(*binned) : binned->weibull);
    const double tol = 0.15 * e.half_width();
    EXPECT_NEAR(b.lower, e.lower, tol) << (with_empirical ? "larger" : "weibull");
    EXPECT_NEAR(b.upper, e.upper, tol) << (with_empirical ? "larger" : "weibull");
    EXPECT_NEAR(b.half_width(), e.half_width(), tol);
  }
  // The empirical percentile alone (exact under the Poisson bootstrap, no binning).
  const Interval ee = ninety(exact->empirical), be = ninety(binned->empirical);
  EXPECT_NEAR(be.lower, ee.lower, 0.15 * ee.half_width());
  EXPECT_NEAR(be.upper, ee.upper, 0.15 * ee.half_width());
}

TEST(BootstrapWeibull, BinnedHalfWidthMatchesTheDeltaMethodOnTwoHundredThousandValues) {
  // Cross-check only (the delta method is not a bootstrap): ln X is a smallest-extreme-value
  // variable with location u = ln λ and scale b = 1/k, ln x_p = u + w b, w = ln(-ln(1-p)).
  // Its Fisher information per value is (1/b²) [[1, 1-γ], [1-γ, (1-γ)² + π²/6]], whose
  // inverse is b² [[1.1087, -0.2570], [-0.2570, 0.6079]] (the covariance is negative), so
  //   sd(ln x̂_p) = (1/k) √((1.1087 - 2 · 0.2570 w + 0.6079 w²) / n),
  // and the 90 % half-width ≈ 1.645 x_p sd. The bootstrap's half-width from 1000 replicates
  // has a Monte Carlo error of about 3 %; allow 10 %.
  const double k = 3.2, lambda = 22.0, p = 0.95;  // bench_report's speeds
  const std::size_t n = 200000;
  const auto x = test::seeded_weibull(k, lambda, n, 7);
  const auto r = bootstrap_weibull_quantile_replicates(x, 95, 3);
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r->method, WeibullBootstrapMethod::binned);  // automatic: n > 20 000
  const auto fit = fit_weibull(x);
  const double xp = quantile(*fit, p);
  const double w = std::log(-std::log(1 - p));
  const double sd = xp / k * std::sqrt((1.1087 - 2 * 0.2570 * w + 0.6079 * w * w) / double(n));
  const Interval b = ninety(r->weibull);
  EXPECT_NEAR(b.half_width(), 1.645 * sd, 0.10 * 1.645 * sd);
  EXPECT_LT(b.lower, xp);
  EXPECT_GT(b.upper, xp);
  EXPECT_NEAR((b.lower + b.upper) / 2, xp, 0.15 * b.half_width());
}

TEST(BootstrapWeibull, BinnedEmpiricalPercentileHasThePercentileBootstrapsDistribution) {
  // Under the Poisson bootstrap the empirical replicate is exact (the bin counts are spread
  // over the bin's values by uniform indices). With few, wide bins (64) and values the fit
  // leaves out (zeros, +infinity), its replicates must have the distribution of the
  // order-statistic bootstrap of the percentile: two-sample KS, p > 0.001.
  auto x = test::seeded_weibull(1.0, 2.0, 30000, 5);
  for (std::size_t i = 0; i < x.size(); i += 20) x[i] = 0.0;  // 5 % zeros
  for (std::size_t i = 7; i < x.size(); i += 1000) x[i] = std::numeric_limits<double>::infinity();
  x[3] = std::numeric_limits<double>::quiet_NaN();              // left out
  for (double p : {90.0, 97.5}) {
    WeibullBootstrapOptions o = method(WeibullBootstrapMethod::binned);
    o.rank_bins = 64;
    o.resamples = 3000;
    const auto binned = bootstrap_weibull_quantile_replicates(x, p, 21, o);
    const auto reference = bootstrap_percentile_replicates(x, p, 22, 10000);
    ASSERT_TRUE(binned && reference) << binned.error;
    EXPECT_EQ(binned->values, x.size() - 1);
    const auto ks = kolmogorov_smirnov_two_sample(binned->empirical, *reference.value);
    ASSERT_TRUE(ks);
    EXPECT_GT(ks->p_value, 1e-3) << "p = " << p << ", D = " << ks->statistic;
    for (double v : binned->weibull) ASSERT_TRUE(std::isfinite(v));
  }
}

TEST(BootstrapWeibull, BinnedIsDeterministicPerSeed) {
  const auto x = test::seeded_weibull(1.37, 1.55, 30000, 9);
  WeibullBootstrapOptions o;
  o.resamples = 300;
  const auto a = bootstrap_weibull_quantile_replicates(x, 95, 42, o);
  const auto b = bootstrap_weibull_quantile_replicates(x, 95, 42, o);
  const auto c = bootstrap_weibull_quantile_replicates(x, 95, 43, o);
  ASSERT_TRUE(a && b && c) << a.error;
  EXPECT_EQ(a->method, WeibullBootstrapMethod::binned);
  EXPECT_EQ(a->weibull, b->weibull);  // bit for bit
  EXPECT_EQ(a->empirical, b->empirical);
  EXPECT_NE(a->weibull, c->weibull);
  const Interval ia = ninety(a->weibull), ib = ninety(b->weibull);
  EXPECT_EQ(ia.lower, ib.lower);
  EXPECT_EQ(ia.upper, ib.upper);
  // The sample's order does not matter (the binned path sorts first).
  auto y = x;
  std::reverse(y.begin(), y.end());
  EXPECT_EQ(bootstrap_weibull_quantile_replicates(y, 95, 42, o)->weibull, a->weibull);
}

TEST(BootstrapWeibull, BadArgumentsAndDegenerateSamplesAreErrors) {
  const std::vector<double> none, x{1, 2, 3};
  EXPECT_FALSE(bootstrap_weibull_quantile_replicates(none, 95, 1));
  EXPECT_FALSE(bootstrap_weibull_quantile_replicates(x, 101, 1));
  WeibullBootstrapOptions one;
  one.resamples = 1;
  EXPECT_FALSE(bootstrap_weibull_quantile_replicates(x, 95, 1, one));
  const std::vector<double> same(30000, 2.5);  // no spread: the sample's own fit fails
  const auto r = bootstrap_weibull_quantile_replicates(same, 95, 1);
  EXPECT_FALSE(r);
  EXPECT_FALSE(r.error.empty());
}

}  // namespace
}  // namespace pierre::stats
