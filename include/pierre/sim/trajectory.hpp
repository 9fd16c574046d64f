// One trajectory: flight found exactly, sliding by closed-form events, impacts by the impact
// law (model-2d.md §2–§4). Pure: it reads prepared constants and writes plain results.
#pragma once

#include <vector>

#include "pierre/model/impact_law.hpp"
#include "pierre/sim/observation_line.hpp"
#include "pierre/sim/random_stream.hpp"
#include "pierre/sim/results.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::sim {

// Everything a trajectory needs, prepared once per run and shared read-only by all threads.
class TrajectoryModel {
 public:
  explicit TrajectoryModel(const Scenario& scenario);

  const Scenario& scenario() const { return *scenario_; }
  const model::ImpactLaw& law() const { return law_; }
  const model::SurfaceConstants& surface(int material) const { return surfaces_[material]; }
  const model::BlockConstants& block(std::size_t i) const { return blocks_[i]; }
  const PhiloxKey& random_key() const { return key_; }

  // Where a source's blocks start (§3.2.2), the same for every trajectory from it: in flight
  // above the ground, on the ground at (x, z) on `segment`, or outside the profile.
  struct SourceStart {
    enum class Kind { flight, ground, outside } kind;
    double z;     // ground: the elevation the block is placed at
    int segment;  // ground: the segment it is placed on; flight: the ground below; outside: -1
  };
  const SourceStart& source_start(std::size_t source) const { return starts_[source]; }

 private:
  const Scenario* scenario_;
  model::ImpactLaw law_;
  PhiloxKey key_;  // the seed's round keys, shared by every trajectory's stream
  std::vector<model::SurfaceConstants> surfaces_;
  std::vector<model::BlockConstants> blocks_;
  std::vector<SourceStart> starts_;
};

// The sources whose ground falls towards the profile's first vertex: their blocks travel against
// the main direction (the vertex order), and observation lines count first crossings in the
// main direction only. Mostly a profile listed from the toe end (model-2d.md §1: from the
// source end). The ground is the segment TrajectoryModel starts the source's blocks on (or
// above).
std::vector<std::size_t> sources_against_main_direction(const Scenario& s);

// Runs trajectory `index` of the scenario. Crossings go to the tally (which appends to its
// output), impact records to `impacts` when it is not null, and the path of the block centre
// to `path` when it is not null (the start, every impact and sliding event, and points along
// each flight arc at most `path_step` seconds apart, and at most 1000 per arc: for drawing, not
// for analysis).
TrajectorySummary simulate_trajectory(const TrajectoryModel& model, std::uint64_t index,
                                      ObservationTally& tally,
                                      std::vector<ImpactRecord>* impacts,
                                      std::vector<geometry::Vec2>* path = nullptr,
                                      double path_step = 0.05);

// The same for the runner's loop, which knows the index's key (it steps the key along instead of
// dividing the index for every trajectory) and writes the summary in place into `out`.
void simulate_trajectory(const TrajectoryModel& model, std::uint64_t index, TrajectoryKey key,
                         ObservationTally& tally, std::vector<ImpactRecord>* impacts,
                         TrajectorySummary& out);

}  // namespace pierre::sim
