// Crest, toe and H of quarry sections (design-checks.md §2): vertical, stepped, overhanging
// faces, profiles running to -x, given values, and sections without a floor.
#include "pierre/design/quarry_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/builders.hpp"

namespace pierre::design {
namespace {

using geometry::Vec2;

TEST(QuarryGeometry, VerticalFaceOverLevelFloor) {
  // A bench behind the crest at the crest's height: the crest is the face's edge, not the
  // bench's start.
  const auto p = test::make_profile({{0, 20}, {10, 20}, {10, 0}, {50, 0}});
  const auto g = quarry_geometry(p, {});
  ASSERT_TRUE(g) << g.error;
  EXPECT_EQ(g->crest_vertex, 1u);
  EXPECT_EQ(g->toe_vertex, 2u);
  EXPECT_DOUBLE_EQ(g->toe.x, 10);
  EXPECT_DOUBLE_EQ(g->height, 20);
  EXPECT_EQ(g->height_origin, GeometryOrigin::found);
  EXPECT_EQ(g->toe_origin, GeometryOrigin::found);
  EXPECT_EQ(g->crest_origin, GeometryOrigin::found);
  EXPECT_EQ(g->floor_segment, 2);
  EXPECT_DOUBLE_EQ(g->floor_length, 40);
  EXPECT_DOUBLE_EQ(g->source_end_distance, -10);
  EXPECT_EQ(g->direction, 1);
}

TEST(QuarryGeometry, SteppedFaceBenchesAreNotTheFloor) {
  // Two flat benches part-way down: every segment after them is not flat, so the toe is at the
  // bottom of the last face.
  const auto p = test::make_profile(
      {{0, 30}, {5, 30}, {10, 20}, {14, 20}, {19, 10}, {23, 10}, {28, 0}, {60, 0}});
  const auto g = quarry_geometry(p, {});
  ASSERT_TRUE(g) << g.error;
  EXPECT_EQ(g->crest_vertex, 1u);
  EXPECT_EQ(g->toe_vertex, 6u);
  EXPECT_DOUBLE_EQ(g->height, 30);
  EXPECT_EQ(g->floor_segment, 6);
  EXPECT_DOUBLE_EQ(g->floor_length, 32);
}

TEST(QuarryGeometry, OverhangingFace) {
  // The upper face leans back over the lower one (x decreases going down): never floor.
  const auto p = test::make_profile({{0, 20}, {12, 20}, {10, 10}, {12, 0}, {50, 0}});
  const auto g = quarry_geometry(p, {});
  ASSERT_TRUE(g) << g.error;
  EXPECT_EQ(g->crest_vertex, 1u);
  EXPECT_EQ(g->toe_vertex, 3u);
  EXPECT_DOUBLE_EQ(g->height, 20);
  EXPECT_EQ(g->floor_segment, 3);
  // Given at the chainage shared by the crest and the toe: the lowest point is the toe.
  QuarryGeometryInput in;
  in.toe_x = 12;
  const auto h = quarry_geometry(p, in);
  ASSERT_TRUE(h) << h.error;
  EXPECT_EQ(h->toe_vertex, 3u);
  EXPECT_EQ(h->toe_origin, GeometryOrigin::given);
  EXPECT_EQ(h->floor_segment, 3);
}

TEST(QuarryGeometry, GentleFloorAndLowRampStillFloor) {
  // A 10° ramp then level: both flatter than 15°, so the toe is at the foot of the face.
  const double dz = 30 * std::tan(10.0 * std::numbers::pi / 180);
  const auto p = test::make_profile({{0, 20}, {10, 20}, {20, 0}, {50, -dz}, {80, -dz}});
  const auto g = quarry_geometry(p, {});
  ASSERT_TRUE(g) << g.error;
  EXPECT_EQ(g->toe_vertex, 2u);
  EXPECT_DOUBLE_EQ(g->height, 20);
  // With a floor angle of 5° the ramp is not floor: the toe moves to its foot.
  QuarryGeometryInput in;
  in.floor_angle_deg = 5;
  const auto h = quarry_geometry(p, in);
  ASSERT_TRUE(h) << h.error;
  EXPECT_EQ(h->toe_vertex, 3u);
  EXPECT_NEAR(h->height, 20 + dz, 1e-12);
}

TEST(QuarryGeometry, ProfileRunningToMinusX) {
  const auto p = test::make_profile({{50, 20}, {40, 20}, {40, 0}, {0, 0}});
  const auto g = quarry_geometry(p, {});
  ASSERT_TRUE(g) << g.error;
  EXPECT_EQ(g->direction, -1);
  EXPECT_EQ(g->toe_vertex, 2u);
  EXPECT_DOUBLE_EQ(g->floor_length, 40);
  EXPECT_DOUBLE_EQ(distance_from_toe(*g, 30), 10);
  EXPECT_DOUBLE_EQ(distance_from_toe(*g, 45), -5);
}

TEST(QuarryGeometry, GivenValues) {
  const auto p = test::make_profile({{0, 20}, {10, 20}, {10, 0}, {50, 0}});
  QuarryGeometryInput in;
  in.toe_x = 30;  // inside the floor's first segment
  in.crest_x = 5;  // on the bench
  in.height = 18;
  const auto g = quarry_geometry(p, in);
  ASSERT_TRUE(g) << g.error;
  EXPECT_EQ(g->toe_origin, GeometryOrigin::given);
  EXPECT_EQ(g->crest_origin, GeometryOrigin::given);
  EXPECT_EQ(g->height_origin, GeometryOrigin::given);
  EXPECT_FALSE(g->toe_vertex.has_value());
  EXPECT_DOUBLE_EQ(g->toe.x, 30);
  EXPECT_DOUBLE_EQ(g->toe.z, 0);
  EXPECT_EQ(g->floor_segment, 2);  // the segment holding the toe
  EXPECT_DOUBLE_EQ(g->height, 18);
  EXPECT_DOUBLE_EQ(g->height_derived, 20);
  EXPECT_DOUBLE_EQ(g->floor_length, 20);
}

TEST(QuarryGeometry, Failures) {
  // Ends in a 20° slope: no floor flatter than 15°.
  const auto steep = test::make_profile({{0, 20}, {10, 20}, {10, 5}, {30, 5 - 20 * std::tan(0.35)}});
  const auto a = quarry_geometry(steep, {});
  EXPECT_FALSE(a);
  EXPECT_NE(a.error.find("a section with no toe"), std::string::npos) << a.error;
  const auto p = test::make_profile({{0, 20}, {10, 20}, {10, 0}, {50, 0}});
  QuarryGeometryInput out;
  out.toe_x = 60;
  EXPECT_FALSE(quarry_geometry(p, out));
  QuarryGeometryInput last;
  last.toe_x = 50;  // the last vertex: no floor past it
  EXPECT_FALSE(quarry_geometry(p, last));
  QuarryGeometryInput before;
  before.toe_x = 5;
  before.crest_x = 10;
  EXPECT_FALSE(quarry_geometry(p, before));
  // Level everywhere: crest = toe, H = 0.
  const auto flat = test::make_profile({{0, 0}, {10, 0}, {20, 0}});
  const auto f = quarry_geometry(flat, {});
  EXPECT_FALSE(f);
}

// design-checks.md §2: the floor is where every later segment is *flatter* than the floor angle.
// A segment exactly at the floor angle is not floor: with a floor angle of 45°, a 1:1 segment
// (atan2(10, 10) is 45° to the last bit) belongs to the face, and the toe is at its foot.
// (Treating "at the angle" as flat passed every test.)
TEST(QuarryGeometry, ASegmentAtExactlyTheFloorAngleIsNotFloor) {
  const auto p = test::make_profile({{0, 40}, {10, 10}, {20, 0}, {100, 0}});
  QuarryGeometryInput in;
  in.floor_angle_deg = 45;
  const auto g = quarry_geometry(p, in);
  ASSERT_TRUE(g) << g.error;
  EXPECT_EQ(g->toe_vertex, 2u);
  EXPECT_DOUBLE_EQ(g->toe.x, 20);
  EXPECT_DOUBLE_EQ(g->height, 40);
  // Just steeper than the segment, the floor angle makes it floor.
  in.floor_angle_deg = 45.001;
  const auto h = quarry_geometry(p, in);
  ASSERT_TRUE(h) << h.error;
  EXPECT_EQ(h->toe_vertex, 1u);
  EXPECT_DOUBLE_EQ(h->height, 30);
}

}  // namespace
}  // namespace pierre::design
