#include "pierre/geometry/profile.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "profile_arc.hpp"

namespace pierre::geometry {
namespace {

using detail::kEps;
using detail::kInf;

// Direction changes below this are not vertices (model-2d.md §2: subdividing changes nothing).
constexpr double kStraightAngle = 1e-9;
constexpr int kLeafSize = 4;

std::string fmt_point(Vec2 v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%g, %g)", v.x, v.z);
  return buf;
}

std::string fmt_crossing(const Segment& a, const Segment& b) {
  return "the profile crosses itself: the segment from " + fmt_point(a.a) + " to " +
         fmt_point(a.b) + " meets the segment from " + fmt_point(b.a) + " to " + fmt_point(b.b);
}

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


}  // namespace

std::optional<Profile> Profile::build(const std::vector<Vec2>& vertices,
                                      const std::vector<int>& materials,
                                      std::vector<ProfileIssue>* issues) {
  std::vector<ProfileIssue> found;
  if (vertices.size() < 2) found.push_back({0, "a profile needs at least two vertices", {}});
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!std::isfinite(vertices[i].x) || !std::isfinite(vertices[i].z))
      found.push_back({i, "vertex coordinates must be finite numbers", {}});
    else if (i > 0 && vertices[i].x == vertices[i - 1].x && vertices[i].z == vertices[i - 1].z)
      found.push_back({i, "vertex repeats the previous one (a segment of zero length)", {}});
  }
  // One material a segment: a shorter list left segments on material 0 without a word.
  if (vertices.size() >= 2 && materials.size() != vertices.size() - 1)
    found.push_back({std::min(materials.size(), vertices.size() - 1),
                     "one material per segment expected (" + std::to_string(vertices.size() - 1) +
                         " segments, " + std::to_string(materials.size()) + " materials)",
                     {}});
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
    s.x_lo = std::min(s.a.x, s.b.x);
    s.x_hi = std::max(s.a.x, s.b.x);
    s.material = materials[i];
    p.segments_.push_back(s);
  }
  p.x_min_ = p.z_min_ = kInf;
  p.x_max_ = p.z_max_ = -kInf;
  for (const Vec2& v : vertices) {
    p.x_min_ = std::min(p.x_min_, v.x);
    p.x_max_ = std::max(p.x_max_, v.x);
    p.z_min_ = std::min(p.z_min_, v.z);
    p.z_max_ = std::max(p.z_max_, v.z);
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
    if (std::abs(angle) > std::numbers::pi - kStraightAngle)
      found.push_back({i + 1, "the profile folds back on itself at this vertex", {}});
  }

  p.nodes_.reserve(2 * p.segments_.size() / kLeafSize + 4);
  p.build_node(0, static_cast<int>(p.segments_.size()));
  // Maximal straight runs: consecutive segments joined by vertices that are not events.
  p.run_of_.assign(p.segments_.size(), 0);
  for (std::size_t i = 0; i < p.segments_.size();) {
    std::size_t e = i + 1;
    while (e < p.segments_.size() && p.turns_[e - 1] == VertexTurn::straight) ++e;
    const Segment& s0 = p.segments_[i];
    const Vec2 end = p.segments_[e - 1].b;
    Run r;
    r.a = s0.a;
    r.d = s0.d;
    r.n = s0.n;
    r.length = e - i > 1 ? dot(end - s0.a, s0.d) : s0.length;
    r.x_lo = std::min(s0.a.x, end.x);
    r.x_hi = std::max(s0.a.x, end.x);
    r.slope = s0.d.x != 0.0 ? s0.d.z / s0.d.x : 0.0;
    r.begin = static_cast<int>(i);
    r.end = static_cast<int>(e);
    for (std::size_t k = i; k < e; ++k) p.run_of_[k] = static_cast<int>(p.runs_.size());
    p.runs_.push_back(r);
    i = e;
  }
  p.parents_.assign(p.nodes_.size(), -1);
  p.leaf_of_.assign(p.segments_.size(), 0);
  for (std::size_t k = 0; k < p.nodes_.size(); ++k) {
    const Node& nd = p.nodes_[k];
    if (nd.left >= 0) {
      p.parents_[nd.left] = p.parents_[nd.right] = static_cast<int>(k);
    } else {
      for (int j = nd.first; j < nd.last; ++j) p.leaf_of_[j] = static_cast<int>(k);
    }
  }

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
            found.push_back({i, fmt_crossing(si, p.segments_[j]), static_cast<std::size_t>(j)});
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

