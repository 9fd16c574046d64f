// A scenario as the simulation sees it: parsed and validated by io, plain data here.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pierre/geometry/profile.hpp"
#include "pierre/model/block.hpp"
#include "pierre/model/material.hpp"
#include "pierre/model/model_defaults.hpp"
#include "pierre/model/roughness.hpp"
#include "pierre/sim/observation_line.hpp"

namespace pierre::sim {

struct Source {
  std::string name;
  geometry::Vec2 position;  // m; on or below the ground: placed on the ground (§3.2.2)
  geometry::Vec2 velocity;  // m/s
  double omega = 0;         // rad/s, counter-clockwise positive
};

struct SimulationSettings {
  std::uint64_t seed = 1;
  std::uint32_t throws = 1;  // per block and source
  double gravity = model::ModelDefaults::gravity;
  model::RoughnessModel roughness;
  double stop_head_factor = model::ModelDefaults::stop_head_factor;
  double max_sliding_speed = model::ModelDefaults::max_sliding_speed;
  double max_time = model::ModelDefaults::max_time;
  long max_impacts = model::ModelDefaults::max_impacts;
  // Segments from this index on are the floor (a quarry's, past the toe): each trajectory
  // records its first contact there (design-checks.md §2, ID). -1: not recorded.
  int floor_segment = -1;
};

struct Scenario {
  std::string name;
  geometry::Profile profile;
  std::vector<model::Material> materials;  // indexed by Segment::material
  std::vector<model::Block> blocks;        // one entry per physical block thrown
  std::vector<Source> sources;
  std::vector<ObservationLine> lines;
  SimulationSettings settings;

  // Trajectories: every block from every source, `throws` times each.
  std::uint64_t trajectory_count() const {
    return std::uint64_t{sources.size()} * blocks.size() * settings.throws;
  }
};

// What would make a hand-built scenario unsafe to simulate: no profile, a segment naming a
// material the list lacks, or more trajectories than a 64-bit index counts. (io's reader checks
// all of this and much more, with the file and line; this guards the core used as a library.)
std::optional<std::string> scenario_fault(const Scenario& scenario);

// Which source, block and throw a global trajectory index stands for: source-major, then block,
// then throw.
struct TrajectoryKey {
  std::uint32_t source, block, throw_index;
};
inline TrajectoryKey trajectory_key(const Scenario& s, std::uint64_t index) {
  const std::uint64_t throws = s.settings.throws, nb = s.blocks.size();
  return {static_cast<std::uint32_t>(index / (throws * nb)),
          static_cast<std::uint32_t>((index / throws) % nb),
          static_cast<std::uint32_t>(index % throws)};
}

}  // namespace pierre::sim
