// model-2d.md §7 tests 1 and 2: exact contacts of the flight parabola.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pierre/geometry/profile.hpp"
#include "support/builders.hpp"

using namespace pierre::geometry;
using pierre::test::make_profile;

namespace {
constexpr double g = 9.81;
}

TEST(ProfileContact, FreeFallOntoLevelGroundMatchesClosedForm) {
  const Profile p = make_profile({{-10, 0}, {10, 0}});
  for (double h : {0.1, 1.0, 12.5, 250.0}) {
    const auto c = p.first_contact({0.3, h}, {0, 0}, g, 1e9, Departure{});
    ASSERT_TRUE(c);
    const double t = std::sqrt(2 * h / g);
    EXPECT_NEAR(c->t, t, 1e-12 * t);  // (the contact speed g t follows; the simulator's own
                                      // incident speed is checked in trajectory_test.cpp)
  }
}

// Without a time limit (t_max = ∞) the search must still find the ground: a vertical flight's
// window over every node is then endless, and an endless window's lowest point is −∞. (It was
// evaluated as NaN when the block rose or fell from rest, and every node was skipped.)
TEST(ProfileContact, VerticalFlightWithoutATimeLimitFindsTheGround) {
  const Profile p = make_profile({{0, 100}, {100, 0}, {150, 0}});
  const double inf = std::numeric_limits<double>::infinity();
  for (double vz : {0.0, 3.0, -3.0}) {
    SCOPED_TRACE(vz);
    const auto c = p.first_contact({0.5, 200}, {0, vz}, g, inf, Departure{});
    ASSERT_TRUE(c);
    const double h = 200 - 99.5;  // above the slope z = 100 − x at x = 0.5
    const double t = (vz + std::sqrt(vz * vz + 2 * g * h)) / g;
    EXPECT_NEAR(c->t, t, 1e-12 * t);
    EXPECT_EQ(c->segment, 0);
  }
}

TEST(ProfileContact, InclinedSegmentRootIsExact) {
  // Ground z = -0.5 x (descending to +x); block from (0, 10) with v = (3, 1).
  const Profile p = make_profile({{-5, 2.5}, {100, -50}});
  const auto c = p.first_contact({0, 10}, {3, 1}, g, 1e9, Departure{});
  ASSERT_TRUE(c);
  // 10 + t - g t²/2 = -0.5 * 3 t  ->  g/2 t² - 2.5 t - 10 = 0
  const double t = (2.5 + std::sqrt(2.5 * 2.5 + 4 * (g / 2) * 10)) / g;
  EXPECT_NEAR(c->t, t, 1e-12 * t);
  const double x = 3 * t;
  EXPECT_NEAR(c->s, std::hypot(x + 5, -0.5 * x - 2.5), 1e-9);
}

TEST(ProfileContact, VerticalFaceIsHitFromTheAirSide) {
  // Floor, then a wall rising at x = 10 (air on the left of the walking direction: x < 10).
  const Profile p = make_profile({{0, 0}, {10, 0}, {10, 20}, {30, 20}});
  const auto c = p.first_contact({2, 25}, {4, 2}, g, 1e9, Departure{});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->segment, 1);
  EXPECT_NEAR(c->t, 8.0 / 4.0, 1e-12);
  const double z = 25 + 2 * 2.0 - 0.5 * g * 4.0;  // still above the floor at t = 2
  ASSERT_GT(z, 0);
  EXPECT_NEAR(c->s, z, 1e-9);
}

TEST(ProfileContact, OverhangIsHitFromBelow) {
  // Walking +x along the floor, up a wall at x = 10, then back over the floor (overhang
  // underside from (10, 6) to (4, 6)): its outward normal points down.
  const Profile p = make_profile({{0, 0}, {10, 0}, {10, 6}, {4, 6}, {4, 7}, {20, 7}});
  EXPECT_LT(p.segment(2).n.z, 0);
  const auto c = p.first_contact({5, 1}, {0.5, 12}, g, 1e9, Departure{});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->segment, 2);
  // 1 + 12 t - g t²/2 = 6: the first (rising) root.
  const double t = (12 - std::sqrt(144 - 2 * g * 5)) / g;
  EXPECT_NEAR(c->t, t, 1e-12);
  // Where: x = 5 + 0.5 t on the underside, measured from its start vertex (10, 6) going -x.
  EXPECT_NEAR(c->s, 10 - (5 + 0.5 * t), 1e-12);
}

