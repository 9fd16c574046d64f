// The bootstraps share their resamples out over threads: every resample is computed once, and
// the replicates are the same numbers for any thread count.
#include "pierre/stats/resample_blocks.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "pierre/stats/bootstrap.hpp"
#include "pierre/stats/bootstrap_weibull.hpp"
#include "support/seeded_samples.hpp"

namespace pierre::stats {
namespace {

TEST(ResampleBlocks, EveryResampleOnceForAnyCountAndThreads) {
  for (std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
    for (unsigned threads : {0u, 1u, 2u, 3u, 8u, 64u}) {
      std::vector<std::atomic<int>> seen(count);
      for_resample_blocks(count, threads, [&](std::size_t first, std::size_t last) {
        ASSERT_LE(first, last);
        for (std::size_t r = first; r < last; ++r) seen[r].fetch_add(1);
      });
      for (std::size_t r = 0; r < count; ++r)
        EXPECT_EQ(seen[r].load(), 1) << "resample " << r << " of " << count << ", threads " << threads;
    }
  }
}

TEST(ResampleBlocks, AnExceptionInABlockReachesTheCaller) {
  EXPECT_THROW(for_resample_blocks(100, 4,
                                   [](std::size_t first, std::size_t) {
                                     if (first > 0) throw std::runtime_error("block");
                                   }),
               std::runtime_error);
}

TEST(ResampleBlocks, BootstrapReplicatesAreTheSameForAnyThreadCount) {
  // 101 resamples: blocks of unequal size. A resample skipped or computed by the wrong
  // block would leave a 0 or another resample's value in its place.
  const auto x = test::seeded_weibull(1.37, 1.55, 500, 3);
  const Statistic mean = [](std::span<double> v) {
    double s = 0;
    for (double e : v) s += e;
    return s / static_cast<double>(v.size());
  };
  const auto one = bootstrap_replicates(x, mean, 11, 101, 1);
  ASSERT_TRUE(one) << one.error;
  for (unsigned threads : {2u, 3u, 8u}) EXPECT_EQ(*bootstrap_replicates(x, mean, 11, 101, threads), *one);

  for (auto [method, n] : {std::pair{WeibullBootstrapMethod::exact, std::size_t{2000}},
                           std::pair{WeibullBootstrapMethod::binned, std::size_t{30000}}}) {
    const auto y = test::seeded_weibull(1.37, 1.55, n, 5);
    WeibullBootstrapOptions o;
    o.method = method;
    o.resamples = 101;
    const auto ref = bootstrap_weibull_quantile_replicates(y, 95, 17, o);
    ASSERT_TRUE(ref) << ref.error;
    ASSERT_EQ(ref->weibull.size(), 101u);
    for (double q : ref->weibull) ASSERT_TRUE(std::isfinite(q) && q > 0);
    for (unsigned threads : {2u, 3u, 8u}) {
      o.threads = threads;
      const auto r = bootstrap_weibull_quantile_replicates(y, 95, 17, o);
      ASSERT_TRUE(r) << r.error;
      EXPECT_EQ(r->method, method);
      EXPECT_EQ(r->weibull, ref->weibull) << threads << " threads";  // bit for bit
      EXPECT_EQ(r->empirical, ref->empirical) << threads << " threads";
      EXPECT_EQ(r->values, n);
    }
  }
}

}  // namespace
}  // namespace pierre::stats
