#include "pierre/design/quarry_distances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pierre::design {

QuarryTrajectory quarry_trajectory(const sim::TrajectorySummary& t, const QuarryGeometry& g) {
  QuarryTrajectory q;
  q.trajectory = t.trajectory;
  q.block = t.block;
  q.mass = t.mass;
  q.stop_reason = t.stop_reason;
  q.duration = t.duration;
  q.reached_floor = t.has_floor_contact;
  q.id = t.has_floor_contact ? std::max(0.0, distance_from_toe(g, t.floor_contact.x))
                             : std::numeric_limits<double>::quiet_NaN();

  const double d_stop = distance_from_toe(g, t.stop.x);
  if (t.stop_reason == sim::StopReason::boundary) {
    // Which end it left by: the nearer one.
    const bool at_runout_end =
        std::abs(g.floor_length - d_stop) <= std::abs(d_stop - g.source_end_distance);
    q.censored = at_runout_end;
    q.left_upslope = !at_runout_end;
  }
  if (q.censored) {
    q.rd = std::numeric_limits<double>::infinity();
  } else if (!q.left_upslope && d_stop > 0) {
    q.rd = d_stop;
  } else {
    q.rd = 0;
    q.above_toe = true;
  }
  return q;
}

void QuarryDistances::add(const sim::TrajectorySummary& t, const QuarryGeometry& g) {
  censor_distance = g.floor_length;
  const QuarryTrajectory q = quarry_trajectory(t, g);
  ++thrown;
  left_profile += q.censored;
  left_upslope += q.left_upslope;
  above_toe += q.above_toe;
  if (q.stop_reason != sim::StopReason::energy && q.stop_reason != sim::StopReason::friction &&
      q.stop_reason != sim::StopReason::boundary)
    ++abnormal;
  if (q.reached_floor) {
    ++reached_floor;
    id.push_back(q.id);
  } else {
    ++not_reached_floor;
  }
  rd.push_back(q.rd);
  duration.push_back(q.duration);
  trajectories.push_back(q);
}

QuarryDistances quarry_distances(std::span<const sim::TrajectorySummary> trajectories,
                                 const QuarryGeometry& geometry) {
  QuarryDistances out;
  out.censor_distance = geometry.floor_length;
  for (const auto& t : trajectories) out.add(t, geometry);
  return out;
}

}  // namespace pierre::design