TEST(ProfileContact, DepartureFromASegmentFindsTheNextContactNotTimeZero) {
  const Profile p = make_profile({{0, 10}, {100, -40}});  // slope -0.5
  const Segment& s = p.segment(0);
  const Vec2 start = s.a + 20.0 * s.d;
  const Vec2 v = 2.0 * s.n + 6.0 * s.d;  // rebound leaving the surface
  Departure dep;
  dep.segment[0] = 0;
  const auto c = p.first_contact(start, v, g, 1e9, dep);
  ASSERT_TRUE(c);
  // (p(t) - a)·n = 2 t - g n_z t²/2 = 0  ->  t = 4 / (g n_z)
  EXPECT_NEAR(c->t, 4.0 / (g * s.n.z), 1e-12);
  EXPECT_GT(c->s, 20.0);
}

TEST(ProfileContact, GrazingDepartureAlongTheSurfaceDoesNotFallThrough) {
  // Leaving a 10° segment exactly along it must land on it again after 2 v·n/(g n_z) = 0,
  // i.e. no spurious contact at t = 0 and no fall through: with v·n tiny positive the root
  // is tiny and positive.
  const Profile p = make_profile({{0, 0}, {10, -10 * std::tan(0.1745)}, {40, -12}});
  const Segment& s = p.segment(0);
  Departure dep;
  dep.segment[0] = 0;
  const Vec2 v = 5.0 * s.d + 1e-3 * s.n;
  const auto c = p.first_contact(s.a + 3.0 * s.d, v, g, 1e9, dep);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->segment, 0);
  EXPECT_NEAR(c->t, 2e-3 / (g * s.n.z), 1e-15);
}

TEST(ProfileContact, DepartureFromConvexVertexLandsOnTheSteeperSegment) {
  // 10° then 40°: sliding off the vertex at 3 m/s.
  const double a1 = 10 * M_PI / 180, a2 = 40 * M_PI / 180;
  const Vec2 v1{10, -10 * std::tan(a1)};
  const Profile p = make_profile({{0, 0}, v1, {v1.x + 30, v1.z - 30 * std::tan(a2)}});
  ASSERT_EQ(p.turn_after(0), VertexTurn::convex);
  const Vec2 vel = 3.0 * p.segment(0).d;
  Departure dep;
  dep.segment[0] = 0;
  dep.tangent[0] = true;
  dep.segment[1] = 1;
  const auto c = p.first_contact(v1, vel, g, 1e9, dep);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->segment, 1);
  const Segment& s = p.segment(1);
  EXPECT_NEAR(c->t, 2 * dot(vel, s.n) / (g * s.n.z), 1e-12);
  EXPECT_GT(c->t, 0.0);
}

TEST(ProfileContact, SubdividedSegmentGivesTheSameContact) {
  std::vector<Vec2> coarse{{0, 20}, {10, 0}, {60, 0}};
  std::vector<Vec2> fine;
  for (int i = 0; i < 1000; ++i) fine.push_back({i * 0.01, 20 - i * 0.02});
  for (int i = 0; i <= 5000; ++i) fine.push_back({10 + i * 0.01, 0});
  const Profile pc = make_profile(coarse), pf = make_profile(fine);
  const auto cc = pc.first_contact({-1, 25}, {4, 1}, g, 1e9, Departure{});
  const auto cf = pf.first_contact({-1, 25}, {4, 1}, g, 1e9, Departure{});
  ASSERT_TRUE(cc && cf);
  EXPECT_NEAR(cc->t, cf->t, 1e-10);
}

TEST(ProfileGround, GroundBelowUnderAnOverhangIsTheFloor) {
  const Profile p = make_profile({{0, 0}, {10, 0}, {10, 6}, {4, 6}, {4, 7}, {20, 7}});
  EXPECT_NEAR(p.ground_below(5, 3)->z, 0.0, 1e-12);
  EXPECT_NEAR(p.ground_below(5, 8)->z, 7.0, 1e-12);
  EXPECT_NEAR(p.top_ground(5)->z, 7.0, 1e-12);
}

