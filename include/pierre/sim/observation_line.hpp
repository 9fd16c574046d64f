// Observation lines (the thesis's OBS file; model-2d.md §5): vertical lines at chainages that
// tally every crossing of a block's path, kept apart from the physics as a tally is in a
// Monte Carlo transport code.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pierre/geometry/profile.hpp"
#include "pierre/sim/results.hpp"

namespace pierre::sim {

struct ObservationLine {
  std::string name;
  double x = 0;  // chainage, m
};

// The per-trajectory tally: receives the path piece by piece from the integrator.
class ObservationTally {
 public:
  ObservationTally(const std::vector<ObservationLine>& lines, const geometry::Profile& profile,
                   bool all_crossings);

  // Where crossings go (kept across trajectories), and the start of each trajectory.
  void output(std::vector<Crossing>* out) { out_ = out; }
  void begin(std::uint64_t trajectory, std::uint32_t block, double mass, double inertia) {
    trajectory_ = trajectory;
    block_ = block;
    mass_ = mass;
    inertia_ = inertia;
    ++stamp_;  // forgets every line's first crossing at once
  }

  // A flight arc from p0 with velocity v0 starting at time t0, over (0, tau]. Inline: most arcs
  // cross no line, and that is found here from the lines sorted by x without a call.
  void flight(geometry::Vec2 p0, geometry::Vec2 v0, double omega, double t0, double tau,
              double g) {
    // The lines crossed, half-open (0, tau] (a crossing at an arc's end is not counted again by
    // the next piece), are a run [a, b) of the sorted ones: x0 < xc <= x1 forwards, x1 <= xc < x0
    // backwards. The tests are written as negations so that a NaN end counts as before, and a
    // NaN v0.x goes backwards. Only first crossings in the main direction count unless all are
    // asked for (forwards_, backwards_); a vertical drop crosses no vertical line.
    const double x1 = p0.x + v0.x * tau;
    const std::size_t n = xs_.size();
    if (v0.x > 0) {
      if (!forwards_ || p0.x >= x_last_ || x1 < x_first_) return;  // beside every line
      const std::size_t a = std::upper_bound(xs_.begin(), xs_.end(), p0.x) - xs_.begin();
      if (a == n || xs_[a] > x1) return;
      std::size_t b = a + 1;
      while (b < n && !(xs_[b] > x1)) ++b;
      flight_crossings(a, b, p0, v0, omega, t0, g);
    } else {
      if (v0.x == 0.0 || !backwards_ || p0.x <= x_first_ || x1 > x_last_) return;
      const std::size_t b = std::lower_bound(xs_.begin(), xs_.end(), p0.x) - xs_.begin();
      if (b == 0 || xs_[b - 1] < x1) return;
      std::size_t a = b - 1;
      while (a > 0 && !(xs_[a - 1] < x1)) --a;
      flight_crossings(a, b, p0, v0, omega, t0, g);
    }
  }
  // Sliding along a segment: position p0 + d·(w0 τ + a τ²/2), over (0, tau].
  void slide(geometry::Vec2 p0, geometry::Vec2 d, double w0, double acc, double omega,
             double t0, double tau);

  bool empty() const { return lines_.empty(); }

 private:
  // Records the crossings of the sorted lines [a, b) by a flight arc, in line order.
  void flight_crossings(std::size_t a, std::size_t b, geometry::Vec2 p0, geometry::Vec2 v0,
                        double omega, double t0, double g);
  void flight_crossing(std::size_t line, geometry::Vec2 p0, geometry::Vec2 v0, double omega,
                       double t0, double g);
  void record(std::size_t line, double time, geometry::Vec2 pos, geometry::Vec2 vel,
              double omega, bool sliding);

  struct Line {
    double x;
    double ground_z;  // ground at the line when the profile has no overhang there
    bool single_ground;
  };
  std::vector<Line> lines_;         // in the scenario's order: a crossing's `line` index
  std::vector<double> xs_;          // the lines' x, sorted
  double x_first_ = std::numeric_limits<double>::infinity();   // xs_ front, +inf when empty
  double x_last_ = -std::numeric_limits<double>::infinity();   // xs_ back, −inf when empty
  std::vector<std::uint32_t> order_;  // order_[k]: the line whose x is xs_[k]
  bool sorted_ = true;              // the scenario's order is already by x: order_[k] == k
  std::vector<std::uint32_t> scratch_;  // crossed lines of one arc, put back in line order
  const geometry::Profile* profile_;
  bool all_;
  int main_direction_;
  bool forwards_, backwards_;  // crossings in that direction (x rising, falling) are recorded
  std::uint64_t trajectory_ = 0;
  std::uint32_t block_ = 0;
  double mass_ = 0, inertia_ = 0;
  std::vector<Crossing>* out_ = nullptr;
  // A line's first crossing in the main direction is already recorded for this trajectory when
  // its entry equals stamp_ (a new stamp per trajectory instead of clearing them all).
  std::vector<std::uint64_t> seen_;
  std::uint64_t stamp_ = 0;
};

}  // namespace pierre::sim
