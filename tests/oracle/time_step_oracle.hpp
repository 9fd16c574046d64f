// An independent, deliberately plain reference for whole trajectories: the thesis's own
// algorithm (§3.2–§3.3) with fixed time steps and "revert on ground penetration", here with a
// step of 1e-4 s instead of the thesis's 0.02 s.
//
// It shares with the core only what must be shared for a trajectory-by-trajectory comparison:
// the scenario (profile vertices, materials, blocks, sources, lines, settings), the impact law
// (model::ImpactLaw::resolve) and the per-trajectory random stream, consumed in the same order
// (one draw per impact, sliding launches and concave-vertex impacts included). Everything the
// exact-contact core does in closed form — the contact search, the sliding events, the
// observation-line crossings, the ground under the block — is redone here by stepping.
#pragma once

#include <cstdint>
#include <vector>

#include "pierre/geometry/vec2.hpp"
#include "pierre/model/impact_law.hpp"
#include "pierre/sim/results.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::oracle {

struct OracleOptions {
  double dt = 1e-4;             // s: the fixed time step
  bool record_impacts = false;  // keep every impact (for diagnosing divergences)
};

// How an oracle impact came about.
enum class ImpactKind : std::uint8_t {
  penetration,  // a flight step went below the ground: reverted, then resolved
  launch,       // sliding faster than the maximum sliding speed (§3.2.2)
  vertex,       // sliding into a concave vertex: an impact on the next segment
};

struct OracleImpact {
  double time = 0;
  geometry::Vec2 position;  // where the impact was resolved (the reverted point for a flight)
  int segment = -1;
  geometry::Vec2 v_in;
  double omega_in = 0;
  ImpactKind kind = ImpactKind::penetration;
  model::ImpactResult result = model::ImpactResult::rebound;
  model::ImpactDetail detail;
};

struct OracleCrossing {
  std::uint32_t line = 0;
  double time = 0;
  geometry::Vec2 velocity;
  double speed = 0;
  double height = 0;  // block centre above the top ground at the line
  bool sliding = false;
};

struct OracleResult {
  geometry::Vec2 start, stop;
  sim::StopReason stop_reason = sim::StopReason::numerical;
  double duration = 0;
  std::uint32_t impacts = 0;  // calls of the impact law (= random draws used)
  bool has_first_impact = false;
  geometry::Vec2 first_impact;
  std::vector<OracleCrossing> crossings;  // first crossing of each line in the main direction
  std::vector<OracleImpact> impact_log;   // when OracleOptions::record_impacts
  std::uint64_t steps = 0;                // time steps taken (cost)
};

// Simulates trajectory `index` of the scenario (its source, block and random stream are those
// the core uses for the same index).
OracleResult simulate_time_step(const sim::Scenario& scenario, std::uint64_t index,
                                const OracleOptions& options = {});

}  // namespace pierre::oracle
