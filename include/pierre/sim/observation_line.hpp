// Observation lines (the thesis's OBS file; model-2d.md §5): vertical lines at chainages that
// tally every crossing of a block's path, kept apart from the physics as a tally is in a
// Monte Carlo transport code.
#pragma once

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
  void begin(std::uint64_t trajectory, std::uint32_t block, double mass, double inertia);

  // A flight arc from p0 with velocity v0 starting at time t0, over (0, tau].
  void flight(geometry::Vec2 p0, geometry::Vec2 v0, double omega, double t0, double tau,
              double g);
  // Sliding along a segment: position p0 + d·(w0 τ + a τ²/2), over (0, tau].
  void slide(geometry::Vec2 p0, geometry::Vec2 d, double w0, double acc, double omega,
             double t0, double tau);

  bool empty() const { return lines_.empty(); }

 private:
  void record(std::size_t line, double time, geometry::Vec2 pos, geometry::Vec2 vel,
              double omega, bool sliding);

  struct Line {
    double x;
    double ground_z;  // ground at the line when the profile has no overhang there
    bool single_ground;
  };
  std::vector<Line> lines_;
  const geometry::Profile* profile_;
  bool all_;
  int main_direction_;
  std::uint64_t trajectory_ = 0;
  std::uint32_t block_ = 0;
  double mass_ = 0, inertia_ = 0;
  std::vector<Crossing>* out_ = nullptr;
  std::vector<char> seen_;  // first crossing in the main direction already recorded
};

}  // namespace pierre::sim
