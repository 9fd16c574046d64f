// What a run produces, as plain data (model-2d.md §4, §5; the thesis's DIS, OBS and TR files).
#pragma once

#include <cstdint>
#include <string_view>

#include "pierre/geometry/vec2.hpp"
#include "pierre/model/impact_law.hpp"

namespace pierre::sim {

enum class StopReason : std::uint8_t {
  energy,        // energy head below H_stop after an impact (Eq 3.13)
  friction,      // at rest on a segment no steeper than the friction angle
  boundary,      // left the profile
  time_limit,
  impact_limit,
  numerical,     // a non-finite value or a lost contact: counted and reported, never dropped
};

std::string_view to_string(StopReason r);

// Fields ordered so that no padding falls between them (136 bytes, not 152): a million-trajectory
// run keeps a million of these, and fresh memory costs the kernel a page fault per 4 KiB.
struct TrajectorySummary {
  std::uint64_t trajectory = 0;  // global index: fixes the random stream
  std::uint32_t source = 0;
  std::uint32_t block = 0;       // index into the scenario's block list
  std::uint32_t throw_index = 0;
  std::uint32_t impacts = 0;
  double mass = 0;               // kg
  geometry::Vec2 start;          // m
  geometry::Vec2 stop;           // m
  double duration = 0;           // s
  geometry::Vec2 first_impact;   // m
  geometry::Vec2 floor_contact;    // m: first impact there, or where it slid onto it
  double max_jump_height = 0;    // m, above the ground directly below
  double max_speed = 0;          // m/s, translational
  double max_energy = 0;         // J, translational + rotational
  StopReason stop_reason = StopReason::numerical;
  bool has_first_impact = false;
  bool has_floor_contact = false;  // reached SimulationSettings::floor_segment or beyond
  // An energy stop (Eq 3.13) on ground steeper than its friction angle that falls in the travel
  // direction (or a vertical face): tan β of that ground (+inf for a vertical face), else 0. The
  // model stops the block there whatever the slope (model-2d.md §3 step 8), where a block at
  // rest would slide on. Not on a counter-slope, where it would slide back, short of where it
  // stopped (a ditch's far side). (A float: it fits the padding.)
  float steep_stop_tan = 0;
  double runout() const;         // horizontal distance start → stop, m
};

struct Crossing {
  std::uint64_t trajectory = 0;
  std::uint32_t line = 0;   // index of the observation line
  std::uint32_t block = 0;
  double mass = 0;          // kg
  double time = 0;          // s from release
  int direction = 1;        // +1 towards increasing x
  geometry::Vec2 velocity;  // m/s
  double speed = 0;         // m/s
  double omega = 0;         // rad/s
  double translational_energy = 0;  // J
  double rotational_energy = 0;     // J
  double height = 0;        // m: block centre above the ground directly below, at the line
  bool sliding = false;
};

struct ImpactRecord {
  std::uint64_t trajectory = 0;
  std::uint32_t index = 0;  // impact number within the trajectory, from 0
  double time = 0;          // s
  geometry::Vec2 position;  // m
  std::uint32_t segment = 0;
  model::ImpactResult result = model::ImpactResult::rebound;
  model::ImpactDetail detail;
};

}  // namespace pierre::sim
