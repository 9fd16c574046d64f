// RandomStream's draws against Random123's Philox2x64 called directly: draw k of trajectory n
// is Philox of the counter {k, n}, whether the stream is made from the seed or the shared key.
#include <Random123/philox.h>
#include <gtest/gtest.h>

#include "pierre/sim/random_stream.hpp"

using namespace pierre::sim;

TEST(RandomStream, DrawsFollowTheCounter) {
  // Draw k of trajectory n is Philox of the counter {k, n}, converted as before the rewrite.
  const std::uint64_t seed = 20130611, traj = 4242;
  RandomStream rs(seed, traj), shared(PhiloxKey(seed), traj);
  r123::Philox2x64 gen;
  for (std::uint64_t k = 0; k < 50; ++k) {
    const auto r = gen({{k, traj}}, {{seed}});
    const auto d = rs.impact_draws();
    EXPECT_EQ(d.roughness_u, (static_cast<double>(r[0] >> 12) + 0.5) * 0x1.0p-52);
    EXPECT_EQ(d.shape_u, (static_cast<double>(r[1] >> 12) + 0.5) * 0x1.0p-52);
    EXPECT_EQ(d.level_sign, (r[0] & 1u) != 0);
    EXPECT_EQ(shared.impact_draws().roughness_u, d.roughness_u);
  }
  EXPECT_EQ(rs.draws_used(), 50u);
}

TEST(RandomStream, OpenUnitEnds) {
  EXPECT_GT(RandomStream::to_open_unit(0), 0.0);
  EXPECT_LT(RandomStream::to_open_unit(~std::uint64_t{0}), 1.0);
  EXPECT_EQ(RandomStream::to_open_unit(~std::uint64_t{0}), (0x1.0p52 - 0.5) * 0x1.0p-52);
}
