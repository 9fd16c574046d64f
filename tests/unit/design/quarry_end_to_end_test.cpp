// A small quarry section run through sim::run_simulation, then the quarry procedure: the
// invariants of ID and RD (design-checks.md §2) on real trajectories.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pierre/design/quarry_distances.hpp"
#include "pierre/design/quarry_geometry.hpp"
#include "pierre/design/quarry_zones.hpp"
#include "pierre/sim/runner.hpp"
#include "support/builders.hpp"

namespace pierre::design {
namespace {

TEST(QuarryEndToEnd, InvariantsOnASimulatedSection) {
  // A 20 m stepped face (quarry-preg's shape) over an 18 m floor: short, so some blocks leave.
  sim::Scenario sc;
  sc.name = "face";
  sc.profile = test::make_profile({{0, 20}, {10.38, 20}, {12.33, 16}, {14.45, 12}, {16.23, 8},
                                   {18.54, 4}, {20, 0}, {38, 0}},
                                  {1, 0, 0, 0, 0, 0, 1});
  auto face = test::make_material(5, 50, 0.65);   // Table 6.1, quarry face
  auto floor = test::make_material(5, 50, 0.35);  // Table 6.1, quarry floor
  sc.materials = {face, floor};
  for (double m : {140.0, 400.0, 1100.0, 3000.0, 8130.0}) sc.blocks.push_back(test::make_block(m));
  sc.sources = {sim::Source{"crest", {10.68, 20.5}, {0.5, 0}, 0}};
  sc.settings.seed = 2015;
  sc.settings.throws = 40;

  const auto g = quarry_geometry(sc.profile, {});
  ASSERT_TRUE(g) << g.error;
  EXPECT_EQ(g->toe_vertex, 6u);
  EXPECT_DOUBLE_EQ(g->height, 20);
  sc.settings.floor_segment = g->floor_segment;

  sim::ResultCollector sink;
  sim::RunOptions opt;
  opt.threads = 2;
  const auto report = sim::run_simulation(sc, opt, sink);
  ASSERT_FALSE(report.error);
  ASSERT_EQ(sink.trajectories.size(), 200u);

  const QuarryDistances d = quarry_distances(sink.trajectories, *g);
  EXPECT_EQ(d.thrown, 200u);
  EXPECT_EQ(d.reached_floor + d.not_reached_floor, d.thrown);
  EXPECT_EQ(d.id.size(), d.reached_floor);
  EXPECT_EQ(d.rd.size(), d.thrown);
  EXPECT_GT(d.reached_floor, 150u);
  std::uint64_t censored = 0, zeros = 0, on_floor = 0, rolled_back = 0;
  double max_back = 0;
  for (const QuarryTrajectory& t : d.trajectories) {
    EXPECT_TRUE(t.rd >= 0) << t.trajectory;  // also false for NaN
    if (std::isinf(t.rd)) {
      EXPECT_TRUE(t.censored);
      ++censored;
    }
    if (t.rd == 0) ++zeros;
    if (t.reached_floor) {
      EXPECT_GE(t.id, 0);
      EXPECT_LE(t.id, g->floor_length + 1e-9);
    }
    // A block that stopped on the floor first touched it no farther out than it stopped —
    // except that the roughness tilts the contact plane against the motion, so a rebound may
    // carry a block a little back towards the face (PIERRE 2, Eq 6.5): counted, and small.
    if (t.reached_floor && !t.censored && !t.above_toe &&
        (t.stop_reason == sim::StopReason::energy || t.stop_reason == sim::StopReason::friction)) {
      ++on_floor;
      if (t.id > t.rd) {
        ++rolled_back;
        max_back = std::max(max_back, t.id - t.rd);
      }
    }
    EXPECT_GT(t.duration, 0);
  }
  EXPECT_EQ(censored, d.left_profile);
  EXPECT_GT(censored, 0u);  // the floor is short: some leave it
  std::printf("stopped on the floor %llu, of which came back past their first floor contact %llu "
              "(at most %.3f m)\n",
              static_cast<unsigned long long>(on_floor), static_cast<unsigned long long>(rolled_back),
              max_back);
  EXPECT_GT(on_floor, 100u);
  EXPECT_LE(rolled_back * 10, on_floor);  // ID <= RD for at least 90 % of them
  EXPECT_LT(max_back, 1.0);               // and the others came back less than 1 m
  EXPECT_EQ(zeros, d.above_toe);

  QuarrySectionInput in;
  in.spec.name = "face";
  in.spec.work_areas = {{"far", 29.0}};
  in.spec.bench_width = 10;
  in.rules.name = "quarry-thesis-2015";
  in.geometry = *g;
  in.distances = d;
  const auto out = design_quarry({in}, 7);
  ASSERT_TRUE(out.design) << out.error;
  const QuarryRow& row = out.design->rows[0];
  EXPECT_EQ(row.thrown, 200u);
  EXPECT_EQ(row.rd.count, 200u);
  EXPECT_EQ(row.id.count, d.reached_floor);
  EXPECT_EQ(row.rd.censored, d.left_profile);
  EXPECT_LE(row.rd.p50, row.rd.p95);
  EXPECT_LE(row.rd.p95, row.rd.max);
  EXPECT_LE(row.id.p50, row.id.p95);
  EXPECT_DOUBLE_EQ(row.rd.p95_h * 20, row.rd.p95);
  // The thesis's Preg rows: RD50 5.5–8.0 m, ID50 1.0–2.2 m (Table 6.2, 6.3); loose bounds.
  EXPECT_GT(row.rd.p50, 2);
  EXPECT_LT(row.rd.p50, 15);
  EXPECT_LT(row.id.p50, 6);
  EXPECT_TRUE(find_if(out.design->checks.begin(), out.design->checks.end(), [](const CheckLine& l) {
                return l.id == "zone.far";
              }) != out.design->checks.end());
}

}  // namespace
}  // namespace pierre::design
