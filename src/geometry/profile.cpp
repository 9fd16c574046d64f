#include "pierre/geometry/profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace pierre::geometry {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Direction changes below this are not vertices (model-2d.md §2: subdividing changes nothing).
constexpr double kStraightAngle = 1e-9;
// Geometric slack for "on the segment" and box tests: round-off, not physics.
constexpr double kEps = 1e-9;
constexpr int kLeafSize = 4;

bool segments_intersect(const Segment& p, const Segment& q) {
  // Proper or touching intersection of two closed segments.
  auto orient = [](Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); };
  const double d1 = orient(q.a, q.b, p.a), d2 = orient(q.a, q.b, p.b);
  const double d3 = orient(p.a, p.b, q.a), d4 = orient(p.a, p.b, q.b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto on = [](Vec2 a, Vec2 b, Vec2 c) {  // c on segment ab, given collinear
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.z, b.z) <= c.z &&
           c.z <= std::max(a.z, b.z);
  };
  return (d1 == 0 && on(q.a, q.b, p.a)) || (d2 == 0 && on(q.a, q.b, p.b)) ||
         (d3 == 0 && on(p.a, p.b, q.a)) || (d4 == 0 && on(p.a, p.b, q.b));
}

// The time window in which the parabola's x lies in [lo, hi], clipped to [t0, t1].
bool x_window(double x0, double vx, double lo, double hi, double t0, double t1, double& ta,
              double& tb) {
  if (vx > 0) {
    ta = std::max(t0, (lo - x0) / vx);
    tb = std::min(t1, (hi - x0) / vx);
  } else if (vx < 0) {
    ta = std::max(t0, (hi - x0) / vx);
    tb = std::min(t1, (lo - x0) / vx);
  } else {
    if (x0 < lo || x0 > hi) return false;
    ta = t0;
    tb = t1;
  }
  return ta <= tb;
}

}  // namespace

std::optional<Profile> Profile::build(const std::vector<Vec2>& vertices,
                                      const std::vector<int>& materials,
                                      std::vector<ProfileIssue>* issues) {
  std::vector<ProfileIssue> found;
  if (vertices.size() < 2) found.push_back({0, "a profile needs at least two vertices"});
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!std::isfinite(vertices[i].x) || !std::isfinite(vertices[i].z))
      found.push_back({i, "vertex coordinates must be finite numbers"});
    else if (i > 0 && vertices[i].x == vertices[i - 1].x && vertices[i].z == vertices[i - 1].z)
      found.push_back({i, "vertex repeats the previous one (a segment of zero length)"});
  }
  if (!found.empty()) {
    if (issues) *issues = std::move(found);
    return std::nullopt;
  }

  Profile p;
  p.vertices_ = vertices;
  p.segments_.reserve(vertices.size() - 1);
  for (std::size_t i = 0; i + 1 < vertices.size(); ++i) {
    Segment s;
    s.a = vertices[i];
    s.b = vertices[i + 1];
    s.length = norm(s.b - s.a);
    s.d = (1.0 / s.length) * (s.b - s.a);
    s.n = left_normal(s.d);
    s.material = i < materials.size() ? materials[i] : 0;
    p.segments_.push_back(s);
  }
  p.x_min_ = kInf;
  p.x_max_ = -kInf;
  for (const Vec2& v : vertices) {
    p.x_min_ = std::min(p.x_min_, v.x);
    p.x_max_ = std::max(p.x_max_, v.x);
  }
  p.main_direction_ = vertices.back().x >= vertices.front().x ? 1 : -1;
  p.x_monotone_ = true;
  for (const Segment& s : p.segments_)
    if (s.d.x * p.main_direction_ < 0) p.x_monotone_ = false;

  p.turns_.resize(p.segments_.size() > 0 ? p.segments_.size() - 1 : 0);
  for (std::size_t i = 0; i + 1 < p.segments_.size(); ++i) {
    const Vec2 d0 = p.segments_[i].d, d1 = p.segments_[i + 1].d;
    const double angle = std::atan2(cross(d0, d1), dot(d0, d1));
    if (std::abs(angle) < kStraightAngle)
      p.turns_[i] = VertexTurn::straight;
    else
      p.turns_[i] = angle > 0 ? VertexTurn::concave : VertexTurn::convex;
    if (std::abs(angle) > M_PI - kStraightAngle)
      found.push_back({i + 1, "the profile folds back on itself at this vertex"});
  }

  p.nodes_.reserve(2 * p.segments_.size() / kLeafSize + 4);
  p.build_node(0, static_cast<int>(p.segments_.size()));

  // Self-intersection: every pair of non-adjacent segments whose boxes overlap.
  for (std::size_t i = 0; i < p.segments_.size() && found.empty(); ++i) {
    const Segment& si = p.segments_[i];
    const double xl = std::min(si.a.x, si.b.x), xh = std::max(si.a.x, si.b.x);
    const double zl = std::min(si.a.z, si.b.z), zh = std::max(si.a.z, si.b.z);
    std::vector<int> stack{0};
    while (!stack.empty() && found.empty()) {
      const Node& nd = p.nodes_[stack.back()];
      stack.pop_back();
      if (nd.x_hi < xl || nd.x_lo > xh || nd.z_hi < zl || nd.z_lo > zh) continue;
      if (nd.left < 0) {
        for (int j = nd.first; j < nd.last; ++j) {
          if (j <= static_cast<int>(i) + 1) continue;  // each pair once; neighbours share a vertex
          if (segments_intersect(si, p.segments_[j]))
            found.push_back({i + 1, "the profile crosses itself: segment from vertex " +
                                        std::to_string(i + 1) + " meets segment from vertex " +
                                        std::to_string(j + 1) + " (1-based)"});
        }
      } else {
        stack.push_back(nd.left);
        stack.push_back(nd.right);
      }
    }
  }
  if (!found.empty()) {
    if (issues) *issues = std::move(found);
    return std::nullopt;
  }
  return p;
}

