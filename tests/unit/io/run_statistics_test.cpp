// design::run_statistics (tested here: the io test program links the design layer): counts,
// not-reached, NaN when a line is never crossed (the percentiles are stats::, tested there).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

#include "pierre/design/run_statistics.hpp"
#include "pierre/io/result_writer.hpp"

namespace {

using namespace pierre;

TEST(RunStatistics, LinesRunoutAndStops) {
  design::RunSamples s(2, -1);  // a profile running towards decreasing x
  for (int i = 0; i < 4; ++i) {
    sim::TrajectorySummary t;
    t.trajectory = static_cast<std::uint64_t>(i);
    t.start = {100, 0};
    t.stop = {100.0 - 10.0 * (i + 1), 0};
    t.stop_reason = i == 3 ? sim::StopReason::friction : sim::StopReason::energy;
    s.add(t);
    if (i < 3) {
      sim::Crossing c;
      c.trajectory = t.trajectory;
      c.line = 0;
      c.direction = -1;
      c.speed = 2.0 * (i + 1);
      c.height = 1.0;
      c.translational_energy = 1000.0 * (i + 1);
      s.add(c);
      c.direction = +1;  // against the main direction: ignored
      c.speed = 100;
      s.add(c);
    }
  }
  const auto st = design::run_statistics({{"A", 50}, {"B", 10}}, s);
  EXPECT_EQ(st.trajectories, 4u);
  ASSERT_EQ(st.lines.size(), 2u);
  EXPECT_EQ(st.lines[0].name, "A");
  EXPECT_EQ(st.lines[0].count, 3u);
  EXPECT_EQ(st.lines[0].not_reached, 1u);
  EXPECT_DOUBLE_EQ(st.lines[0].speed.mean, 4.0);
  EXPECT_DOUBLE_EQ(st.lines[0].speed.p50, 4.0);
  EXPECT_DOUBLE_EQ(st.lines[0].speed.p95, 5.8);  // 4 + 0.9 × 2
  EXPECT_DOUBLE_EQ(st.lines[0].speed.max, 6.0);
  EXPECT_DOUBLE_EQ(st.lines[0].translational_energy.max, 3000.0);
  EXPECT_EQ(st.lines[1].count, 0u);
  EXPECT_EQ(st.lines[1].not_reached, 4u);
  EXPECT_TRUE(std::isnan(st.lines[1].speed.mean));
  EXPECT_DOUBLE_EQ(st.runout.p50, 25.0);
  EXPECT_DOUBLE_EQ(st.runout.max, 40.0);
  EXPECT_DOUBLE_EQ(st.runout.p95, 38.5);  // h = 2.85 over {10, 20, 30, 40}
  ASSERT_EQ(st.stop_reasons.size(), 6u);
  EXPECT_EQ(st.stop_reasons[0].reason, sim::StopReason::energy);
  EXPECT_EQ(st.stop_reasons[0].count, 3u);
  EXPECT_EQ(st.stop_reasons[1].count, 1u);
}

// A block still moving where its trajectory ended (off the profile onwards, cut off by a limit)
// has a runout that is only a lower bound: so is every type-7 percentile that reaches or
// interpolates towards the shortest such runout, i.e. every one above the largest runout below
// it. Blocks at rest (energy, friction), and blocks that left at the upper end, bound nothing.
TEST(RunStatistics, RunoutPercentilesReachingAMovingBlockAreLowerBounds) {
  auto stats_of = [](std::initializer_list<std::pair<double, sim::StopReason>> runs) {
    design::RunSamples s(0, 1);
    for (auto [runout, why] : runs) {
      sim::TrajectorySummary t;
      t.start = {0, 50};
      t.stop = {runout, 0};  // a negative runout: thrown back, off the upper end
      t.stop_reason = why;
      s.add(t);
    }
    return design::run_statistics({}, s).runout;
  };
  using R = sim::StopReason;
  // 10, 20, 30 at rest; 40 left the profile: P50 = 25 is a runout; P95 = 30 + 0.85·(40 − 30)
  // = 38.5 leans on the 40 and is a lower bound, as the max is.
  auto r = stats_of({{10, R::energy}, {20, R::friction}, {30, R::energy}, {40, R::boundary}});
  EXPECT_DOUBLE_EQ(r.lower_bound_from, 30.0);
  EXPECT_DOUBLE_EQ(r.p95, 38.5);
  EXPECT_FALSE(r.is_lower_bound(r.p50));
  EXPECT_TRUE(r.is_lower_bound(r.p95));
  EXPECT_TRUE(r.is_lower_bound(r.max));
  EXPECT_FALSE(r.is_lower_bound(30.0));  // a percentile that lands on the 30 m block is a runout
  // One cut off by the time limit at 22 m: P50 = 22 + 0.5·(30 − 22) = 26 and above lean on it;
  // 10, below it, is a runout.
  r = stats_of({{10, R::energy}, {22, R::time_limit}, {30, R::energy}, {40, R::friction}});
  EXPECT_DOUBLE_EQ(r.lower_bound_from, 10.0);
  EXPECT_DOUBLE_EQ(r.p50, 26.0);
  EXPECT_TRUE(r.is_lower_bound(r.p50));
  EXPECT_TRUE(r.is_lower_bound(r.max));
  EXPECT_FALSE(r.is_lower_bound(10.0));
  // A block thrown back off the upper end (1 m behind its release) bounds nothing downslope.
  r = stats_of({{10, R::energy}, {-1, R::boundary}, {30, R::energy}, {40, R::friction}});
  EXPECT_TRUE(std::isinf(r.lower_bound_from));
  EXPECT_FALSE(r.is_lower_bound(r.max));
  // Every block at rest: nothing is a lower bound.
  r = stats_of({{10, R::energy}, {20, R::friction}});
  EXPECT_TRUE(std::isinf(r.lower_bound_from));
  EXPECT_FALSE(r.is_lower_bound(r.max));
}

// model-2d.md §5: asked for all crossings, the statistics count every crossing in either
// direction; the first ones in the main direction stay the barrier design's sample, and
// "not reached" still counts trajectories without one.
TEST(RunStatistics, EveryCrossingWhenAskedFor) {
  for (const bool every : {false, true}) {
    SCOPED_TRACE(every);
    design::RunSamples s(1, +1, every);
    for (std::uint64_t i = 0; i < 3; ++i) {
      sim::TrajectorySummary t;
      t.trajectory = i;
      s.add(t);
    }
    auto crossing = [&](std::uint64_t traj, int dir, double speed) {
      sim::Crossing c;
      c.trajectory = traj;
      c.line = 0;
      c.direction = dir;
      c.speed = speed;
      s.add(c);
    };
    crossing(0, +1, 10);  // trajectory 0: down, back up, down again
    crossing(0, -1, 2);
    crossing(0, +1, 3);
    crossing(1, +1, 20);
    crossing(2, -1, 1);  // trajectory 2 only ever crosses against the main direction
    const auto st = design::run_statistics({{"A", 5}}, s);
    EXPECT_EQ(st.every_crossing, every);
    EXPECT_EQ(st.lines[0].not_reached, 1u);  // trajectory 2 either way
    ASSERT_EQ(s.lines()[0].speed, (std::vector<double>{10, 20}));
    if (every) {
      EXPECT_EQ(st.lines[0].count, 5u);
      EXPECT_DOUBLE_EQ(st.lines[0].speed.mean, 36.0 / 5);
      EXPECT_DOUBLE_EQ(st.lines[0].speed.p50, 3.0);
    } else {
      EXPECT_EQ(st.lines[0].count, 2u);
      EXPECT_DOUBLE_EQ(st.lines[0].speed.mean, 15.0);
      EXPECT_TRUE(s.every().empty());
    }
  }
}

// The mean of 10^6 crossings is summed with compensation: one large value and a million small
// ones that a plain running sum would drop one by one (1e-16 is under half an ulp of 1).
TEST(RunStatistics, TheMeanKeepsValuesARunningSumWouldDrop) {
  std::vector<double> v{1.0};
  v.insert(v.end(), 1'000'000, 1e-16);
  const design::QuantityStatistics q = design::quantity_statistics(v);
  const double exact = (1.0 + 1e-10) / 1'000'001.0;
  EXPECT_NEAR(q.mean, exact, 1e-15 * exact);  // a plain sum gives 1 / 1000001: 1e-10 off
  EXPECT_EQ(q.max, 1.0);
  EXPECT_EQ(q.p50, 1e-16);
  EXPECT_EQ(q.count, 1'000'001u);
}

// What the stop reasons mean for the results, in words the console and the report share: none
// when every block came to rest; a sentence for each limit that cut blocks off and for blocks
// that left the profile (their runouts make the percentiles lower bounds), singular for one.
TEST(RunStatistics, StopReasonNotesSayWhatTheCountsMean) {
  design::RunStatistics s;
  auto set = [&](std::array<std::uint64_t, 6> n) {
    s.stop_reasons.clear();
    for (std::size_t k = 0; k < n.size(); ++k)
      s.stop_reasons.push_back({static_cast<sim::StopReason>(k), n[k]});
  };
  set({90, 10, 0, 0, 0, 0});
  EXPECT_TRUE(design::stop_reason_notes(s).empty());
  set({90, 10, 7, 0, 1, 2});
  const auto notes = design::stop_reason_notes(s);
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_EQ(notes[0].rfind("7 trajectories left the profile; their runout is where they left it, "
                           "so the runout percentiles are lower bounds",
                           0),
            0u)
      << notes[0];
  EXPECT_EQ(notes[1], "1 trajectory was cut off by simulation.max_impacts (a block bouncing in "
                      "place, e.g. on a very small roughness), not at rest; its stop point and "
                      "runout are where it was cut off.");
  EXPECT_EQ(notes[2].rfind("2 trajectories were cut off by a numerical failure", 0), 0u) << notes[2];
  EXPECT_NE(notes[2].find("their stop points and runouts are where they were cut off."),
            std::string::npos);
  set({0, 0, 1, 3, 0, 0});
  const auto more = design::stop_reason_notes(s);
  ASSERT_EQ(more.size(), 2u);
  EXPECT_EQ(more[0].rfind("1 trajectory left the profile; its runout is where it left it", 0), 0u);
  EXPECT_EQ(more[1].rfind("3 trajectories were cut off by simulation.max_time, not at rest", 0), 0u)
      << more[1];
}

// Energy stops on ground steeper than its friction angle are counted with the steepest such
// ground (atan of the largest tan β: 1 → 45°, √3 → 60°), and said in one note.
TEST(RunStatistics, EnergyStopsOnSteepGroundAreCountedAndNoted) {
  design::RunSamples s(0, 1);
  double x = 10;
  for (const float tan_beta : {0.0f, 1.0f, 1.7320508f, 0.0f}) {
    sim::TrajectorySummary t;
    t.stop_reason = sim::StopReason::energy;
    t.steep_stop_tan = tan_beta;
    t.stop = {x *= 2, 0};  // 20, 40, 80, 160 m: the steep ones at 40 and 80 m
    s.add(t);
  }
  const auto st = design::run_statistics({}, s);
  EXPECT_EQ(st.energy_stops_on_steep_ground, 2u);
  EXPECT_NEAR(st.steepest_energy_stop_deg, 60.0, 1e-5);
  EXPECT_EQ(st.energy_stop_steep_x_min, 40.0);
  EXPECT_EQ(st.energy_stop_steep_x_max, 80.0);
  const auto notes = design::stop_reason_notes(st);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("2 blocks were stopped by the energy criterion (Eq 3.13) on ground "
                           "steeper than its friction angle (up to 60.0°, at x = 40.0 to 80.0 m)",
                           0),
            0u)
      << notes[0];
  design::RunStatistics none = st;
  none.energy_stops_on_steep_ground = 0;
  EXPECT_TRUE(design::stop_reason_notes(none).empty());
}

