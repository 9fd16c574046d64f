// The observation tally on its own: which lines an arc crosses, in which order they are written
// (line order, whatever the order of the lines' x), and the first-crossing rule.
#include <gtest/gtest.h>

#include <cmath>

#include "pierre/sim/observation_line.hpp"
#include "support/builders.hpp"

using namespace pierre;
using namespace pierre::sim;
using geometry::Vec2;

namespace {

std::vector<std::uint32_t> lines_of(const std::vector<Crossing>& cs) {
  std::vector<std::uint32_t> out;
  for (const auto& c : cs) out.push_back(c.line);
  return out;
}

const std::vector<ObservationLine> kUnsorted = {{"c", 30}, {"a", 10}, {"b", 20}, {"a2", 10}};

// A tally over level ground (z = 0, x from 0 to 100) writing its crossings into `out`.
struct LevelTally {
  LevelTally(const std::vector<ObservationLine>& lines, bool all)
      : profile(test::make_profile({{0, 0}, {100, 0}})), tally(lines, profile, all) {
    tally.output(&out);
  }
  geometry::Profile profile;
  ObservationTally tally;
  std::vector<Crossing> out;
};

}  // namespace

TEST(ObservationTally, CrossingsAreWrittenInLineOrderForUnsortedLines) {
  LevelTally lt(kUnsorted, false);
  ObservationTally& tally = lt.tally;
  std::vector<Crossing>& out = lt.out;
  tally.begin(7, 1, 100.0, 2.0);
  tally.flight({0, 5}, {10, 0}, 0.5, 0.0, 3.0, 0.0);  // x from 0 to 30
  EXPECT_EQ(lines_of(out), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_DOUBLE_EQ(out[0].time, 3.0);
  EXPECT_DOUBLE_EQ(out[1].time, 1.0);
  EXPECT_DOUBLE_EQ(out[2].height, 5.0);
  EXPECT_EQ(out[0].trajectory, 7u);
  // Only the first crossing in the main direction counts, until the next trajectory.
  tally.flight({0, 5}, {10, 0}, 0.5, 3.0, 3.0, 0.0);
  tally.flight({30, 5}, {-10, 0}, 0.5, 6.0, 3.0, 0.0);
  EXPECT_EQ(out.size(), 4u);
  tally.begin(8, 1, 100.0, 2.0);
  tally.flight({15, 5}, {10, 0}, 0.5, 0.0, 0.5, 0.0);  // x from 15 to 20
  EXPECT_EQ(lines_of(out), (std::vector<std::uint32_t>{0, 1, 2, 3, 2}));
}

// A crossing on a falling arc, by hand: from (0, 5) m at (10, 12) m/s under g = 9.81 m/s², the
// line at x = 20 is reached after 2 s, at z = 5 + 24 − 19.62 = 9.38 m (the ground is z = 0), with
// v = (10, 12 − 19.62) = (10, −7.62) m/s. (Every other call here has g = 0: dropping −½gt² from
// the height, or −gt from v_z, passed every sim test.)
TEST(ObservationTally, ACrossingOnAFallingArcIsWhereTheParabolaIs) {
  LevelTally lt({{"L", 20}}, false);
  ObservationTally& tally = lt.tally;
  std::vector<Crossing>& out = lt.out;
  tally.begin(3, 0, 100.0, 2.0);
  tally.flight({0, 5}, {10, 12}, 1.5, 4.0, 3.0, 9.81);
  ASSERT_EQ(out.size(), 1u);
  const Crossing& c = out[0];
  EXPECT_DOUBLE_EQ(c.time, 6.0);  // t0 + 2 s
  EXPECT_NEAR(c.height, 9.38, 1e-12);
  EXPECT_NEAR(c.velocity.x, 10.0, 1e-12);
  EXPECT_NEAR(c.velocity.z, -7.62, 1e-12);
  EXPECT_NEAR(c.speed, std::sqrt(100 + 7.62 * 7.62), 1e-12);
  EXPECT_NEAR(c.translational_energy, 0.5 * 100 * (100 + 7.62 * 7.62), 1e-9);
  EXPECT_NEAR(c.rotational_energy, 0.5 * 2.0 * 1.5 * 1.5, 1e-12);
  EXPECT_FALSE(c.sliding);
}

TEST(ObservationTally, ArcsAreHalfOpenAndEveryCrossingIsKeptWhenAsked) {
  LevelTally lt(kUnsorted, true);
  ObservationTally& tally = lt.tally;
  std::vector<Crossing>& out = lt.out;
  tally.begin(0, 0, 100.0, 2.0);
  tally.flight({0, 5}, {10, 0}, 0.0, 0.0, 2.0, 0.0);  // ends on the line at 20: counted
  tally.flight({20, 5}, {10, 0}, 0.0, 2.0, 1.0, 0.0);  // starts there: not again; reaches 30
  EXPECT_EQ(lines_of(out), (std::vector<std::uint32_t>{1, 2, 3, 0}));
  out.clear();
  tally.flight({30, 5}, {-10, 0}, 0.0, 3.0, 2.5, 0.0);  // back from 30 (excluded) to 5
  EXPECT_EQ(lines_of(out), (std::vector<std::uint32_t>{1, 2, 3}));
  for (const auto& c : out) EXPECT_EQ(c.direction, -1);
  out.clear();
  tally.flight({15, 5}, {0, 3}, 0.0, 0.0, 1.0, 9.81);  // vertical: crosses nothing
  tally.flight({12, 5}, {1, 0}, 0.0, 0.0, 1.0, 0.0);   // between lines
  EXPECT_TRUE(out.empty());
}

// Sliding pieces are half-open as flight arcs are: a line at the vertex where one slide ends and
// the next begins (a line placed at a profile vertex, which users do) is crossed once, not twice,
// when every crossing is kept. (Closing the forward slide at its start passed every test.) The
// crossing time solves w0 τ + a τ²/2 = x_c − x0 by hand: from x = 0 at 10 m/s decelerating at
// 2 m/s², the line at 10 is reached at τ = 5 − √15 s at 2√15 m/s, the line at 20 at 5 − √5 s at
// 2√5 m/s.
TEST(ObservationTally, SlidesAreHalfOpenAndCrossedWhereTheMotionSaysSo) {
  LevelTally lt(kUnsorted, true);
  ObservationTally& tally = lt.tally;
  std::vector<Crossing>& out = lt.out;
  tally.begin(0, 0, 100.0, 2.0);
  tally.slide({0, 0}, {1, 0}, 10.0, 0.0, 0.0, 0.0, 2.0);  // ends on the line at 20: counted
  tally.slide({20, 0}, {1, 0}, 10.0, 0.0, 0.0, 2.0, 1.0);  // starts there: not again; reaches 30
  EXPECT_EQ(lines_of(out), (std::vector<std::uint32_t>{1, 2, 3, 0}));
  out.clear();
  tally.slide({30, 0}, {1, 0}, -10.0, 0.0, 0.0, 3.0, 2.5);  // back from 30 (excluded) to 5
  EXPECT_EQ(lines_of(out), (std::vector<std::uint32_t>{1, 2, 3}));
  for (const auto& c : out) {
    EXPECT_EQ(c.direction, -1);
    EXPECT_TRUE(c.sliding);
    EXPECT_EQ(c.height, 0.0);
  }
  out.clear();
  tally.slide({0, 0}, {1, 0}, 10.0, -2.0, 0.0, 0.0, 5.0);  // comes to rest at 25 after 5 s
  ASSERT_EQ(lines_of(out), (std::vector<std::uint32_t>{1, 2, 3}));
  EXPECT_NEAR(out[0].time, 5 - std::sqrt(15.0), 1e-12);
  EXPECT_NEAR(out[0].velocity.x, 2 * std::sqrt(15.0), 1e-12);
  EXPECT_NEAR(out[1].time, 5 - std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(out[1].velocity.x, 2 * std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(out[1].translational_energy, 0.5 * 100.0 * 20.0, 1e-9);
}
