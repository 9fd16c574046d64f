// The runner's contract with its sink: chunks in trajectory order, the count announced first,
// and an early stop on request (Ctrl-C at the command line) that delivers a prefix of the run.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include "pierre/sim/runner.hpp"
#include "support/builders.hpp"

using namespace pierre;
using namespace pierre::sim;

namespace {

Scenario slope(std::uint32_t throws) {
  const double t35 = std::tan(35 * M_PI / 180);
  auto prof = test::make_profile({{0, 100}, {100, 100 - 100 * t35}, {300, 100 - 100 * t35}});
  return test::make_scenario(std::move(prof), test::make_material(15, 50, 0.7),
                             {test::make_block(500, 1.0, 1.5)}, {0, 101}, throws, 7);
}

// Records what it is given; optionally sets `stop` when it receives chunk number `stop_at`.
struct RecordingSink : ResultSink {
  std::uint64_t expected = 0;
  std::vector<std::uint64_t> firsts;
  std::vector<TrajectorySummary> trajectories;
  std::atomic<bool>* stop = nullptr;
  std::size_t stop_at = 0;
  void expect(std::uint64_t n) override { expected = n; }
  void consume(ChunkResult&& c) override {
    firsts.push_back(c.first);
    trajectories.insert(trajectories.end(), c.trajectories.begin(), c.trajectories.end());
    if (stop && firsts.size() == stop_at) stop->store(true);
  }
};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Tags each chunk in prepare with the chunk's first trajectory and how many it holds.
struct Tag : PreparedChunk {
  std::uint64_t first = 0;
  std::size_t count = 0;
};
struct PreparingSink : ResultSink {
  mutable std::atomic<int> prepared{0};
  std::vector<std::uint64_t> firsts;
  bool every_chunk_tagged = true;
  void prepare(ChunkResult& c) const override {
    auto tag = std::make_unique<Tag>();
    tag->first = c.first;
    tag->count = c.trajectories.size();
    c.prepared = std::move(tag);
    ++prepared;
  }
  void consume(ChunkResult&& c) override {
    const auto* tag = dynamic_cast<const Tag*>(c.prepared.get());
    every_chunk_tagged = every_chunk_tagged && tag && tag->first == c.first &&
                         tag->count == c.trajectories.size();
    firsts.push_back(c.first);
  }
};

}  // namespace

TEST(Runner, AnnouncesTheTrajectoryCountAndDeliversChunksInOrder) {
  const Scenario s = slope(300);
  RecordingSink sink;
  RunOptions o;
  o.threads = 2;
  o.chunk_size = 7;
  const RunReport rep = run_simulation(s, o, sink);
  EXPECT_FALSE(rep.interrupted);
  EXPECT_EQ(sink.expected, 300u);
  ASSERT_EQ(sink.trajectories.size(), 300u);
  for (std::size_t k = 0; k < sink.firsts.size(); ++k) EXPECT_EQ(sink.firsts[k], 7 * k);
  // The collector keeps them all, in one allocation of the announced size.
  ResultCollector c;
  run_simulation(s, o, c);
  ASSERT_EQ(c.trajectories.size(), 300u);
  EXPECT_EQ(c.trajectories.capacity(), 300u);
}

// The sink's prepare runs once per chunk on the worker (the CSV text is made there), and each
// chunk reaches consume carrying what prepare made of that same chunk.
TEST(Runner, EachChunkArrivesWithWhatPrepareMadeOfIt) {
  const Scenario s = slope(300);
  for (unsigned threads : {1u, 2u}) {
    PreparingSink sink;
    RunOptions o;
    o.threads = threads;
    o.chunk_size = 7;
    run_simulation(s, o, sink);
    EXPECT_EQ(sink.prepared.load(), 43) << threads;  // ceil(300 / 7)
    ASSERT_EQ(sink.firsts.size(), 43u) << threads;
    EXPECT_TRUE(sink.every_chunk_tagged) << threads;
  }
}

TEST(Runner, AStopRequestedBeforeTheRunDeliversNothing) {
  const Scenario s = slope(100);
  std::atomic<bool> stop{true};
  RecordingSink sink;
  RunOptions o;
  o.threads = 2;
  o.stop = &stop;
  const RunReport rep = run_simulation(s, o, sink);
  EXPECT_TRUE(rep.interrupted);
  EXPECT_TRUE(sink.firsts.empty());
}

TEST(Runner, AStopDuringTheRunEndsItEarlyWithAPrefixOfTheFullRun) {
  const Scenario s = slope(2000);
  RunOptions o;
  o.chunk_size = 10;
  RecordingSink full;
  o.threads = 1;
  run_simulation(s, o, full);
  ASSERT_EQ(full.trajectories.size(), 2000u);
  for (unsigned threads : {1u, 2u}) {
    std::atomic<bool> stop{false};
    RecordingSink part;
    part.stop = &stop;
    part.stop_at = 3;
    o.threads = threads;
    o.stop = &stop;
    const RunReport rep = run_simulation(s, o, part);
    EXPECT_TRUE(rep.interrupted) << threads;
    // The chunks under way when the stop came are finished and delivered, no more: at most
    // the window of 4 chunks per thread beyond the third.
    ASSERT_GE(part.firsts.size(), 3u);
    EXPECT_LE(part.firsts.size(), 3u + 4 * threads);
    for (std::size_t k = 0; k < part.firsts.size(); ++k) EXPECT_EQ(part.firsts[k], 10 * k);
    for (std::size_t i = 0; i < part.trajectories.size(); ++i)
      EXPECT_TRUE(same_bits(part.trajectories[i].stop.x, full.trajectories[i].stop.x)) << i;
  }
}

// The core used as a library: a hand-built scenario that would read out of range is refused
// with the reason, and nothing is run or delivered.
TEST(Runner, RefusesAScenarioItCannotSimulateSafely) {
  auto refused = [](const Scenario& s, const std::string& why) {
    RecordingSink sink;
    const RunReport rep = run_simulation(s, RunOptions{}, sink);
    ASSERT_TRUE(rep.error);
    EXPECT_NE(rep.error->find(why), std::string::npos) << *rep.error;
    EXPECT_EQ(rep.trajectories, 0u);
    EXPECT_TRUE(sink.firsts.empty());
    EXPECT_EQ(sink.expected, 0u);
  };
  Scenario no_profile = slope(3);
  no_profile.profile = geometry::Profile{};
  refused(no_profile, "the profile has no segment");

  Scenario no_material = slope(3);
  no_material.materials.clear();
  refused(no_material, "segment 0 names material 0, but 0 material(s) are given");

  Scenario too_many = slope(std::numeric_limits<std::uint32_t>::max());
  too_many.blocks.resize(1u << 16, too_many.blocks.front());  // 2^33 (source, block) pairs
  too_many.sources.resize(1u << 17, too_many.sources.front());
  refused(too_many, "overflows");

  RecordingSink sink;  // and the scenario it was made from runs
  const RunReport ok = run_simulation(slope(3), RunOptions{}, sink);
  EXPECT_FALSE(ok.error);
  EXPECT_EQ(sink.trajectories.size(), 3u);
}