// A quarry scenario's sections run into one RunSamples, each on its own profile: where the steep
// energy stops fell is said per section (an x range over two profiles meant nothing), and a
// section without any is left out.
TEST(RunStatistics, SteepEnergyStopsAreLocatedPerQuarrySection) {
  design::RunSamples s(0, 1);
  auto stop = [&s](double x, float tan_beta) {
    sim::TrajectorySummary t;
    t.stop_reason = sim::StopReason::energy;
    t.steep_stop_tan = tan_beta;
    t.stop = {x, 0};
    s.add(t);
  };
  s.begin_section("North", 1);
  stop(16.1, 1.0f);
  stop(16.3, 1.0f);
  stop(40.0, 0.0f);  // not steep: no place
  s.begin_section("Middle", 1);
  stop(12.0, 0.0f);
  s.begin_section("South", -1);
  stop(10.6, 2.0f);
  stop(10.62, 2.0f);  // 10.6 as printed: one place, not "10.6 to 10.6 m"
  {  // South runs towards −x: a block leaving at its far end (x = 5) is still moving onwards
    sim::TrajectorySummary t;
    t.stop_reason = sim::StopReason::boundary;
    t.start = {20, 0};
    t.stop = {5, 0};
    s.add(t);
  }
  const auto st = design::run_statistics({}, s);
  EXPECT_EQ(st.energy_stops_on_steep_ground, 4u);
  // Its runout, 15 m, bounds the runouts from below: the largest under it, 12 m, on.
  EXPECT_EQ(st.runout.lower_bound_from, 12.0);
  ASSERT_EQ(st.energy_stops_on_steep_ground_by_section.size(), 2u);
  EXPECT_EQ(st.energy_stops_on_steep_ground_by_section[0].section, "North");
  EXPECT_EQ(st.energy_stops_on_steep_ground_by_section[0].count, 2u);
  EXPECT_EQ(st.energy_stops_on_steep_ground_by_section[0].x_min, 16.1);
  EXPECT_EQ(st.energy_stops_on_steep_ground_by_section[0].x_max, 16.3);
  EXPECT_EQ(st.energy_stops_on_steep_ground_by_section[1].section, "South");
  const auto notes = design::stop_reason_notes(st);  // the steep stops' and the one that left
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(std::count_if(notes.begin(), notes.end(), [](const std::string& n) {
              return n.find("(up to 63.4°, 2 in section North at x = 16.1 to 16.3 m; 2 in section "
                            "South at x = 10.6 m)") != std::string::npos;
            }),
            1)
      << notes[0] << "\n" << notes[1];
  // summary.json gives them per section, and no pooled range.
  const auto j = nlohmann::json::parse(io::summary_json(io::RunInfo{}, st));
  EXPECT_TRUE(j["energy_stops_on_steep_ground_x_m"].is_null());
  ASSERT_EQ(j["energy_stops_on_steep_ground_by_section"].size(), 2u);
  EXPECT_EQ(j["energy_stops_on_steep_ground_by_section"][1]["section"], "South");
  EXPECT_EQ(j["energy_stops_on_steep_ground_by_section"][1]["x_m"]["min"], 10.6);
}