int Profile::build_node(int first, int last) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back({kInf, -kInf, kInf, -kInf, first, last});
  Node nd = nodes_[id];
  for (int i = first; i < last; ++i) {
    const Segment& s = segments_[i];
    nd.x_lo = std::min({nd.x_lo, s.a.x, s.b.x});
    nd.x_hi = std::max({nd.x_hi, s.a.x, s.b.x});
    nd.z_lo = std::min({nd.z_lo, s.a.z, s.b.z});
    nd.z_hi = std::max({nd.z_hi, s.a.z, s.b.z});
  }
  if (last - first > kLeafSize) {
    const int mid = first + (last - first) / 2;
    nd.left = build_node(first, mid);
    nd.right = build_node(mid, last);
  }
  nodes_[id] = nd;
  return id;
}

std::optional<Contact> Profile::first_contact(Vec2 p0, Vec2 v0, double g, double t_max,
                                              const Departure& dep) const {
  Contact best;
  double t_best = t_max;
  bool found = false;

  auto test_segment = [&](int j) {
    const Segment& s = segments_[j];
    double c = dot(p0 - s.a, s.n);
    const double b = dot(v0, s.n);
    const double a = -0.5 * g * s.n.z;
    int departed = -1;
    for (int k = 0; k < 2; ++k)
      if (dep.segment[k] == j) departed = k;
    double roots[2];
    int nroots = 0;
    if (departed >= 0) {
      if (dep.tangent[departed]) return;
      c = 0.0;  // exactly on the line: drop the trivial root t = 0 (model-2d.md §2)
      if (b < 0 && dep.concave_vertex) {
        roots[nroots++] = 0.0;  // entering the neighbour at a concave vertex at once
      } else if (a != 0.0) {
        roots[nroots++] = -b / a;
      }
    } else if (a == 0.0) {
      if (b != 0.0) roots[nroots++] = -c / b;
    } else {
      const double disc = b * b - 4 * a * c;
      if (disc < 0) return;
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if (q == 0.0) {
        roots[nroots++] = 0.0;
      } else {
        const double r1 = q / a, r2 = c / q;
        roots[nroots++] = std::min(r1, r2);
        roots[nroots++] = std::max(r1, r2);
      }
    }
    for (int r = 0; r < nroots; ++r) {
      const double t = roots[r];
      if (!(t >= 0.0) || t >= t_best) continue;
      if (!(b + 2 * a * t < 0.0)) continue;  // must enter from the air side
      const Vec2 pt{p0.x + v0.x * t, p0.z + v0.z * t - 0.5 * g * t * t};
      const double along = dot(pt - s.a, s.d);
      const double slack = kEps * std::max(1.0, s.length);
      if (along < -slack || along > s.length + slack) continue;
      t_best = t;
      best = {t, j, std::clamp(along, 0.0, s.length)};
      found = true;
      return;
    }
  };

  // Best-first walk of the tree: the child the block reaches first is visited first, and
  // a box is skipped when the arc cannot reach it before the best contact so far.
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    double ta, tb;
    if (!x_window(p0.x, v0.x, nd.x_lo - kEps, nd.x_hi + kEps, 0.0, t_best, ta, tb)) continue;
    const double za = p0.z + v0.z * ta - 0.5 * g * ta * ta;
    const double zb = p0.z + v0.z * tb - 0.5 * g * tb * tb;
    if (std::min(za, zb) > nd.z_hi + kEps) continue;  // concave arc: lowest at an end
    const double t_apex = std::clamp(v0.z / g, ta, tb);
    const double z_top = p0.z + v0.z * t_apex - 0.5 * g * t_apex * t_apex;
    if (z_top < nd.z_lo - kEps) continue;
    if (nd.left < 0) {
      for (int j = nd.first; j < nd.last; ++j) test_segment(j);
      continue;
    }
    const Node& l = nodes_[nd.left];
    const Node& r = nodes_[nd.right];
    // Push the later child first: along the flight, the one nearer in x is reached first.
    const double kl = v0.x >= 0 ? l.x_lo : -l.x_hi;
    const double kr = v0.x >= 0 ? r.x_lo : -r.x_hi;
    if (kl <= kr) {
      stack[top++] = nd.right;
      stack[top++] = nd.left;
    } else {
      stack[top++] = nd.left;
      stack[top++] = nd.right;
    }
  }
  if (!found) return std::nullopt;
  return best;
}

