// The hand-written Philox2x64-10 of RandomStream (precomputed key schedule) against Random123's
// own: every output bit must agree, since the random streams fix every result of a run.
#include <Random123/philox.h>
#include <gtest/gtest.h>

#include "pierre/sim/random_stream.hpp"

using namespace pierre::sim;

namespace {

void expect_same(std::uint64_t seed, std::uint64_t c0, std::uint64_t c1) {
  r123::Philox2x64 gen;
  const auto ref = gen({{c0, c1}}, {{seed}});
  std::uint64_t o0 = 0, o1 = 0;
  RandomStream::philox(PhiloxKey(seed), c0, c1, o0, o1);
  EXPECT_EQ(o0, ref[0]) << seed << " " << c0 << " " << c1;
  EXPECT_EQ(o1, ref[1]) << seed << " " << c0 << " " << c1;
}

}  // namespace

TEST(RandomStream, PhiloxMatchesRandom123) {
  const std::uint64_t values[] = {0, 1, 2, 7, 20130611, 0x9E3779B97F4A7C15ull,
                                  0xFFFFFFFFFFFFFFFFull, 0x8000000000000000ull, 123456789012345ull};
  for (std::uint64_t seed : values)
    for (std::uint64_t c0 : values)
      for (std::uint64_t c1 : values) expect_same(seed, c0, c1);
}

TEST(RandomStream, DrawsFollowTheCounter) {
  // Draw k of trajectory n is Philox of the counter {k, n}, converted as before the rewrite.
  const std::uint64_t seed = 20130611, traj = 4242;
  RandomStream rs(seed, traj);
  r123::Philox2x64 gen;
  for (std::uint64_t k = 0; k < 50; ++k) {
    const auto r = gen({{k, traj}}, {{seed}});
    const auto d = rs.impact_draws();
    EXPECT_EQ(d.roughness_u, (static_cast<double>(r[0] >> 12) + 0.5) * 0x1.0p-52);
    EXPECT_EQ(d.shape_u, (static_cast<double>(r[1] >> 12) + 0.5) * 0x1.0p-52);
    EXPECT_EQ(d.level_sign, (r[0] & 1u) != 0);
  }
  EXPECT_EQ(rs.draws_used(), 50u);
}

TEST(RandomStream, OpenUnitEnds) {
  EXPECT_GT(RandomStream::to_open_unit(0), 0.0);
  EXPECT_LT(RandomStream::to_open_unit(~std::uint64_t{0}), 1.0);
  EXPECT_EQ(RandomStream::to_open_unit(~std::uint64_t{0}), (0x1.0p52 - 0.5) * 0x1.0p-52);
}