// Energy stops at the first impact (one impact, stopped by energy) are counted, and noted from
// a twentieth of the trajectories on: 2 of 40 is, 1 of 40 is not. A stop after two impacts, or
// a friction stop after one, is not one.
// The note says the speeds they struck at, and why such a stop comes about: a gentle drop
// (a source a little above the ground), or a hard fall whose impact takes nearly all the
// energy (user review: the note blamed a slow drop on blocks that struck at 115 m/s).
TEST(RunStatistics, StopsAtTheFirstImpactAreCountedAndNoted) {
  auto run = [](int dead, double speed) {
    design::RunSamples s(0, 1);
    for (int i = 0; i < 40; ++i) {
      sim::TrajectorySummary t;
      t.stop_reason = i == 30 ? sim::StopReason::friction : sim::StopReason::energy;
      t.impacts = i < dead || i == 30 ? 1 : 2;
      t.max_speed = i < dead ? speed + i : 50.0;  // the others' speeds count for nothing
      s.add(t);
    }
    return design::run_statistics({}, s);
  };
  const auto two = run(2, 2.5);
  EXPECT_EQ(two.energy_stops_at_first_impact, 2u);
  EXPECT_EQ(two.first_impact_stop_speed_min, 2.5);
  EXPECT_EQ(two.first_impact_stop_speed_max, 3.5);
  const auto notes = design::stop_reason_notes(two);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("2 of 40 blocks (5.0 %) came to rest at their first impact (their largest "
                           "speed, that of the impact unless thrown faster: 2.5 to 3.5 m/s): the "
                           "energy criterion (Eq 3.13) stopped them there. A source a little above "
                           "the ground drops its blocks so:",
                           0),
            0u)
      << notes[0];
  EXPECT_NE(notes[0].find("put it on the ground (z at or below it)"), std::string::npos);
  EXPECT_EQ(notes[0].find("A hard impact"), std::string::npos);
  const auto hard = design::stop_reason_notes(run(3, 115.0));
  ASSERT_EQ(hard.size(), 1u);
  EXPECT_NE(hard[0].find("thrown faster: 115.0 to 117.0 m/s): the energy criterion"), std::string::npos)
      << hard[0];
  EXPECT_NE(hard[0].find("A hard impact does it too: the restitution factors fall as the impact's "
                         "energy rises (Eq 6.4), so a block that falls far onto the ground keeps "
                         "almost nothing; check the source's height (z) against the profile's."),
            std::string::npos)
      << hard[0];
  EXPECT_EQ(hard[0].find("a little above"), std::string::npos) << hard[0];
  const auto both = design::stop_reason_notes(run(2, 9.5));  // 9.5 and 10.5 m/s: either cause
  ASSERT_EQ(both.size(), 1u);
  EXPECT_NE(both[0].find("a little above the ground"), std::string::npos) << both[0];
  EXPECT_NE(both[0].find("A hard impact does it too"), std::string::npos) << both[0];
  const auto one = run(1, 2.5);
  EXPECT_EQ(one.energy_stops_at_first_impact, 1u);
  EXPECT_TRUE(design::stop_reason_notes(one).empty());
}

}  // namespace
