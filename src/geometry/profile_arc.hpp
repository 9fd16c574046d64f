// What the profile's searches share (profile.cpp, profile_contact.cpp, profile_height.cpp):
// the geometric slack and an arc's horizontal motion. Internal to the geometry library.
#pragma once

#include <algorithm>
#include <limits>

namespace pierre::geometry::detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
// Geometric slack for "on the segment" and box tests: round-off, not physics.
inline constexpr double kEps = 1e-9;
// Segments (or runs) tested in order from the departure before the tree is used.
inline constexpr int kMarch = 6;

// The horizontal motion of an arc, x(t) = x0 + vx t, with 1/vx kept: the time window in which
// x lies in [lo, hi], clipped to [0, t1], costs two multiplications.
struct ArcX {
  double x0, vx, inv;
  ArcX(double x, double v) : x0(x), vx(v), inv(v != 0.0 ? 1.0 / v : 0.0) {}
  bool window(double lo, double hi, double t1, double& ta, double& tb) const {
    if (vx > 0) {
      ta = std::max(0.0, (lo - x0) * inv);
      tb = std::min(t1, (hi - x0) * inv);
    } else if (vx < 0) {
      ta = std::max(0.0, (hi - x0) * inv);
      tb = std::min(t1, (lo - x0) * inv);
    } else {
      if (x0 < lo || x0 > hi) return false;
      ta = 0.0;
      tb = t1;
    }
    return ta <= tb;
  }
};

}  // namespace pierre::geometry::detail