std::optional<GroundPoint> Profile::ground_below(double x, double z) const {
  GroundPoint best{-kInf, -1};
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    if (x < nd.x_lo - kEps || x > nd.x_hi + kEps || nd.z_lo > z + kEps || nd.z_hi < best.z)
      continue;
    if (nd.left >= 0) {
      stack[top++] = nd.left;
      stack[top++] = nd.right;
      continue;
    }
    for (int j = nd.first; j < nd.last; ++j) {
      const Segment& s = segments_[j];
      if (s.d.x == 0.0) continue;  // a vertical face: its top is its neighbour's end
      const double lo = std::min(s.a.x, s.b.x), hi = std::max(s.a.x, s.b.x);
      if (x < lo - kEps || x > hi + kEps) continue;
      const double u = std::clamp((x - s.a.x) / (s.b.x - s.a.x), 0.0, 1.0);
      const double zs = s.a.z + u * (s.b.z - s.a.z);
      if (zs <= z + kEps && zs > best.z) best = {zs, j};
    }
  }
  if (best.segment < 0) return std::nullopt;
  return best;
}

std::optional<GroundPoint> Profile::top_ground(double x) const { return ground_below(x, kInf); }

double Profile::max_height_above_ground(Vec2 p0, Vec2 v0, double g, double t_end) const {
  auto z_at = [&](double t) { return p0.z + v0.z * t - 0.5 * g * t * t; };
  if (v0.x == 0.0) {  // vertical drop: one ground point under the whole arc
    const double t_apex = std::clamp(v0.z / g, 0.0, t_end);
    const auto ground = ground_below(p0.x, p0.z);
    return ground ? z_at(t_apex) - ground->z : 0.0;
  }
  double best = 0.0;
  auto consider = [&](double t, int seg) {
    const double x = p0.x + v0.x * t, z = z_at(t);
    const auto ground = ground_below(x, z);
    if (!ground) return;
    if (seg >= 0 && std::abs(ground->z - (segments_[seg].a.z +
                                          (x - segments_[seg].a.x) * segments_[seg].d.z /
                                              segments_[seg].d.x)) > 1e-9)
      return;  // another surface lies between: this segment is not the ground below here
    best = std::max(best, z - ground->z);
  };

  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    double ta, tb;
    if (!x_window(p0.x, v0.x, nd.x_lo, nd.x_hi, 0.0, t_end, ta, tb)) continue;
    const double t_apex = std::clamp(v0.z / g, ta, tb);
    if (z_at(t_apex) - nd.z_lo <= best) continue;  // cannot beat the best so far
    if (nd.left >= 0) {
      stack[top++] = nd.left;
      stack[top++] = nd.right;
      continue;
    }
    for (int j = nd.first; j < nd.last; ++j) {
      const Segment& s = segments_[j];
      if (s.d.x == 0.0) continue;
      double sa, sb;
      if (!x_window(p0.x, v0.x, std::min(s.a.x, s.b.x), std::max(s.a.x, s.b.x), 0.0, t_end, sa,
                    sb))
        continue;
      // h(t) = z(t) - ground(x(t)) is a concave quadratic on this segment.
      const double slope = s.d.z / s.d.x;
      const double t_star = std::clamp((v0.z - v0.x * slope) / g, sa, sb);
      const double x = p0.x + v0.x * t_star;
      const double h = z_at(t_star) - (s.a.z + (x - s.a.x) * slope);
      if (h <= best) continue;
      if (x_monotone_) {
        best = h;
      } else {
        consider(t_star, j);
        consider(sa, -1);
        consider(sb, -1);
      }
    }
  }
  return best;
}

}  // namespace pierre::geometry
