#include "pierre/stats/resample_index_stream.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pierre::stats {
namespace {

TEST(ResampleIndexStream, PinnedToPhiloxKnownAnswer) {
  // Random123's tests/kat_vectors: Philox4x32-10 with counter 0 and key 0 gives
  // 6627e8d5 e169c58d bc57ac4c 9b00dbd8. Seed 0, resample 0, draw pair 0 is that block, so
  // the first two indices in [0, 1000) are floor(1000 · w / 2^64) for
  // w = 0x6627e8d5e169c58d (0.39905... → 399) and w = 0xbc57ac4c9b00dbd8 (0.73571... → 735).
  // This pins the stream on every platform.
  ResampleIndexStream s(0, 0);
  EXPECT_EQ(s.next(1000), 399u);
  EXPECT_EQ(s.next(1000), 735u);
  const auto b = ResampleIndexStream(0, 0).block(0, 0);
  EXPECT_EQ(b[0], 0x6627e8d5u);
  EXPECT_EQ(b[3], 0x9b00dbd8u);
}

TEST(ResampleIndexStream, SameSeedAndResampleSameIndicesOtherwiseDifferent) {
  ResampleIndexStream a(42, 7), b(42, 7), c(42, 8), d(43, 7);
  int differ_c = 0, differ_d = 0;
  for (int i = 0; i < 100; ++i) {
    const auto x = a.next(1'000'000);
    EXPECT_EQ(x, b.next(1'000'000));
    differ_c += x != c.next(1'000'000);
    differ_d += x != d.next(1'000'000);
  }
  EXPECT_GT(differ_c, 95);  // equal by chance with probability 1e-6 each
  EXPECT_GT(differ_d, 95);
}

TEST(ResampleIndexStream, IndicesAreInRangeAndUniform) {
  // n = 7 does not divide 2^64 (the case the rejection step exists for). 70 000 draws:
  // each count ~ Binomial(70 000, 1/7), mean 10 000, sd 92.6; allow 4.5 sd. And a
  // chi-square with 6 degrees of freedom below 22.5 (p = 0.001).
  ResampleIndexStream s(2015, 3);
  std::vector<int> count(7, 0);
  for (int i = 0; i < 70000; ++i) {
    const auto k = s.next(7);
    ASSERT_LT(k, 7u);
    ++count[k];
  }
  double chi2 = 0;
  for (int c : count) {
    EXPECT_NEAR(c, 10000, 4.5 * 92.6);
    chi2 += (c - 10000.0) * (c - 10000.0) / 10000.0;
  }
  EXPECT_LT(chi2, 22.5);
}

TEST(ResampleIndexStream, RejectionRemovesTheBiasOfAHugeRange) {
  // n = 3 · 2^62: a plain multiply-shift maps 2 words to every index k ≡ 0 (mod 3) and one
  // word to the others, so P(k ≡ 0) would be 1/2. With Lemire's rejection (2^64 mod n = 2^62:
  // a quarter of the words are redrawn) it is exactly 1/3. 6000 draws: sd 0.0061; allow 4 sd.
  const std::uint64_t n = 3 * (std::uint64_t{1} << 62);
  ResampleIndexStream s(5, 0);
  int zero_mod_3 = 0;
  for (int i = 0; i < 6000; ++i) {
    const auto k = s.next(n);
    ASSERT_LT(k, n);
    zero_mod_3 += k % 3 == 0;
  }
  EXPECT_NEAR(zero_mod_3 / 6000.0, 1.0 / 3.0, 4 * 0.0061);
}

TEST(OpenUnitInterval, NeverZeroOrOne) {
  // The extremes by hand: (0 + 0.5) / 2^52 and (2^52 - 1 + 0.5) / 2^52.
  EXPECT_EQ(open_unit_interval(0), 0x1.0p-53);
  EXPECT_EQ(open_unit_interval(~std::uint64_t{0}), 1.0 - 0x1.0p-53);
  EXPECT_LT(open_unit_interval(~std::uint64_t{0}), 1.0);
  EXPECT_EQ(open_unit_interval(std::uint64_t{1} << 63), 0.5 + 0x1.0p-53);
}

}  // namespace
}  // namespace pierre::stats