TEST(ProfileGround, MaxJumpHeightOfAnArcOverLevelGround) {
  const Profile p = make_profile({{0, 0}, {100, 0}});
  // Apex height v_z²/2g above the start height 1 m.
  EXPECT_NEAR(p.max_height_above_ground({1, 1}, {3, 6}, g, 1.0), 1 + 36 / (2 * g), 1e-12);
  // Over a 30° slope the largest gap is where the arc's slope equals the ground's.
  const double m = -std::tan(M_PI / 6);
  const Profile q = make_profile({{0, 0}, {100, 100 * m}});
  const double vx = 5, vz = 2;
  const double t_star = (vz - vx * m) / g;  // d/dt [z(t) - m x(t)] = 0
  const double h = vz * t_star - 0.5 * g * t_star * t_star - m * vx * t_star;
  EXPECT_NEAR(q.max_height_above_ground({0, 0}, {vx, vz}, g, 10.0), h, 1e-12);
}

TEST(ProfileBuild, RejectsSelfIntersectionAndTooFewVertices) {
  std::vector<ProfileIssue> issues;
  EXPECT_FALSE(Profile::build({{0, 0}}, {}, &issues));
  ASSERT_FALSE(issues.empty());
  issues.clear();
  EXPECT_FALSE(Profile::build({{0, 0}, {10, 0}, {10, 5}, {5, -5}}, {0, 0, 0}, &issues));
  ASSERT_FALSE(issues.empty());
  EXPECT_NE(issues[0].what.find("crosses itself"), std::string::npos);
  EXPECT_TRUE(Profile::build({{0, 0}, {10, -5}, {20, -5}}, {0, 0}, &issues));
  // One material a segment: a short list left segments on material 0 without a word.
  issues.clear();
  EXPECT_FALSE(Profile::build({{0, 0}, {10, -5}, {20, -5}}, {1}, &issues));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].vertex, 1u);
  EXPECT_NE(issues[0].what.find("2 segments, 1 materials"), std::string::npos) << issues[0].what;
}

// A segment cut into two collinear pieces is the same ground (model-2d.md §2): the same heights
// and the same contact for the same flight, the pieces keeping the segment's material.
TEST(ProfileBuild, SplittingASegmentKeepsTheGround) {
  const Profile p = make_profile({{0, 30}, {10, 10}, {40, 0}}, {3, 7});
  std::vector<ProfileIssue> issues;
  const Vec2 cut_at = {25, 5};  // on the second segment's line
  const auto q = p.split_at(1, cut_at, &issues);
  ASSERT_TRUE(q) << (issues.empty() ? "" : issues[0].what);
  ASSERT_EQ(q->segment_count(), 3u);
  EXPECT_EQ(q->segment(1).b.x, 25);
  EXPECT_EQ(q->segment(1).material, 7);
  EXPECT_EQ(q->segment(2).material, 7);
  EXPECT_EQ(q->turn_after(1), VertexTurn::straight);
  for (double x : {5.0, 12.0, 24.9, 25.0, 25.1, 39.0})
    EXPECT_NEAR(q->top_ground(x)->z, p.top_ground(x)->z, 1e-12) << x;
  // A block dropped from above x = 30 lands at the same point of the line either way.
  const auto c0 = p.first_contact({30, 20}, {0, 0}, 9.81, 100, {});
  const auto c1 = q->first_contact({30, 20}, {0, 0}, 9.81, 100, {});
  ASSERT_TRUE(c0 && c1);
  EXPECT_NEAR(c1->t, c0->t, 1e-12);
  EXPECT_EQ(c1->segment, 2);
  // A point off the segment's line, or a segment that is not there, is refused.
  EXPECT_FALSE(p.split_at(1, {25, 6}, &issues));
  ASSERT_FALSE(issues.empty());
  EXPECT_NE(issues[0].what.find("not on the segment's line"), std::string::npos) << issues[0].what;
  EXPECT_FALSE(p.split_at(2, cut_at, &issues));
}
