// A point or vector in the vertical section: x horizontal (chainage), z up. Metres.
#pragma once

#include <cmath>
#include <numbers>

namespace pierre::geometry {

struct Vec2 {
  double x = 0.0;
  double z = 0.0;
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.z + b.z}; }
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.z - b.z}; }
constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.z}; }
constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.z}; }
constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.z * b.z; }
// z-component of the 3-D cross product: > 0 when b turns counter-clockwise from a.
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.z - a.z * b.x; }
inline double norm(Vec2 a) { return std::sqrt(dot(a, a)); }
// Left normal: for a walking direction d the air is on this side (model-2d.md §1).
constexpr Vec2 left_normal(Vec2 d) { return {-d.z, d.x}; }

// An angle in radians in degrees, as inputs and reports give angles (model-2d.md: degrees
// except roughness). (The impact law keeps its own 180/π factor: its outputs are pinned to it.)
constexpr double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace pierre::geometry
