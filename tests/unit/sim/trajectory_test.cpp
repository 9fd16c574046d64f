// model-2d.md §7 tests 9 and 10, and whole-trajectory invariants.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "pierre/sim/runner.hpp"
#include "pierre/sim/trajectory.hpp"
#include "support/builders.hpp"

using namespace pierre;
using namespace pierre::sim;
using geometry::Vec2;

namespace {

ResultCollector run(const Scenario& s, unsigned threads, bool impacts = false,
                    std::uint32_t chunk = 512) {
  ResultCollector c;
  RunOptions o;
  o.threads = threads;
  o.record_impacts = impacts;
  o.chunk_size = chunk;
  run_simulation(s, o, c);
  return c;
}

Scenario slope_scenario(std::uint64_t seed = 42) {
  // A 35° talus slope, a break to 10°, then a level floor: blocks fly, roll, slide and stop.
  const double t35 = std::tan(35 * M_PI / 180), t10 = std::tan(10 * M_PI / 180);
  auto prof = test::make_profile(
      {{0, 100}, {100, 100 - 100 * t35}, {140, 100 - 100 * t35 - 40 * t10}, {400, 100 - 100 * t35 - 40 * t10}});
  std::vector<model::Block> blocks{test::make_block(500, 1.0, 1.5), test::make_block(3000, 1.0, 1.5)};
  Scenario s = test::make_scenario(std::move(prof), test::make_material(15, 50, 0.7), blocks,
                                   {0, 101}, 200, seed);
  s.lines = {{"upper", 50}, {"lower", 120}};
  return s;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Trajectory 0 of `s` alone, with its path drawn `step` seconds apart into `path`.
TrajectorySummary simulate_with_path(const Scenario& s, std::vector<Vec2>& path, double step) {
  const TrajectoryModel model(s);
  ObservationTally tally(s.lines, s.profile, false);
  std::vector<Crossing> crossings;
  tally.output(&crossings);
  return simulate_trajectory(model, 0, tally, nullptr, &path, step);
}

}  // namespace

TEST(Runner, IdenticalResultsForOneTwoAndEightThreads) {
  const Scenario s = slope_scenario();
  const auto r1 = run(s, 1, true, 7), r2 = run(s, 2, true, 7), r8 = run(s, 8, true, 7);
  ASSERT_EQ(r1.trajectories.size(), 400u);
  for (const auto* r : {&r2, &r8}) {
    ASSERT_EQ(r->trajectories.size(), r1.trajectories.size());
    ASSERT_EQ(r->crossings.size(), r1.crossings.size());
    ASSERT_EQ(r->impacts.size(), r1.impacts.size());
    for (std::size_t i = 0; i < r1.trajectories.size(); ++i) {
      const auto &a = r1.trajectories[i], &b = r->trajectories[i];
      EXPECT_EQ(a.trajectory, b.trajectory);
      EXPECT_TRUE(same_bits(a.stop.x, b.stop.x) && same_bits(a.stop.z, b.stop.z));
      EXPECT_TRUE(same_bits(a.duration, b.duration));
      EXPECT_TRUE(same_bits(a.max_jump_height, b.max_jump_height));
      EXPECT_EQ(a.impacts, b.impacts);
    }
    for (std::size_t i = 0; i < r1.crossings.size(); ++i) {
      EXPECT_TRUE(same_bits(r1.crossings[i].speed, r->crossings[i].speed));
      EXPECT_TRUE(same_bits(r1.crossings[i].height, r->crossings[i].height));
    }
    for (std::size_t i = 0; i < r1.impacts.size(); i += 97)
      EXPECT_TRUE(same_bits(r1.impacts[i].detail.roughness_deg, r->impacts[i].detail.roughness_deg));
  }
  // And a different seed gives different trajectories.
  const auto other = run(slope_scenario(43), 2);
  int differ = 0;
  for (std::size_t i = 0; i < other.trajectories.size(); ++i)
    differ += other.trajectories[i].stop.x != r1.trajectories[i].stop.x;
  EXPECT_GT(differ, 300);
}

// A failure inside a worker thread (here the progress callback; out of memory with --impacts
// is the real case) is reported in RunReport::error and stops the run; it used to leave the
// thread and end the program through std::terminate (exit 134).
TEST(Runner, AWorkerThreadsFailureIsReportedNotFatal) {
  for (unsigned threads : {1u, 2u, 4u}) {
    ResultCollector c;
    RunOptions o;
    o.threads = threads;
    o.chunk_size = 16;
    int calls = 0;
    const auto rep = run_simulation(slope_scenario(), o, c, [&](std::uint64_t, std::uint64_t) {
      if (++calls == 3) throw std::runtime_error("the disk is full");
    });
    ASSERT_TRUE(rep.error) << threads;
    EXPECT_EQ(*rep.error, "the disk is full");
    EXPECT_FALSE(rep.interrupted);
    EXPECT_LT(c.trajectories.size(), slope_scenario().trajectory_count());
  }
}

TEST(Trajectory, EveryTrajectoryEndsFiniteOnTheSlope) {
  const Scenario s = slope_scenario();
  const auto r = run(s, 2);
  for (const auto& t : r.trajectories) {
    EXPECT_NE(t.stop_reason, StopReason::numerical);
    EXPECT_TRUE(std::isfinite(t.stop.x) && std::isfinite(t.stop.z));
    const auto ground = s.profile.top_ground(t.stop.x);
    if (t.stop_reason == StopReason::energy || t.stop_reason == StopReason::friction) {
      ASSERT_TRUE(ground);
      EXPECT_NEAR(t.stop.z, ground->z, 1e-6);  // stopped on the ground, not in it
    }
    EXPECT_GE(t.max_jump_height, 0.0);
    EXPECT_GT(t.impacts, 0u);
  }
}

TEST(Trajectory, BlocksOnALongLevelFloorAllStop) {
  auto prof = test::make_profile({{0, 0}, {5000, 0}});
  std::vector<model::Block> blocks{test::make_block(200), test::make_block(5000, 0.8, 1.6)};
  Scenario s = test::make_scenario(std::move(prof), test::make_material(5, 50, 0.35), blocks,
                                   {10, 3}, 100);
  s.sources[0].velocity = {12, 0};
  for (const auto& t : run(s, 2).trajectories) {
    EXPECT_TRUE(t.stop_reason == StopReason::energy || t.stop_reason == StopReason::friction)
        << to_string(t.stop_reason);
    EXPECT_LT(t.stop.x, 5000);
  }
}

TEST(Trajectory, BlockInAVNotchStopsInFiniteTime) {
  // Two 40° flanks meeting at (50, 0); φ = 30° < 40°, so it cannot rest on a flank.
  const double t40 = std::tan(40 * M_PI / 180);
  auto prof = test::make_profile({{0, 50 * t40}, {50, 0}, {100, 50 * t40}});
  Scenario s = test::make_scenario(std::move(prof), test::make_material(15, 50, 0.5, 30),
                                   {test::make_block(1000)}, {20, 30 * t40}, 50);
  for (const auto& t : run(s, 1).trajectories) {
    EXPECT_TRUE(t.stop_reason == StopReason::energy || t.stop_reason == StopReason::friction)
        << to_string(t.stop_reason);
    EXPECT_LT(t.duration, 600.0);
    // It ends in the notch, below where it started (the energy criterion may stop it on a
    // flank: a stop is an impact whose rebound head is below c_stop R, wherever it is).
    EXPECT_GT(t.stop.x, 20.0);
    EXPECT_LT(t.stop.x, 80.0);
    EXPECT_LT(t.stop.z, 30 * t40);
  }
}

// The energy criterion (Eq 3.13) stops a block whatever the slope; a stop on ground steeper
// than its friction angle is marked with that ground's tan β, for the run's note. In a notch
// of two 40° flanks (φ = 30°) every energy stop is on a flank: those on the near flank, falling
// onwards, are marked; those on the far flank, a counter-slope rising in the travel direction,
// are not (a block there would slide back, short of its stop: the note's advice to let blocks
// go on misfired on a ditch's far side, user review). On ground flatter than φ none is steep.
TEST(Trajectory, AnEnergyStopOnGroundSteeperThanItsFrictionAngleIsMarked) {
  const double t40 = std::tan(40 * M_PI / 180);
  Scenario notch = test::make_scenario(test::make_profile({{0, 50 * t40}, {50, 0}, {100, 50 * t40}}),
                                       test::make_material(15, 50, 0.5, 30), {test::make_block(1000)},
                                       {20, 30 * t40}, 50);
  std::size_t near = 0, far = 0;
  // Within the block's radius of the notch's bottom a block rests on the far flank too, where
  // sliding back ends: not marked.
  const double radius = test::make_block(1000).radius();
  for (const auto& t : run(notch, 1).trajectories) {
    if (t.stop_reason == StopReason::energy && t.stop.x < 50) {
      ++near;
      const bool at_bottom = (50 - t.stop.x) / std::cos(40 * M_PI / 180) < radius;
      EXPECT_NEAR(t.steep_stop_tan, at_bottom ? 0.0 : t40, 1e-6);  // a float: 7 digits
    } else {
      far += t.stop_reason == StopReason::energy;
      EXPECT_EQ(t.steep_stop_tan, 0.0f) << t.stop.x;
    }
  }
  EXPECT_GT(near, 0u);
  EXPECT_GT(far, 0u);
  // The same flanks at 25° < φ: no stop there is steep.
  const double t25 = std::tan(25 * M_PI / 180);
  Scenario gentle = test::make_scenario(test::make_profile({{0, 50 * t25}, {50, 0}, {100, 50 * t25}}),
                                        test::make_material(15, 50, 0.5, 30), {test::make_block(1000)},
                                        {20, 30 * t25 + 5}, 50);
  std::size_t energy = 0;
  for (const auto& t : run(gentle, 1).trajectories) {
    energy += t.stop_reason == StopReason::energy;
    EXPECT_EQ(t.steep_stop_tan, 0.0f);
  }
  EXPECT_GT(energy, 0u);
}

// A block stopped at the toe, the vertex between a 45° face and a level floor, rests on the
// floor's start: the ground onward is level, and the stop is not one on steep ground (a checking
// engineer found "steep" stops at x = 16.16 m, the toe vertex of a quarry face to 9 digits). A
// drop a hundredth of a micrometre short of the vertex strikes the face's last point.
TEST(Trajectory, AnEnergyStopAtTheToeVertexIsNotOnSteepGround) {
  for (const double x : {10 - 1e-8, 10.0}) {
    Scenario toe = test::make_scenario(test::make_profile({{0, 10}, {10, 0}, {30, 0}}),
                                       test::make_material(15, 50, 0.5, 30), {test::make_block(1000)},
                                       {x, 0.3}, 20);
    toe.settings.stop_head_factor = 10;  // every block stops at its first impact
    for (const auto& t : run(toe, 1).trajectories) {
      ASSERT_EQ(t.stop_reason, StopReason::energy);
      ASSERT_EQ(t.impacts, 1u);
      EXPECT_NEAR(t.stop.x, 10, 1e-7);
      EXPECT_EQ(t.steep_stop_tan, 0.0f) << x;
    }
  }
  // Within the block's radius (0.45 m for 1000 kg at 2650 kg/m³) up the face it rests at the
  // toe too; a drop 1.4 m up the face (1 m in x) stops on steep ground.
  for (const double x : {9.8, 9.0}) {
    Scenario face = test::make_scenario(test::make_profile({{0, 10}, {10, 0}, {30, 0}}),
                                        test::make_material(15, 50, 0.5, 30), {test::make_block(1000)},
                                        {x, 10.3 - x}, 5);
    face.settings.stop_head_factor = 10;
    for (const auto& t : run(face, 1).trajectories)
      EXPECT_NEAR(t.steep_stop_tan, x == 9.0 ? 1.0 : 0.0, 1e-6) << x;
  }
}

// Placed on the ground (source below it) with φ = 30° on a 45° slope: a = g (sin 45 − cos 45
// tan 30) > 0. The first impact is the launch at the maximum sliding speed (5 m/s), after sliding
// s = v²/2a along the slope: exactly where the closed form puts it. The same in the mirror image,
// where the slope rises along the vertex order and the block slides towards −x, against the main
// direction (the launch time is (−5 − w)/a in that direction: writing +5 launched it at once,
// from rest, and passed every test).
TEST(Trajectory, BlockOnA45DegreeSlopeSlidesLaunchesAndKeepsGoing) {
  struct Case {
    const char* name;
    std::vector<Vec2> profile;
    double x0;   // the source's x (150 m high, below the ground: placed on it at 190 m)
    double dir;  // +1 slides towards +x, −1 towards −x
    double toe;  // the slope's foot: it goes all the way down past it
  };
  const Case cases[] = {{"along the vertex order", {{0, 200}, {200, 0}, {600, 0}}, 10, 1, 200},
                        {"towards the first vertex", {{0, 0}, {400, 0}, {600, 200}}, 590, -1, 400}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Scenario s = test::make_scenario(test::make_profile(c.profile),
                                     test::make_material(15, 50, 0.3, 30),
                                     {test::make_block(1000)}, {c.x0, 150}, 20);
    const auto r = run(s, 1, true);
    for (const auto& t : r.trajectories) {
      EXPECT_NEAR(t.start.z, 190.0, 1e-9);          // placed on the ground
      EXPECT_GT(c.dir * (t.stop.x - c.toe), 0.0);  // went all the way down
      EXPECT_NE(t.stop_reason, StopReason::numerical);
    }
    const double a = 9.81 * (std::sin(M_PI / 4) - std::cos(M_PI / 4) * std::tan(M_PI / 6));
    const double s_launch = 25.0 / (2 * a);
    ASSERT_FALSE(r.impacts.empty());
    const auto& first = r.impacts.front();
    EXPECT_EQ(first.index, 0u);
    EXPECT_NEAR(first.time, 5.0 / a, 1e-9);
    EXPECT_NEAR(first.position.x, c.x0 + c.dir * s_launch / std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(std::hypot(first.detail.vt_in, first.detail.vn_in), 5.0, 1e-9);
  }
}

TEST(Trajectory, BlockAtRestOnAGentleSlopeStopsByFriction) {
  auto prof = test::make_profile({{0, 20}, {100, 0}});  // 11.3° < φ = 30°
  Scenario s = test::make_scenario(std::move(prof), test::make_material(15, 50, 0.3, 30),
                                   {test::make_block(1000)}, {10, 0}, 3);
  for (const auto& t : run(s, 1).trajectories) {
    EXPECT_EQ(t.stop_reason, StopReason::friction);
    EXPECT_EQ(t.duration, 0.0);
    EXPECT_EQ(t.impacts, 0u);
  }
}

// A source inside the rock is placed on the ground over it (model-2d.md §1: "on or below
// ground: placed on the ground"), also under an overhang, where ground lies below it too: in the
// ledge it goes onto the ledge's top, below the slope under the ledge onto that slope. (It used
// to start in flight whenever any ground lay below it, and fell through the ledge's underside.)
TEST(Trajectory, ASourceInsideTheRockIsPlacedOnTheGroundOverIt) {
  // A level ledge top at z = 50 over an underside from (10, 50) back to (8, 45), a wall down
  // to (8, 20), a 42.3° slope to (30, 0) and a level floor.
  auto prof = test::make_profile({{0, 50}, {10, 50}, {8, 45}, {8, 20}, {30, 0}, {60, 0}});
  Scenario s = test::make_scenario(std::move(prof), test::make_material(5, 50, 0.3, 30),
                                   {test::make_block(1000)}, {9, 49}, 1);
  const double z_slope = 20.0 - 20.0 * (9.0 - 8.0) / 22.0;  // the slope's z at x = 9
  // At x = 9: the ledge's rock spans z 47.5 to 50, the air 19.09 to 47.5, the slope's rock below.
  s.sources = {Source{"in the ledge", {9, 49}, {0, 0}, 0},
               Source{"under the slope", {9, 10}, {0, 0}, 0},
               Source{"under the ledge", {9, 46}, {0, 0}, 0}};
  const auto r = run(s, 1);
  ASSERT_EQ(r.trajectories.size(), 3u);
  const auto& ledge = r.trajectories[0];
  EXPECT_EQ(ledge.start.z, 50.0);  // on the ledge top, level: at rest at once
  EXPECT_EQ(ledge.stop_reason, StopReason::friction);
  EXPECT_EQ(ledge.impacts, 0u);
  EXPECT_EQ(ledge.max_speed, 0.0);
  const auto& slope = r.trajectories[1];
  EXPECT_NEAR(slope.start.z, z_slope, 1e-12);  // onto the slope over it, not the ledge's top
  const auto& air = r.trajectories[2];
  EXPECT_EQ(air.start.z, 46.0);  // in the air: falls from where it is
  EXPECT_GE(air.impacts, 1u);
  EXPECT_NEAR(air.first_impact.x, 9.0, 1e-9);  // straight down onto the slope below
  EXPECT_NEAR(air.first_impact.z, z_slope, 1e-9);
}

// The largest speed of a trajectory is over all of it, rebounds included: a spinning block can
// leave an impact faster than it came (spin turned into translation), faster than at the end of
// the arc that follows. And a source on the ground keeps only its velocity along the ground:
// a block thrown into level ground at 30 m/s starts, and stays, at rest.
TEST(Trajectory, MaxSpeedCountsReboundsAndOnlyTheSpeedKeptAtTheStart) {
  auto prof = test::make_profile({{0, 100}, {200, 0}});  // 26.6°
  Scenario s = test::make_scenario(std::move(prof), test::make_material(5, 50, 0.3),
                                   {test::make_block(2650)}, {100, 50.1}, 20, 1);
  s.sources[0].omega = 60.0;  // rad/s, counter-clockwise: against the travel down the slope
  const auto r = run(s, 1, true);
  std::size_t k = 0;
  int faster_rebounds = 0;
  for (const auto& t : r.trajectories) {
    double v_max = 0;
    for (; k < r.impacts.size() && r.impacts[k].trajectory == t.trajectory; ++k) {
      const auto& d = r.impacts[k].detail;
      if (r.impacts[k].result != model::ImpactResult::rebound) continue;
      const double in = std::hypot(d.vt_in, d.vn_in), out = std::hypot(d.vt_out, d.vn_out);
      v_max = std::max({v_max, in, out});
      faster_rebounds += out > in;
    }
    EXPECT_GE(t.max_speed, v_max * (1 - 1e-12)) << t.trajectory;
  }
  EXPECT_GT(faster_rebounds, 0) << "the case must have rebounds faster than their impacts";

  auto level = test::make_profile({{0, 0}, {100, 0}});
  Scenario g = test::make_scenario(std::move(level), test::make_material(5, 50, 0.3),
                                   {test::make_block(1000)}, {50, 0}, 1);
  g.sources[0].velocity = {0, -30};
  const auto t = run(g, 1).trajectories.at(0);
  EXPECT_EQ(t.stop_reason, StopReason::friction);
  EXPECT_EQ(t.max_speed, 0.0);
  EXPECT_EQ(t.max_energy, 0.0);
}

// A concave vertex met while sliding is one impact and one event against max_impacts (it was
// counted twice: with max_impacts = 1 a block sliding into a V stopped with 0 impacts).
TEST(Trajectory, AConcaveVertexIsOneEventAgainstTheImpactLimit) {
  auto prof = test::make_profile({{0, 1}, {1, 0}, {2, 1}});  // a 45° V
  Scenario s = test::make_scenario(std::move(prof), test::make_material(5, 50, 0.3, 30),
                                   {test::make_block(100)}, {0.5, 0}, 1);
  for (long limit : {1L, 2L, 3L}) {
    s.settings.max_impacts = limit;
    const auto r = run(s, 1, true);
    const auto& t = r.trajectories.at(0);
    ASSERT_GE(r.impacts.size(), 1u);
    EXPECT_EQ(r.impacts.front().position.x, 1.0);  // slid into the vertex: the first impact
    // Every event here is an impact (the V's vertex, then its flanks), so the limit ends the
    // block after exactly that many.
    EXPECT_EQ(t.stop_reason, StopReason::impact_limit) << limit;
    EXPECT_EQ(t.impacts, static_cast<std::uint32_t>(limit)) << limit;
  }
  s.settings.max_impacts = 1;
  const auto t = run(s, 1).trajectories.at(0);
  EXPECT_EQ(t.impacts, 1u);
}

// A profile listed from the toe end (x rising uphill, the source at the top) is simulated the
// same, but its blocks travel against the vertex order, in which observation lines count first
// crossings: the sources on ground that falls towards the first vertex are named.
TEST(Scenario, SourcesAgainstTheMainDirectionAreNamed) {
  auto from_toe = test::make_profile({{0, 38}, {100, 40}, {150, 70}, {200, 100}});
  Scenario s = test::make_scenario(std::move(from_toe), test::make_material(5, 50, 0.3),
                                   {test::make_block(1000)}, {199, 101}, 1);
  s.sources.push_back(Source{"on the flat", {50, 39}, {0, 0}, 0});  // 1.1°: rises too
  s.sources.push_back(Source{"in the rock", {160, 10}, {0, 0}, 0});  // under the 31° part
  EXPECT_EQ(sources_against_main_direction(s), (std::vector<std::size_t>{0, 1, 2}));
  auto from_top = test::make_profile({{0, 100}, {50, 70}, {100, 40}, {200, 38}, {300, 38}});
  Scenario t = test::make_scenario(std::move(from_top), test::make_material(5, 50, 0.3),
                                   {test::make_block(1000)}, {1, 101}, 1);
  t.sources.push_back(Source{"level", {250, 38}, {0, 0}, 0});
  EXPECT_TRUE(sources_against_main_direction(t).empty());
  // Listed from the toe end, its blocks never cross a line in the vertex order.
  s.lines = {{"L", 140}};
  s.sources.resize(1);
  s.settings.throws = 20;
  const auto r = run(s, 1);
  EXPECT_TRUE(r.crossings.empty());
  for (const auto& t2 : r.trajectories) EXPECT_LT(t2.stop.x, 140) << t2.trajectory;
}

// What a line records of each crossing (model-2d.md §5; design-checks.md §1 step 1): the speed
// is the norm of the velocity, the translational energy ½ m v², the rotational ½ I ω² with
// I = 2/5 m R² of the block's own mass and radius. (Doubling either energy passed every test.)
TEST(Trajectory, CrossingEnergiesAreHalfMVSquaredAndHalfIOmegaSquared) {
  const Scenario s = slope_scenario();
  const auto r = run(s, 1);
  ASSERT_GT(r.crossings.size(), 100u);
  int spinning = 0;
  for (const auto& c : r.crossings) {
    const model::Block& b = s.blocks.at(c.block);
    EXPECT_EQ(c.mass, b.mass);
    EXPECT_NEAR(c.speed, std::hypot(c.velocity.x, c.velocity.z), 1e-12 * c.speed);
    EXPECT_NEAR(c.translational_energy, 0.5 * b.mass * c.speed * c.speed,
                1e-12 * c.translational_energy);
    const double inertia = 0.4 * b.mass * b.radius() * b.radius();
    EXPECT_NEAR(c.rotational_energy, 0.5 * inertia * c.omega * c.omega, 1e-12 * c.rotational_energy + 1e-300);
    spinning += c.omega != 0;
  }
  EXPECT_GT(spinning, 100);  // the rotational energies were really exercised
}

// model-2d.md §7 test 1 through the whole simulator: a block dropped from rest h above level
// ground meets it after √(2h/g) at √(2gh), straight down; the impact record says so.
TEST(Trajectory, FreeFallMeetsTheGroundAtRootTwoGH) {
  for (double h : {0.5, 12.5, 250.0}) {
    auto level = test::make_profile({{0, 0}, {100, 0}});
    Scenario s = test::make_scenario(std::move(level), test::make_material(15, 50, 0.5),
                                     {test::make_block(1000)}, {50, h + 0.0}, 1);
    const auto r = run(s, 1, true);
    ASSERT_FALSE(r.impacts.empty());
    const auto& first = r.impacts.front();
    const double v = std::sqrt(2 * 9.81 * h);
    EXPECT_NEAR(first.time, std::sqrt(2 * h / 9.81), 1e-12 * std::sqrt(2 * h / 9.81));  // 1e-12 relative (§7 test 1)
    EXPECT_NEAR(first.detail.vn_in, -v, 1e-12 * v);  // into the ground
    EXPECT_NEAR(first.detail.vt_in, 0.0, 1e-12 * v);
    EXPECT_NEAR(first.position.x, 50.0, 1e-12);
    EXPECT_NEAR(r.trajectories.at(0).max_speed, v, 1e-12 * v);
  }
}

TEST(Trajectory, FlyingOffTheProfileEndsAtTheBoundary) {
  auto prof = test::make_profile({{0, 100}, {10, 0}});
  Scenario s = test::make_scenario(std::move(prof), test::make_material(15, 50, 0.3),
                                   {test::make_block(1000)}, {0, 101}, 1);
  s.sources[0].velocity = {30, 0};  // clears the whole 10 m section
  const auto t = run(s, 1).trajectories.at(0);
  EXPECT_EQ(t.stop_reason, StopReason::boundary);
  EXPECT_NEAR(t.stop.x, 10.0, 1e-12);
  EXPECT_EQ(t.impacts, 0u);
}

// A vertical wall that ends the profile stands at its x_min or x_max, where a block flying at it
// would leave the section at the very time it meets the wall: it must hit the wall. (The
// contact at exactly that time was cut off, and the blocks passed through as `boundary`.)
TEST(Trajectory, AWallThatEndsTheProfileIsHitNotPassed) {
  struct Case {
    std::vector<Vec2> pts;
    Vec2 source, velocity;
    double wall_x;
  };
  const Case cases[] = {
      {{{0, 100}, {100, 0}, {110, 0}, {110, 50}}, {100, 2}, {20, 0}, 110.0},  // at the end
      {{{0, 50}, {0, 0}, {10, 0}, {110, -100}}, {5, 2}, {-20, 0}, 0.0},       // at the start
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.wall_x);
    Scenario s = test::make_scenario(test::make_profile(c.pts), test::make_material(15, 50, 0.65),
                                     {test::make_block(1000)}, c.source, 20);
    s.sources[0].velocity = c.velocity;
    for (const auto& t : run(s, 1).trajectories) {
      EXPECT_NE(t.stop_reason, StopReason::boundary) << t.trajectory;
      ASSERT_TRUE(t.has_first_impact);
      EXPECT_NEAR(t.first_impact.x, c.wall_x, 1e-9);
      // The wall is met after τ = distance / speed, at z = 2 − g τ²/2.
      const double tau = std::abs(c.wall_x - c.source.x) / std::abs(c.velocity.x);
      EXPECT_NEAR(t.first_impact.z, 2 - 0.5 * 9.81 * tau * tau, 1e-9);
    }
  }
}

// The time limit ends a flight in the air, at the arc's point at that time, whatever lies
// beyond: a landing (a vertical drop) or leaving the section (a throw back over the top). Both
// were reported as `numerical`, at the start point.
TEST(Trajectory, TheTimeLimitStopsAFlightInTheAir) {
  struct Case {
    Vec2 source, velocity;
  };
  for (const Case& c : {Case{{0.5, 200}, {0, 0}}, Case{{90, 1000}, {-10, 0}}}) {
    SCOPED_TRACE(c.source.x);
    Scenario s = test::make_scenario(test::make_profile({{0, 100}, {100, 0}, {150, 0}}),
                                     test::make_material(15, 50, 0.65), {test::make_block(1000)},
                                     c.source, 1);
    s.sources[0].velocity = c.velocity;
    s.settings.max_time = 2.0;
    const auto t = run(s, 1).trajectories.at(0);
    EXPECT_EQ(t.stop_reason, StopReason::time_limit);
    EXPECT_EQ(t.duration, 2.0);
    EXPECT_NEAR(t.stop.x, c.source.x + 2 * c.velocity.x, 1e-9);
    EXPECT_NEAR(t.stop.z, c.source.z - 0.5 * 9.81 * 4, 1e-9);
    EXPECT_EQ(t.impacts, 0u);
  }
}

TEST(Trajectory, PathFollowsTheParabolaAndEndsAtTheStop) {
  auto prof = test::make_profile({{0, 0}, {100, 0}});
  Scenario s = test::make_scenario(std::move(prof), test::make_material(5, 50, 0.3),
                                   {test::make_block(1000)}, {10, 5}, 1);
  s.sources[0].velocity = {2, 0};
  std::vector<Vec2> path;
  const auto t = simulate_with_path(s, path, 0.01);
  ASSERT_GT(path.size(), 10u);
  EXPECT_EQ(path.front().x, 10.0);
  EXPECT_EQ(path.back().x, t.stop.x);
  // Before the first impact every point is on z = 5 − g/2 ((x − 10)/2)².
  int before = 0;
  for (const Vec2& p : path) {
    const double tt = (p.x - 10) / 2;
    EXPECT_NEAR(p.z, 5 - 0.5 * 9.81 * tt * tt, 1e-9);
    ++before;
    if (p.x == t.first_impact.x && p.z == t.first_impact.z) break;
  }
  EXPECT_GE(before, 100);  // 1.01 s of flight at most 0.01 s apart
}

// A drop of 5 m that lasts an hour (g = 1e-6) or 3e150 s (g = 1e-300, max_time 1e308; both
// valid) is drawn with at most 1000 points on its parabola. The path asked for one point per
// 0.05 s: 63 000 points, or a count past INT_MAX whose conversion was undefined (it gave one
// point in a Release build, and bad_alloc for g = 1e-15).
TEST(Trajectory, APathDrawsALongFlightWithABoundedNumberOfPoints) {
  for (double g : {1e-6, 1e-300}) {
    SCOPED_TRACE(g);
    Scenario s = test::make_scenario(test::make_profile({{0, 0}, {100, 0}}),
                                     test::make_material(5, 50, 0.3), {test::make_block(1000)},
                                     {50, 5}, 1);
    s.settings.gravity = g;
    s.settings.max_time = 1e308;
    std::vector<Vec2> path;
    const auto t = simulate_with_path(s, path, 0.05);
    ASSERT_TRUE(t.has_first_impact);
    // The fall is one arc: the start, then 1000 points along it, the last at the landing; every
    // later arc (the slow rebounds) has at most 1000 too, with a point or two per event.
    ASSERT_GE(path.size(), 1001u);
    EXPECT_LE(path.size(), 1002u * (t.impacts + 2u));
    EXPECT_EQ(path.front().z, 5.0);
    for (std::size_t i = 1; i <= 1000; ++i) {
      EXPECT_EQ(path[i].x, 50.0);
      EXPECT_LT(path[i].z, path[i - 1].z);  // falling all the way
    }
    EXPECT_NEAR(path[1000].z, t.first_impact.z, 1e-9);
  }
}

// A flight whose numbers overflow (g = 1.7e308; the reader refuses more than 1e4 m/s², the core
// takes any Scenario) finds no landing: the block did not leave the profile, it was lost, and
// is said so (model-2d.md §4's `numerical`). It was `boundary`, with a stop z of -inf.
TEST(Trajectory, AFlightThatOverflowsEndsNumericalNotAtTheBoundary) {
  Scenario s = test::make_scenario(test::make_profile({{0, 0}, {100, 0}}),
                                   test::make_material(5, 50, 0.3), {test::make_block(1000)},
                                   {50, 5}, 1);
  s.sources[0].velocity = {1, 0};
  s.settings.gravity = 1.7e308;
  std::vector<Vec2> path;
  const auto t = simulate_with_path(s, path, 0.05);
  EXPECT_EQ(t.stop_reason, StopReason::numerical);
  // The same flight at a gravity a double holds lands on the floor below the source.
  s.settings.gravity = 1e4;
  const auto ok = simulate_with_path(s, path, 0.05);
  ASSERT_TRUE(ok.has_first_impact);
  EXPECT_NEAR(ok.first_impact.x, 50 + std::sqrt(2 * (5 - 0.5) / 1e4), 0.01);
  EXPECT_NE(ok.stop_reason, StopReason::numerical);
}

TEST(Trajectory, FloorContactIsTheFirstImpactPastTheToeOrTheToeWhenSlidingOnto) {
  // A 2 m, 20° ramp onto a floor: a block placed on the ramp slides (φ = 10°) onto the floor
  // through the concave toe at x = 2/tan 20°; one dropped from high lands on the floor.
  const double toe = 2 / std::tan(20 * M_PI / 180);
  auto prof = test::make_profile({{0, 2}, {toe, 0}, {toe + 100, 0}});
  Scenario s = test::make_scenario(prof, test::make_material(5, 50, 0.0, 10), {test::make_block(100)},
                                   {0.5, 0}, 1);
  s.settings.floor_segment = 1;
  s.settings.max_sliding_speed = 100;  // no launch: it must slide onto the floor
  const auto slid = run(s, 1).trajectories.at(0);
  ASSERT_TRUE(slid.has_floor_contact);
  EXPECT_NEAR(slid.floor_contact.x, toe, 1e-9);
  s.sources[0].position = {toe + 7, 30};
  const auto fell = run(s, 1).trajectories.at(0);
  ASSERT_TRUE(fell.has_floor_contact);
  EXPECT_NEAR(fell.floor_contact.x, toe + 7, 1e-12);  // vertical drop
  EXPECT_EQ(fell.floor_contact.x, fell.first_impact.x);
}

TEST(Trajectory, SubdividingSegmentsIntoCollinearPiecesChangesNothing) {
  // model-2d.md §2: a vertex turning by less than 1e-9 rad is not an event. The same quarry
  // face and floor, once with 4 vertices and once cut into 1 000 collinear pieces, must give
  // the same trajectories up to round-off (the contact is found on another piece of the
  // same line, so positions may differ in the last bits).
  const double dx = 20 / std::tan(65 * M_PI / 180);
  const std::vector<Vec2> base{{-5, 20}, {0, 20}, {dx, 0}, {dx + 80, 0}};
  std::vector<Vec2> fine;
  for (std::size_t i = 0; i + 1 < base.size(); ++i)
    for (int k = 0; k < 333; ++k)
      fine.push_back(base[i] + (k / 333.0) * (base[i + 1] - base[i]));
  fine.push_back(base.back());
  std::vector<model::Block> blocks{test::make_block(300, 1.0, 1.3), test::make_block(4000)};
  auto make = [&](const std::vector<Vec2>& pts) {
    Scenario s = test::make_scenario(test::make_profile(pts), test::make_material(5, 50, 0.65),
                                     blocks, {0.2, 20.5}, 200, 11);
    s.sources[0].velocity = {0.5, 0};
    s.lines = {{"toe + 5 m", dx + 5}};
    return s;
  };
  const auto a = run(make(base), 1), b = run(make(fine), 1);
  ASSERT_EQ(a.trajectories.size(), b.trajectories.size());
  int same = 0;
  for (std::size_t i = 0; i < a.trajectories.size(); ++i) {
    const auto &ta = a.trajectories[i], &tb = b.trajectories[i];
    same += ta.impacts == tb.impacts && std::abs(ta.stop.x - tb.stop.x) < 1e-6 &&
            std::abs(ta.max_jump_height - tb.max_jump_height) < 1e-6;
  }
  // The pieces' vertices are rounded off the line by ~1e-15 m, which can tip a decision met by
  // a hair (a stop criterion, a grazing contact); none did with this seed (400 of 400). Two in
  // 400 are allowed for that; a bug in the vertex handling would change far more.
  EXPECT_GE(same, 398) << same << " of 400 identical";
  RecordProperty("identical", same);
}

// model-2d.md §6: every trajectory draws from the stream of its global index, so the split of
// the work into chunks changes nothing. (The threads test above uses one chunk size for every
// run, and passed with every chunk restarting the streams or the source/block/throw keys at 0.)
// Reference: each trajectory simulated on its own by index, outside the runner.
TEST(Runner, ChunkSizeChangesNothingAndTrajectoryIIsTheStreamOfI) {
  const Scenario s = slope_scenario();
  const TrajectoryModel model(s);
  ObservationTally tally({}, s.profile, false);
  for (const std::uint32_t chunk : {1u, 7u, 199u, 1000u}) {
    const auto r = run(s, 2, false, chunk);
    ASSERT_EQ(r.trajectories.size(), 400u) << chunk;
    for (std::uint64_t i = 0; i < r.trajectories.size(); ++i) {
      const auto& a = r.trajectories[i];
      const TrajectorySummary b = simulate_trajectory(model, i, tally, nullptr);
      ASSERT_EQ(a.trajectory, i) << chunk;
      ASSERT_EQ(a.block, b.block) << chunk << " " << i;
      ASSERT_EQ(a.throw_index, b.throw_index) << chunk << " " << i;
      ASSERT_EQ(a.mass, s.blocks.at(b.block).mass) << chunk << " " << i;
      ASSERT_TRUE(same_bits(a.stop.x, b.stop.x) && same_bits(a.stop.z, b.stop.z)) << chunk << " " << i;
      ASSERT_TRUE(same_bits(a.duration, b.duration)) << chunk << " " << i;
      ASSERT_EQ(a.impacts, b.impacts) << chunk << " " << i;
    }
  }
}

// model-2d.md §4: the maximum jump height is the largest over the whole trajectory. A block
// released at rest H above level ground with no roughness bounces straight up and down, each
// rebound lower (kinetic energy never increases at an impact, §7 test 5): its highest point
// above the ground is where it started, H. (Keeping only the last arc's maximum passed every
// test.)
TEST(Trajectory, MaxJumpHeightIsTheHighestOfAllArcs) {
  for (const double h : {4.0, 12.5}) {
    auto level = test::make_profile({{0, 0}, {100, 0}});
    // E_n = 50 m³/s², k_n = 0.5 there: a 1 m³ block dropped from 4 m (E_d = R v² = 48.7)
    // rebounds at k_n ≈ 0.51, to about 1 m, well above the stop head 0.25 R = 0.155 m.
    Scenario s = test::make_scenario(std::move(level), test::make_material(50, 50, 0.0),
                                     {test::make_block(2650)}, {50, h}, 1);
    const auto r = run(s, 1, true);
    ASSERT_EQ(r.trajectories.size(), 1u);
    ASSERT_GE(r.impacts.size(), 3u) << h;  // it bounced, so the last arc is not the first
    EXPECT_NEAR(r.trajectories[0].max_jump_height, h, 1e-12 * h) << h;
  }
}

// model-2d.md §4: the maximum kinetic energy counts rotation, ½ m v² + ½ I ω² with
// I = 2/5 m R². A block released H above level ground with spin ω₀ gains m g H in free fall
// and keeps ω₀, and no impact adds energy (§7 test 5): the maximum is m g H + ½ I ω₀², at
// the first contact. (Leaving the rotational part out of the maximum passed every test.)
TEST(Trajectory, MaxEnergyIsTranslationalPlusRotational) {
  const double h = 5.0, omega0 = 12.0, mass = 2650.0;
  auto level = test::make_profile({{0, 0}, {100, 0}});
  Scenario s = test::make_scenario(std::move(level), test::make_material(15, 50, 0.3),
                                   {test::make_block(mass)}, {50, h}, 1);
  s.sources[0].omega = omega0;
  const auto r = run(s, 1);
  ASSERT_EQ(r.trajectories.size(), 1u);
  const double radius = std::cbrt(3 * mass / (4 * M_PI * 2650));  // 1 m³: 0.6204 m
  const double rotational = 0.5 * 0.4 * mass * radius * radius * omega0 * omega0;
  EXPECT_GT(rotational, 0.1 * mass * 9.81 * h);  // large enough to be seen
  EXPECT_NEAR(r.trajectories[0].max_energy, mass * 9.81 * h + rotational,
              1e-12 * (mass * 9.81 * h + rotational));
}

// model-2d.md §2 (thesis §3.2.2): a block launches when its speed *exceeds* the maximum
// sliding speed. One started sliding at exactly 5 m/s on level ground (φ = 30°) slides: it
// decelerates at g tan φ and stops by friction after v²/(2 g tan φ) = 2.207 m, with no impact.
// (Launching at a speed ≥ the maximum instead of > passed every test.)
TEST(Trajectory, SlidingAtExactlyTheMaximumSlidingSpeedDoesNotLaunch) {
  auto level = test::make_profile({{0, 0}, {100, 0}});
  Scenario s = test::make_scenario(std::move(level), test::make_material(15, 50, 0.3, 30),
                                   {test::make_block(1000)}, {50, 0}, 1);
  s.sources[0].velocity = {5.0, 0.0};
  const auto r = run(s, 1, true);
  ASSERT_EQ(r.trajectories.size(), 1u);
  const auto& t = r.trajectories[0];
  EXPECT_EQ(t.impacts, 0u);
  EXPECT_EQ(t.stop_reason, StopReason::friction);
  const double mu_g = 9.81 * std::tan(M_PI / 6);
  EXPECT_NEAR(t.stop.x, 50 + 25 / (2 * mu_g), 1e-9);
  EXPECT_NEAR(t.duration, 5 / mu_g, 1e-9);
}

// model-2d.md §2: from rest the block stays when tan β ≤ tan φ, equality included. On level,
// frictionless ground (φ = 0, which a scenario may give) that is 0 ≤ 0: a block placed there at
// rest stays where it is, stopped by friction at once. (A strict < passed every test; with it
// the block was "slid" zero distance to the segment's start vertex and left the profile there.)
TEST(Trajectory, ABlockAtRestOnFrictionlessLevelGroundStaysPut) {
  auto level = test::make_profile({{0, 0}, {100, 0}});
  Scenario s = test::make_scenario(std::move(level), test::make_material(15, 50, 0.3, 0.0),
                                   {test::make_block(1000)}, {50, 0}, 1);
  const auto r = run(s, 1);
  ASSERT_EQ(r.trajectories.size(), 1u);
  const auto& t = r.trajectories[0];
  EXPECT_EQ(t.stop_reason, StopReason::friction);
  EXPECT_EQ(t.impacts, 0u);
  EXPECT_EQ(t.duration, 0.0);
  EXPECT_EQ(t.stop.x, 50.0);
  EXPECT_EQ(t.stop.z, 0.0);
}

// model-2d.md §2: a rebound from a concave vertex into the neighbouring segment is a contact
// with it at once (t = 0, at the vertex), not a flight of rounding length. Blocks dropped
// straight onto the bottom of a V land at the vertex (as the end of the first flank); the
// rebounds the roughness turns into the other flank must meet it at the same instant, at the
// vertex (to the rounding of a segment's end point). Two Vs, a symmetric and a lopsided one.
// (Without the end vertex's neighbour in the departure, they met it a hair later.)
TEST(Trajectory, AReboundIntoTheOtherFlankOfAVIsAContactAtOnce) {
  for (const std::vector<Vec2>& v : {std::vector<Vec2>{{0, 10}, {10, 0}, {40, 10}},
                                     std::vector<Vec2>{{0, 10}, {10, 0}, {20, 10}}}) {
    Scenario s = test::make_scenario(test::make_profile(v), test::make_material(15, 50, 0.9, 30),
                                     {test::make_block(1000)}, {10, 15}, 2000);
    const auto r = run(s, 1, true);
    int at_once = 0, a_hair_later = 0;
    for (std::size_t i = 1; i < r.impacts.size(); ++i) {
      const auto &a = r.impacts[i - 1], &b = r.impacts[i];
      if (a.trajectory != b.trajectory || std::abs(a.position.x - 10.0) > 1e-12) continue;
      if (b.time == a.time && std::abs(b.position.x - 10.0) <= 1e-12 && b.segment != a.segment)
        ++at_once;
      else if (b.time - a.time < 1e-9)
        ++a_hair_later;
    }
    EXPECT_GT(at_once, 500) << v[2].x;  // common here: the test exercises the case
    EXPECT_EQ(a_hair_later, 0) << v[2].x;
  }
}

// A block that comes down a wall to its foot (an impact on the wall ending in a slide along it,
// downwards) departs from the ground beside the foot too, and enters it at once (model-2d.md §2,
// as a rebound at a vertex does). Departing from the wall alone, the ground's line was solved
// from coordinates: at this corner (a 35° slope into a rising wall) the foot lies a rounding
// above that line (3.6·10⁻¹⁵ m), the arc had no root on it, and 4 of these 3 000 blocks fell
// through the ground (stop reason numerical). Found by an audit against the spec.
TEST(Trajectory, ABlockSlidingDownAWallEntersTheGroundAtItsFoot) {
  const double t35 = std::tan(35 * M_PI / 180);
  Scenario s = test::make_scenario(test::make_profile({{0, 30 * t35}, {30, 0}, {30, 10}, {60, 10}}),
                                   test::make_material(2, 50, 1.5, 2), {test::make_block(2650, 0.7, 2.0)},
                                   {10, 20 * t35}, 3000, 1);
  s.sources[0].velocity = {4 * std::cos(35 * M_PI / 180), -4 * std::sin(35 * M_PI / 180)};
  const auto r = run(s, 1, true);
  int down_the_wall = 0;  // the case: a slide along the wall, downwards, from its foot
  for (const auto& im : r.impacts)
    if (im.segment == 1 && im.result == model::ImpactResult::sliding && im.position.z < 1e-9 &&
        std::abs(im.detail.slope_deg) > 89.0 && im.detail.vt_out * im.detail.slope_deg > 0.0)
      ++down_the_wall;
  // (vt_out is along the travel, whose descent angle is ±90° on the wall: down when they agree.)
  EXPECT_GE(down_the_wall, 3);  // rare: 4 of these 3 000 blocks, the 4 that fell through
  for (const auto& t : r.trajectories) {
    EXPECT_TRUE(t.stop_reason != StopReason::numerical) << "trajectory " << t.trajectory;
    EXPECT_GE(t.stop.z, -1e-9) << "trajectory " << t.trajectory;  // never below the ground
  }
}
