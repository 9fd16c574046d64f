// ID/RD bookkeeping on hand-made trajectory summaries (design-checks.md §2).
#include "pierre/design/quarry_distances.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/builders.hpp"

namespace pierre::design {
namespace {

using sim::StopReason;
using sim::TrajectorySummary;

TrajectorySummary traj(double stop_x, StopReason why, std::optional<double> floor_x,
                       double stop_z = 0, double start_x = 10.5) {
  static std::uint64_t k = 0;
  TrajectorySummary t;
  t.trajectory = k++;
  t.start = {start_x, 20.5};
  t.stop = {stop_x, stop_z};
  t.stop_reason = why;
  t.duration = 3;
  if (floor_x) {
    t.has_floor_contact = true;
    t.floor_contact = {*floor_x, 0};
  }
  return t;
}

TEST(QuarryDistances, Bookkeeping) {
  // A 20 m vertical face at x = 10 over a 40 m floor, a bench behind the crest.
  const auto p = test::make_profile({{0, 20}, {10, 20}, {10, 0}, {50, 0}});
  const auto g = *quarry_geometry(p, {});
  const std::vector<TrajectorySummary> ts = {
      traj(5, StopReason::friction, std::nullopt, 20),  // never reaches the floor: on the bench
      traj(25, StopReason::energy, 13),                   // impact 3 m out, stops 15 m out
      traj(18, StopReason::friction, 10),                 // slid across the toe: ID 0
      traj(50, StopReason::boundary, 20),                 // left the profile's end: censored
      traj(12, StopReason::friction, 16),                 // rolled back: ID 6 > RD 2
      traj(0, StopReason::boundary, std::nullopt, 20),    // went back over the crest
      traj(30, StopReason::time_limit, 14),               // abnormal stop: kept where it was
  };
  const QuarryDistances d = quarry_distances(ts, g);
  EXPECT_EQ(d.thrown, 7u);
  EXPECT_EQ(d.reached_floor, 5u);
  EXPECT_EQ(d.not_reached_floor, 2u);
  EXPECT_EQ(d.reached_floor + d.not_reached_floor, d.thrown);
  EXPECT_EQ(d.above_toe, 2u);
  EXPECT_EQ(d.left_upslope, 1u);
  EXPECT_EQ(d.left_profile, 1u);
  EXPECT_EQ(d.abnormal, 1u);
  EXPECT_DOUBLE_EQ(d.censor_distance, 40);
  ASSERT_EQ(d.rd.size(), 7u);
  ASSERT_EQ(d.id.size(), 5u);
  EXPECT_EQ(d.rd[0], 0);
  EXPECT_TRUE(d.trajectories[0].above_toe);
  EXPECT_FALSE(d.trajectories[0].reached_floor);
  EXPECT_TRUE(std::isnan(d.trajectories[0].id));
  EXPECT_DOUBLE_EQ(d.rd[1], 15);
  EXPECT_DOUBLE_EQ(d.trajectories[1].id, 3);
  EXPECT_DOUBLE_EQ(d.rd[2], 8);
  EXPECT_DOUBLE_EQ(d.trajectories[2].id, 0);
  EXPECT_TRUE(std::isinf(d.rd[3]));
  EXPECT_TRUE(d.trajectories[3].censored);
  EXPECT_DOUBLE_EQ(d.trajectories[3].id, 10);
  EXPECT_DOUBLE_EQ(d.rd[4], 2);
  EXPECT_DOUBLE_EQ(d.trajectories[4].id, 6);
  EXPECT_EQ(d.rd[5], 0);
  EXPECT_FALSE(d.trajectories[5].censored);
  EXPECT_DOUBLE_EQ(d.rd[6], 20);
  EXPECT_EQ(d.trajectories[6].stop_reason, StopReason::time_limit);
  const std::vector<double> ids = {3, 0, 10, 6, 4};
  EXPECT_EQ(d.id, ids);
  EXPECT_EQ(d.duration.size(), 7u);
}

TEST(QuarryDistances, ProfileRunningToMinusX) {
  const auto p = test::make_profile({{50, 20}, {40, 20}, {40, 0}, {0, 0}});
  const auto g = *quarry_geometry(p, {});
  const std::vector<TrajectorySummary> ts = {
      traj(30, StopReason::energy, 37, 0, 39.5),  // 3 m out, stops 10 m out
      traj(0, StopReason::boundary, 35, 0, 39.5),  // left at x = 0: the runout end
      traj(50, StopReason::boundary, std::nullopt, 20, 39.5),  // back over the source end
  };
  const auto d = quarry_distances(ts, g);
  EXPECT_DOUBLE_EQ(d.id[0], 3);
  EXPECT_DOUBLE_EQ(d.rd[0], 10);
  EXPECT_TRUE(std::isinf(d.rd[1]));
  EXPECT_EQ(d.rd[2], 0);
  EXPECT_EQ(d.left_profile, 1u);
  EXPECT_EQ(d.left_upslope, 1u);
}

TEST(QuarryDistances, GivenToeInsideASegmentClampsEarlyContacts) {
  const auto p = test::make_profile({{0, 20}, {10, 20}, {10, 0}, {50, 0}});
  QuarryGeometryInput in;
  in.toe_x = 12;
  const auto g = *quarry_geometry(p, in);
  // A floor contact at x = 11 (on the floor segment, before the given toe): ID 0.
  const auto d = quarry_distances(std::vector{traj(20, StopReason::energy, 11)}, g);
  EXPECT_EQ(d.id[0], 0);
  EXPECT_DOUBLE_EQ(d.rd[0], 8);
}

}  // namespace
}  // namespace pierre::design
