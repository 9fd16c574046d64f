#include "pierre/sim/observation_line.hpp"

#include <algorithm>
#include <cmath>

namespace pierre::sim {

ObservationTally::ObservationTally(const std::vector<ObservationLine>& lines,
                                   const geometry::Profile& profile, bool all_crossings)
    : profile_(&profile),
      all_(all_crossings),
      main_direction_(profile.main_direction()),
      forwards_(all_ || main_direction_ > 0),
      backwards_(all_ || main_direction_ < 0) {
  for (const ObservationLine& l : lines) {
    Line ln{l.x, 0.0, false};
    // Where one ground line is all there is at x, its elevation is fixed; under an overhang
    // the ground below depends on the block's height and is looked up per crossing.
    const auto top = profile.top_ground(l.x);
    const auto low = profile.ground_below(l.x, top ? top->z - 1e-6 : 0.0);
    if (top && !low) {
      ln.ground_z = top->z;
      ln.single_ground = true;
    }
    lines_.push_back(ln);
  }
  order_.resize(lines_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<std::uint32_t>(i);
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::uint32_t i, std::uint32_t j) { return lines_[i].x < lines_[j].x; });
  for (std::size_t k = 0; k < order_.size(); ++k) {
    xs_.push_back(lines_[order_[k]].x);
    sorted_ = sorted_ && order_[k] == k;
  }
  if (!xs_.empty()) {
    x_first_ = xs_.front();
    x_last_ = xs_.back();
  }
  seen_.assign(lines_.size(), 0);
}

void ObservationTally::record(std::size_t i, double time, geometry::Vec2 pos,
                              geometry::Vec2 vel, double omega, bool sliding) {
  const int direction = vel.x >= 0 ? 1 : -1;
  if (!all_) {
    if (direction != main_direction_ || seen_[i] == stamp_) return;
    seen_[i] = stamp_;
  }
  Crossing& c = out_->emplace_back();
  c.trajectory = trajectory_;
  c.line = static_cast<std::uint32_t>(i);
  c.block = block_;
  c.mass = mass_;
  c.time = time;
  c.direction = direction;
  c.velocity = vel;
  c.speed = norm(vel);
  c.omega = omega;
  c.translational_energy = 0.5 * mass_ * dot(vel, vel);
  c.rotational_energy = 0.5 * inertia_ * omega * omega;
  c.sliding = sliding;
  if (sliding) {
    c.height = 0.0;  // the centre is on the ground line (point contact)
  } else if (lines_[i].single_ground) {
    c.height = pos.z - lines_[i].ground_z;
  } else {
    const auto g = profile_->ground_below(pos.x, pos.z);
    c.height = g ? pos.z - g->z : 0.0;
  }
}

void ObservationTally::flight_crossing(std::size_t i, geometry::Vec2 p0, geometry::Vec2 v0,
                                       double omega, double t0, double g) {
  const double xc = lines_[i].x;
  const double t = (xc - p0.x) / v0.x;
  record(i, t0 + t, {xc, p0.z + v0.z * t - 0.5 * g * t * t}, {v0.x, v0.z - g * t}, omega, false);
}

void ObservationTally::flight_crossings(std::size_t a, std::size_t b, geometry::Vec2 p0,
                                        geometry::Vec2 v0, double omega, double t0, double g) {
  // Crossings are written in line order, whatever the direction of travel.
  if (sorted_) {
    for (std::size_t k = a; k < b; ++k) flight_crossing(k, p0, v0, omega, t0, g);
    return;
  }
  scratch_.assign(order_.begin() + static_cast<std::ptrdiff_t>(a),
                  order_.begin() + static_cast<std::ptrdiff_t>(b));
  std::sort(scratch_.begin(), scratch_.end());
  for (std::uint32_t i : scratch_) flight_crossing(i, p0, v0, omega, t0, g);
}

void ObservationTally::slide(geometry::Vec2 p0, geometry::Vec2 d, double w0, double acc,
                             double omega, double t0, double tau) {
  const double vx0 = w0 * d.x;
  if (d.x == 0.0) return;
  const double dist = w0 * tau + 0.5 * acc * tau * tau;
  const double x1 = p0.x + dist * d.x;
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    const double xc = lines_[i].x;
    const bool forward = x1 > p0.x || (x1 == p0.x && vx0 > 0);
    if (forward ? (xc <= p0.x || xc > x1) : (xc >= p0.x || xc < x1)) continue;
    // Solve w0 τ + a τ²/2 = (xc − x0)/d.x for the first τ in (0, tau]: the motion is monotone
    // between sliding events.
    const double target = (xc - p0.x) / d.x;
    // Stable form of the root nearest zero; the motion's sign is the target's. (The integrator
    // solves the same equation for the segment's end, trajectory.cpp, where a negative
    // discriminant means the end is not reached; here the crossing is known to lie within the
    // slide, so rounding below zero is clamped.)
    const double disc = std::max(0.0, w0 * w0 + 2.0 * acc * target);
    const double denom = w0 + std::copysign(std::sqrt(disc), target);
    double t = denom != 0.0 ? 2.0 * target / denom : tau;
    t = std::clamp(t, 0.0, tau);
    const double w = w0 + acc * t;
    record(i, t0 + t, {xc, p0.z + (w0 * t + 0.5 * acc * t * t) * d.z}, w * d, omega, true);
  }
}

}  // namespace pierre::sim