std::optional<Profile> Profile::split_at(std::size_t segment, Vec2 point,
                                         std::vector<ProfileIssue>* issues) const {
  if (segment >= segments_.size()) {
    if (issues) *issues = {{segments_.size(), "no segment " + std::to_string(segment), {}}};
    return std::nullopt;
  }
  std::vector<Vec2> pts{segments_.front().a};
  std::vector<int> mats;
  for (std::size_t j = 0; j < segments_.size(); ++j) {
    if (j == segment) {
      pts.push_back(point);
      mats.push_back(segments_[j].material);
    }
    pts.push_back(segments_[j].b);
    mats.push_back(segments_[j].material);
  }
  auto cut = build(pts, mats, issues);
  // Collinear pieces only: a point off the line would change the ground.
  if (cut && cut->turn_after(segment) != VertexTurn::straight) {
    if (issues)
      *issues = {{segment + 1, "the point " + fmt_point(point) + " is not on the segment's line", {}}};
    return std::nullopt;
  }
  return cut;
}

int Profile::build_node(int first, int last) {
  const int id = static_cast<int>(nodes_.size());
  Node nd;
  nd.x_lo = nd.z_lo = kInf;
  nd.x_hi = nd.z_hi = -kInf;
  nd.first = first;
  nd.last = last;
  nodes_.push_back(nd);
  for (int i = first; i < last; ++i) {
    const Segment& s = segments_[i];
    nd.x_lo = std::min({nd.x_lo, s.a.x, s.b.x});
    nd.x_hi = std::max({nd.x_hi, s.a.x, s.b.x});
    nd.z_lo = std::min({nd.z_lo, s.a.z, s.b.z});
    nd.z_hi = std::max({nd.z_hi, s.a.z, s.b.z});
  }
  const Vec2 v0 = segments_[first].a, v1 = segments_[last - 1].b;
  nd.slope = std::abs(v1.x - v0.x) > 1e-9 * (1 + std::abs(v1.z - v0.z)) ? (v1.z - v0.z) / (v1.x - v0.x) : 0.0;
  nd.icpt = v0.z - nd.slope * v0.x;
  nd.off_lo = kInf;
  nd.off_hi = -kInf;
  for (int i = first; i <= last; ++i) {  // the offset is affine: its extremes are at vertices
    const Vec2 v = i < last ? segments_[i].a : segments_[last - 1].b;
    const double off = v.z - (nd.icpt + nd.slope * v.x);
    nd.off_lo = std::min(nd.off_lo, off);
    nd.off_hi = std::max(nd.off_hi, off);
  }
  // Straight: more than one segment, no vertex turning by 1e-9 rad or more, all on the chord.
  nd.straight = last - first > 1 && nd.off_hi - nd.off_lo <= kEps;
  for (int i = first; nd.straight && i + 1 < last; ++i)
    nd.straight = turns_[i] == VertexTurn::straight;
  if (last - first > kLeafSize) {
    const int mid = first + (last - first) / 2;
    nd.left = build_node(first, mid);
    nd.right = build_node(mid, last);
  }
  nodes_[id] = nd;
  return id;
}

template <class Prune, class Visit>
void Profile::segments_at(double x, Prune prune, Visit visit) const {
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    if (x < nd.x_lo - kEps || x > nd.x_hi + kEps || prune(nd)) continue;
    if (nd.left >= 0) {
      stack[top++] = nd.left;
      stack[top++] = nd.right;
      continue;
    }
    for (int j = nd.first; j < nd.last; ++j) {
      const Segment& s = segments_[j];
      if (s.d.x == 0.0) continue;
      const double lo = std::min(s.a.x, s.b.x), hi = std::max(s.a.x, s.b.x);
      if (x < lo - kEps || x > hi + kEps) continue;
      const double u = std::clamp((x - s.a.x) / (s.b.x - s.a.x), 0.0, 1.0);
      visit(s, j, s.a.z + u * (s.b.z - s.a.z));
    }
  }
}

std::optional<GroundPoint> Profile::ground_below(double x, double z) const {
  GroundPoint best{-kInf, -1};
  segments_at(
      x, [&](const Node& nd) { return nd.z_lo > z + kEps || nd.z_hi < best.z; },
      [&](const Segment& s, int j, double zs) {
        // A vertical face's top is its neighbour's end; the underside of a ledge (its air
        // below, n.z < 0) is a ceiling, never the ground below a block.
        if (s.n.z >= 0.0 && zs <= z + kEps && zs > best.z) best = {zs, j};
      });
  if (best.segment < 0) return std::nullopt;
  return best;
}

std::optional<GroundPoint> Profile::top_ground(double x) const { return ground_below(x, kInf); }

std::optional<Profile::LineAbove> Profile::line_above(double x, double z) const {
  LineAbove best{kInf, -1, false};
  segments_at(
      x, [&](const Node& nd) { return nd.z_hi <= z + kEps || nd.z_lo > best.z; },
      [&](const Segment& s, int j, double zs) {
        // At the lip of an overhang a ground line and a ceiling meet at one height: the ceiling
        // decides, as just beside the lip the point is below the underside, in the air.
        if (zs > z + kEps && (zs < best.z || (zs == best.z && s.n.z < 0.0)))
          best = {zs, j, s.n.z > 0.0};
      });
  if (best.segment < 0) return std::nullopt;
  return best;
}

}  // namespace pierre::geometry
