// First-impact and runout distances of each trajectory (design-checks.md §2, "ID", "RD"), from
// the trajectory summaries of a run whose SimulationSettings::floor_segment was set to the
// geometry's floor_segment.
//
//   ID = floor_contact.x − x_toe (horizontal, along the main direction), clamped at 0: 0 when
//        the block slid across the toe. A block that never reached the floor has no ID: it is
//        counted (`not_reached_floor`), not in the ID sample; the ID sample's denominator is
//        the blocks that reached the floor.
//   RD = x_stop − x_toe over ALL blocks: 0 for a stop above the toe (on the face or a bench,
//        or back over the crest: `left_upslope`); +infinity (right-censored at the floor's
//        length) for a block that left the profile at its runout end (stop reason
//        `boundary`). Stops by time or impact limit or a numerical failure keep their last
//        position and are counted (`abnormal`).
// The per-trajectory records keep everything a report draws (histograms, CDFs) and durations.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "pierre/design/quarry_geometry.hpp"
#include "pierre/sim/results.hpp"

namespace pierre::design {

struct QuarryTrajectory {
  std::uint64_t trajectory = 0;
  std::uint32_t block = 0;
  double mass = 0;              // kg
  bool reached_floor = false;   // has an ID
  double id = 0;                // m, when reached_floor (else NaN)
  double rd = 0;                // m, >= 0; +infinity when censored
  bool censored = false;        // left the profile at its runout end
  bool above_toe = false;       // stopped on the face or a bench above the toe (RD = 0)
  bool left_upslope = false;    // left the profile at its source end (RD = 0, above_toe too)
  sim::StopReason stop_reason = sim::StopReason::numerical;
  double duration = 0;          // s
};

struct QuarryDistances {
  std::vector<QuarryTrajectory> trajectories;  // in the order given (trajectory order)
  std::vector<double> id;        // m, the blocks that reached the floor
  std::vector<double> rd;        // m, every block (+infinity: censored)
  std::vector<double> duration;  // s, every block
  std::uint64_t thrown = 0;
  std::uint64_t reached_floor = 0, not_reached_floor = 0;
  std::uint64_t above_toe = 0;     // RD = 0 (includes left_upslope)
  std::uint64_t left_profile = 0;  // censored at the runout end
  std::uint64_t left_upslope = 0;  // left the profile at its source end
  std::uint64_t abnormal = 0;      // time limit, impact limit or numerical
  double censor_distance = 0;      // m: where censored runouts are censored (floor length)

  // Adds one trajectory (a run's sink may call this chunk by chunk).
  void add(const sim::TrajectorySummary& t, const QuarryGeometry& g);
};

// One trajectory's ID and RD and how it ended, as QuarryDistances counts it (and as the quarry
// trajectories.csv writes it).
QuarryTrajectory quarry_trajectory(const sim::TrajectorySummary& t, const QuarryGeometry& g);

QuarryDistances quarry_distances(std::span<const sim::TrajectorySummary> trajectories,
                                 const QuarryGeometry& geometry);

}  // namespace pierre::design
