#include "pierre/geometry/profile.hpp"

#include <algorithm>
#include <cstdio>
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
// Segments tested in order from the departure before the tree is used.
constexpr int kMarch = 6;

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
    s.material = i < materials.size() ? materials[i] : 0;
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
    if (std::abs(angle) > M_PI - kStraightAngle)
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

namespace {

// Earliest entering root of the arc p0 + v0 t − g t²/2 on a line (point A, unit direction d,
// air-side normal n) whose piece of interest spans [0, length] along d, before t_best; kind: 0
// plain, 1 departed (c = 0 exactly: drop the trivial root t = 0, model-2d.md §2; from a concave
// vertex, entering the neighbour at once), 2 left tangentially (cannot be hit).
inline bool line_root(Vec2 p0, Vec2 v0, double g, const ArcX& ax, double t_best, Vec2 A, Vec2 n,
                      Vec2 d, double length, double xlo, double xhi, int kind,
                      bool concave_vertex, double& t_out, double& along_out) {
  if (kind == 2) return false;
  double c = dot(p0 - A, n);
  const double b = dot(v0, n);
  const double a = -0.5 * g * n.z;
  double roots[2];
  int nroots = 0;
  if (kind == 1) {
    c = 0.0;
    if (b < 0 && concave_vertex) {
      roots[nroots++] = 0.0;  // entering the neighbour at a concave vertex at once
    } else if (a != 0.0) {
      roots[nroots++] = -b / a;
    }
  } else if (double ta, tb; !ax.window(xlo - kEps, xhi + kEps, t_best, ta, tb)) {
    return false;  // the arc does not pass over this piece before the best contact so far
  } else if (a == 0.0) {
    if (b != 0.0) roots[nroots++] = -c / b;
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return false;
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
    const double along = dot(pt - A, d);
    const double slack = kEps * std::max(1.0, length);
    if (along < -slack || along > length + slack) continue;
    t_out = t;
    along_out = std::clamp(along, 0.0, length);
    return true;
  }
  return false;
}

// One contact search: the arc, its departure and the earliest contact found so far.
struct ArcSearch {
  Vec2 p0, v0;
  double g;
  ArcX ax;
  const Departure& dep;
  double t_best;
  Contact best{};
  bool found = false;

  bool solve(Vec2 A, Vec2 n, Vec2 d, double length, double xlo, double xhi, int kind,
             double& t_out, double& along_out) const {
    return line_root(p0, v0, g, ax, t_best, A, n, d, length, xlo, xhi, kind, dep.concave_vertex,
                     t_out, along_out);
  }

  int kind_of(int j) const {
    for (int k = 0; k < 2; ++k)
      if (dep.segment[k] == j) return dep.tangent[k] ? 2 : 1;
    return 0;
  }
  // The kind of a range of segments: departed if the departure is on it.
  int kind_of(int first, int last) const {
    int kind = 0;
    for (int k = 0; k < 2; ++k)
      if (dep.segment[k] >= first && dep.segment[k] < last)
        kind = std::max(kind, dep.tangent[k] ? 2 : 1);
    return kind;
  }
  bool departs_from(int j) const { return j == dep.segment[0] || j == dep.segment[1]; }

  void test_segment(const Segment& s, int j) {
    double t, along;
    if (solve(s.a, s.n, s.d, s.length, s.x_lo, s.x_hi, kind_of(j), t, along)) {
      t_best = t;
      best = {t, j, along};
      found = true;
    }
  }
};

}  // namespace

std::optional<Contact> Profile::first_contact(Vec2 p0, Vec2 v0, double g, double t_max,
                                              const Departure& dep) const {
  // The commonest arc by far: a rebound from one segment that lands on that same segment (a
  // bounce along a slope or the floor). Without overhangs nothing else can be met first (x is
  // monotone along the flight and along the section), so the departed line's own root is the
  // contact: the same arithmetic as ArcSearch::solve for a departed segment.
  if (const int j = dep.segment[0];
      x_monotone_ && v0.x != 0.0 && j >= 0 && dep.segment[1] < 0 && !dep.tangent[0] &&
      runs_[run_of_[j]].end - runs_[run_of_[j]].begin == 1) {
    const Segment& s = segments_[j];
    const double b = dot(v0, s.n);
    const double a = -0.5 * g * s.n.z;
    if (!(b < 0 && dep.concave_vertex) && a != 0.0) {
      const double t = -b / a;
      if (t >= 0.0 && t < t_max && b + 2 * a * t < 0.0) {
        const Vec2 pt{p0.x + v0.x * t, p0.z + v0.z * t - 0.5 * g * t * t};
        const double along = dot(pt - s.a, s.d);
        const double slack = kEps * std::max(1.0, s.length);
        if (along >= -slack && along <= s.length + slack)
          return Contact{t, j, std::clamp(along, 0.0, s.length)};
      }
      // The next commonest: a hop that leaves its segment (down a face). The departed line
      // holds no contact (the root just rejected is the only one it can have), so the runs
      // ahead come next, as in the general search.
      Contact c;
      if (const int found = march_runs(p0, v0, g, t_max, run_of_[j], c); found >= 0)
        return found ? std::optional<Contact>(c) : std::nullopt;
    }
  } else if (const int j = dep.segment[0];
             x_monotone_ && v0.x != 0.0 && j >= 0 && dep.segment[1] < 0 && !dep.tangent[0]) {
    // The same from a segment of a longer run (a finely digitised straight slope).
    Contact c;
    if (const int found = contact_from(p0, v0, g, t_max, j, 1, c); found >= 0)
      return found ? std::optional<Contact>(c) : std::nullopt;
  } else if (x_monotone_ && v0.x != 0.0 && dep.segment[0] < 0 && dep.segment[1] < 0) {
    // A flight from a source: from the segment under the block.
    const int under = segment_under(p0.x);
    Contact c;
    // A one-segment run: contact_from's first step and its march, written out here, since the
    // call cost every trajectory 62 instructions (callgrind, bench_one_run quarry-preg 4000).
    if (runs_[run_of_[under]].end - runs_[run_of_[under]].begin == 1) {
      const Segment& s = segments_[under];
      double t, along;
      if (line_root(p0, v0, g, ArcX(p0.x, v0.x), t_max, s.a, s.n, s.d, s.length, s.x_lo, s.x_hi,
                    0, false, t, along))
        return Contact{t, under, along};
      if (const int found = march_runs(p0, v0, g, t_max, run_of_[under], c); found >= 0)
        return found ? std::optional<Contact>(c) : std::nullopt;
    } else if (const int found = contact_from(p0, v0, g, t_max, under, 0, c); found >= 0) {
      return found ? std::optional<Contact>(c) : std::nullopt;
    }
    return first_contact_search(p0, v0, g, t_max, dep, under);
  }
  return first_contact_search(p0, v0, g, t_max, dep);
}

int Profile::segment_under(double x) const {
  int lo = 0, hi = static_cast<int>(segments_.size()) - 1;
  while (lo < hi) {  // last segment whose start is not beyond x along the main direction
    const int mid = (lo + hi + 1) / 2;
    if ((segments_[mid].a.x - x) * main_direction_ <= 0) lo = mid; else hi = mid - 1;
  }
  return lo;
}

int Profile::contact_from(Vec2 p0, Vec2 v0, double g, double t_max, int j, int kind,
                          Contact& out) const {
  // first_contact_search's order and arithmetic, without its set-up: the segment, then its
  // whole run when longer (the contact may lie on another piece of the same line), then the
  // runs ahead.
  const Segment& s = segments_[j];
  const Run& run = runs_[run_of_[j]];
  const ArcX ax(p0.x, v0.x);
  double t_best = t_max, t, along;
  bool found = false;
  if (line_root(p0, v0, g, ax, t_best, s.a, s.n, s.d, s.length, s.x_lo, s.x_hi, kind, false, t,
                along)) {
    out = {t, j, along};
    t_best = t;
    found = true;
  }
  if (run.end - run.begin > 1 && line_root(p0, v0, g, ax, t_best, run.a, run.n, run.d, run.length,
                                           run.x_lo, run.x_hi, kind, false, t, along)) {
    out = contact_on_line(run.a, run.d, run.begin, run.end, t, along);
    found = true;
  }
  return found ? 1 : march_runs(p0, v0, g, t_max, run_of_[j], out);
}

int Profile::march_runs(Vec2 p0, Vec2 v0, double g, double t_max, int r, Contact& out) const {
  const ArcX ax(p0.x, v0.x);
  const int step = (v0.x > 0) == (main_direction_ > 0) ? 1 : -1;
  const int n_runs = static_cast<int>(runs_.size());
  for (int k = 0; k < kMarch; ++k) {
    r += step;
    if (r < 0 || r >= n_runs) return 0;
    const Run& run = runs_[r];
    double t, along;
    if (line_root(p0, v0, g, ax, t_max, run.a, run.n, run.d, run.length, run.x_lo, run.x_hi, 0,
                  false, t, along)) {
      out = run.end - run.begin == 1 ? Contact{t, run.begin, along}
                                     : contact_on_line(run.a, run.d, run.begin, run.end, t, along);
      return 1;
    }
  }
  return -1;
}

Contact Profile::contact_on_line(Vec2 a, Vec2 d, int first, int last, double t,
                                 double along) const {
  // The last segment whose start is at or before `along`. The starts rise with the index, so
  // there is one such segment however it is found. (The first starts at a: at 0.)
  auto starts_before = [&](int k) { return dot(segments_[k].a - a, d) <= along; };
  int lo = first, hi = last - 1;
  if (hi > lo) {
    // A line cut into equal pieces (a digitised straight slope) has it at the share along/total
    // of the pieces: look there first, and bisect only what is left.
    const double total = dot(segments_[last - 1].b - a, d);
    const int guess =
        first + std::clamp(static_cast<int>(along / total * (last - first)), 0, last - 1 - first);
    if (starts_before(guess)) {
      lo = guess;
      if (guess < hi && !starts_before(guess + 1)) hi = guess;
    } else {
      hi = guess - 1;
      if (starts_before(hi)) lo = hi;
    }
  }
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (starts_before(mid)) lo = mid; else hi = mid - 1;
  }
  const Segment& sj = segments_[lo];
  return {t, lo, std::clamp(along - dot(sj.a - a, d), 0.0, sj.length)};
}

[[gnu::noinline]] std::optional<Contact> Profile::first_contact_search(
    Vec2 p0, Vec2 v0, double g, double t_max, const Departure& dep, int under) const {
  ArcSearch as{p0, v0, g, ArcX(p0.x, v0.x), dep, t_max};

  // A straight run of collinear segments is one line for the search; the segment hit is then
  // found by bisection along it. (A finely digitised straight face costs what one segment does.)
  auto test_line = [&](Vec2 a, Vec2 d, Vec2 n, double length, double x_lo, double x_hi,
                       int first, int last) {
    double t, along;
    if (!as.solve(a, n, d, length, x_lo, x_hi, as.kind_of(first, last), t, along)) return;
    as.t_best = t;
    as.best = contact_on_line(a, d, first, last, t, along);
    as.found = true;
  };
  auto test_run = [&](const Run& r) {
    test_line(r.a, r.d, r.n, r.length, r.x_lo, r.x_hi, r.begin, r.end);
  };
  auto test_range = [&](int first, int last) {  // collinear segments [first, last)
    const Segment& s0 = segments_[first];
    const Vec2 end = segments_[last - 1].b;
    test_line(s0.a, s0.d, s0.n, dot(end - s0.a, s0.d), std::min(s0.a.x, end.x),
              std::max(s0.a.x, end.x), first, last);
  };

  // Best-first walk of a subtree: the child the block reaches first is visited first, and a
  // node is skipped when the arc cannot meet its segments before the best contact so far.
  auto search = [&](int root) {
    int stack[128];
    int top = 0;
    stack[top++] = root;
    while (top > 0) {
      const Node& nd = nodes_[stack[--top]];
      double ta, tb;
      if (!as.ax.window(nd.x_lo - kEps, nd.x_hi + kEps, as.t_best, ta, tb)) continue;
      // q(t) = z(t) − chord(x(t)) is a concave quadratic: a contact needs q in [off_lo, off_hi].
      const double q0 = p0.z - nd.icpt - nd.slope * p0.x, q1 = v0.z - nd.slope * v0.x;
      // An endless window (a vertical flight searched without a time limit) ends far below
      // everything: g > 0. (Evaluated, q(∞) is NaN when q1 ≥ 0 and skipped every node.)
      auto q = [&](double t) { return t < kInf ? q0 + q1 * t - 0.5 * g * t * t : -kInf; };
      if (std::min(q(ta), q(tb)) > nd.off_hi + kEps) continue;  // lowest at an end
      if (q(std::clamp(q1 / g, ta, tb)) < nd.off_lo - kEps) continue;
      if (nd.straight) {
        test_range(nd.first, nd.last);
        continue;
      }
      if (nd.left < 0) {
        for (int j = nd.first; j < nd.last; ++j)
          if (!as.departs_from(j)) as.test_segment(segments_[j], j);  // tested first
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
  };
  auto result = [&]() -> std::optional<Contact> {
    if (!as.found) return std::nullopt;
    return as.best;
  };

  // The segments departed from first: a concave neighbour may be entered at once.
  int ahead_seed = -1, behind_seed = -1;  // furthest and nearest departure segment by index
  for (int k = 0; k < 2; ++k) {
    const int j = dep.segment[k];
    if (j < 0) continue;
    as.test_segment(segments_[j], j);
    ahead_seed = std::max(ahead_seed, j);
    behind_seed = behind_seed < 0 ? j : std::min(behind_seed, j);
  }
  if (!x_monotone_ || v0.x == 0.0) {
    search(0);
    return result();
  }
  if (ahead_seed < 0) {
    // No departure (a flight from a source): start the march at the segment under the block.
    const int lo = under >= 0 ? under : segment_under(p0.x);
    as.test_segment(segments_[lo], lo);
    ahead_seed = behind_seed = lo;
  }
  // On a section without overhangs x grows with the segment index (times main_direction),
  // and along a flight x changes monotonically with time: the first contact is in the
  // departure's run or in the nearest runs beyond it, so the first contact found going run by
  // run is the earliest. Most hops land within a few runs: test them in order first, and
  // only then climb the tree from the last one's leaf, searching only the subtrees ahead.
  // A run of collinear segments is one line (the departure's own run included: its other
  // pieces lie on the departed line too).
  const bool ahead_is_right = (v0.x > 0) == (main_direction_ > 0);
  const int step = ahead_is_right ? 1 : -1;
  const int n_runs = static_cast<int>(runs_.size());
  int r = run_of_[ahead_is_right ? ahead_seed : behind_seed];
  if (runs_[r].end - runs_[r].begin > 1) test_run(runs_[r]);
  for (int k = 0; k < kMarch && !as.found; ++k) {
    r += step;
    if (r < 0 || r >= n_runs) break;
    const Run& run = runs_[r];
    if (run.end - run.begin > 1) {
      test_run(run);
    } else if (!as.departs_from(run.begin)) {
      double t, along;  // a one-segment run is its segment
      if (as.solve(run.a, run.n, run.d, run.length, run.x_lo, run.x_hi, 0, t, along)) {
        as.t_best = t;
        as.best = {t, run.begin, along};
        as.found = true;
      }
    }
  }
  if (as.found) return as.best;
  if (r < 0 || r >= n_runs) return std::nullopt;
  int node = leaf_of_[ahead_is_right ? runs_[r].end - 1 : runs_[r].begin];
  search(node);
  while (!as.found && node != 0) {
    const int parent = parents_[node];
    const Node& pn = nodes_[parent];
    if (ahead_is_right && pn.left == node) search(pn.right);
    if (!ahead_is_right && pn.right == node) search(pn.left);
    node = parent;
  }
  return result();
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

double Profile::max_height_above_ground(Vec2 p0, Vec2 v0, double g, double t_end,
                                        double at_least, int seg_a, int seg_b) const {
  // The commonest arc: departing from and landing on one straight run. The ground under it is
  // that line, and h(t) = z(t) − line(x(t)) is a concave quadratic: its maximum is at the
  // stationary point clamped to the part of the arc above the run.
  if (x_monotone_ && v0.x != 0.0 && seg_a >= 0 && seg_b >= 0 && run_of_[seg_a] == run_of_[seg_b]) {
    const Run& run = runs_[run_of_[seg_a]];
    const double best = std::max(0.0, at_least);
    double sa, sb;
    if (run.d.x == 0.0 || !ArcX(p0.x, v0.x).window(run.x_lo, run.x_hi, t_end, sa, sb)) return best;
    const double t_star = std::clamp((v0.z - v0.x * run.slope) / g, sa, sb);
    const double x = p0.x + v0.x * t_star;
    const double z = p0.z + v0.z * t_star - 0.5 * g * t_star * t_star;
    return std::max(best, z - (run.a.z + (x - run.a.x) * run.slope));
  }
  // A short hop over a few runs (down a face), without the general search's set-up.
  if (x_monotone_ && v0.x != 0.0 && seg_b >= 0) {
    const int from = seg_a >= 0 ? seg_a : segment_under(p0.x);  // from a source: as the contact search
    const int r_lo = run_of_[std::min(from, seg_b)], r_hi = run_of_[std::max(from, seg_b)];
    if (r_hi - r_lo < 2 * kMarch)
      return max_height_runs(p0, v0, g, t_end, std::max(0.0, at_least), r_lo, r_hi);
    return max_height_search(p0, v0, g, t_end, at_least, from, seg_b);
  }
  return max_height_search(p0, v0, g, t_end, at_least, seg_a, seg_b);
}

[[gnu::noinline]] double Profile::max_height_runs(Vec2 p0, Vec2 v0, double g, double t_end,
                                                  double best, int r_lo, int r_hi) const {
  // Without overhangs the ground under the arc is exactly the runs between those under its two
  // ends, each one line: h(t) = z(t) − line(x(t)) is a concave quadratic on each, its maximum
  // over the part of the arc above the run at the stationary point or an end.
  auto z_at = [&](double t) { return p0.z + v0.z * t - 0.5 * g * t * t; };
  const ArcX ax(p0.x, v0.x);
  for (int r = r_lo; r <= r_hi; ++r) {
    const Run& run = runs_[r];
    double sa, sb;
    if (run.d.x == 0.0 || !ax.window(run.x_lo, run.x_hi, t_end, sa, sb)) continue;
    const double t_star = std::clamp((v0.z - v0.x * run.slope) / g, sa, sb);
    const double x = p0.x + v0.x * t_star;
    best = std::max(best, z_at(t_star) - (run.a.z + (x - run.a.x) * run.slope));
  }
  return best;
}

[[gnu::noinline]] double Profile::max_height_search(Vec2 p0, Vec2 v0, double g, double t_end,
                                                    double at_least, int seg_a,
                                                    int seg_b) const {
  auto z_at = [&](double t) { return p0.z + v0.z * t - 0.5 * g * t * t; };
  if (v0.x == 0.0) {  // vertical drop: one ground point under the whole arc
    const double t_apex = std::clamp(v0.z / g, 0.0, t_end);
    const auto ground = ground_below(p0.x, p0.z);
    return std::max(at_least, ground ? z_at(t_apex) - ground->z : 0.0);
  }
  if (x_monotone_ && seg_a < 0 && seg_b >= 0) {
    seg_a = segment_under(p0.x);  // a flight from a source (as the contact search finds it)
  }
  double best = std::max(0.0, at_least);
  const ArcX ax(p0.x, v0.x);
  // Under overhangs a segment is the ground below only where nothing lies between, and where
  // that is changes only at the x of another segment's vertex (a flight crosses no segment).
  // So the part of the arc above segment j is cut at those x; on each piece where j is the
  // ground below (looked up at the piece's middle), h is concave and maximised exactly.
  auto visible_max = [&](int j, double sa, double sb) {
    std::vector<double> cuts;
    const Segment& s = segments_[j];
    const double slope = s.d.z / s.d.x;
    const double xa = p0.x + v0.x * sa, xb = p0.x + v0.x * sb;
    const double lo_x = std::min(xa, xb), hi_x = std::max(xa, xb);
    cuts.assign({sa, sb});  // (overhangs only: the allocation never touches the common paths)
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& nd = nodes_[stack[--top]];
      if (nd.x_hi <= lo_x || nd.x_lo >= hi_x) continue;
      if (nd.left >= 0) {
        stack[top++] = nd.left;
        stack[top++] = nd.right;
        continue;
      }
      for (int k = nd.first; k < nd.last; ++k)
        for (const double vx : {segments_[k].a.x, segments_[k].b.x})
          if (vx > lo_x && vx < hi_x) cuts.push_back(ax.inv * (vx - p0.x));
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double ta = cuts[i], tb = cuts[i + 1];
      if (!(tb > ta)) continue;
      const double tm = 0.5 * (ta + tb);
      const double xm = p0.x + v0.x * tm;
      const auto ground = ground_below(xm, z_at(tm));
      if (!ground ||
          std::abs(ground->z - (s.a.z + (xm - s.a.x) * slope)) > kEps * (1 + std::abs(ground->z)))
        continue;  // another surface lies between here
      const double t = std::clamp((v0.z - v0.x * slope) / g, ta, tb);
      const double x = p0.x + v0.x * t;
      best = std::max(best, z_at(t) - (s.a.z + (x - s.a.x) * slope));
    }
  };

  // Upper bound of h over a node: the arc's highest point over the node's window minus the
  // node's lowest ground; -inf when the arc does not pass over the node.
  // Without overhangs the ground under the arc is exactly the segments between those under its
  // two ends: nodes outside that index range are skipped without a look.
  int lo = 0, hi = static_cast<int>(segments_.size()) - 1;
  if (x_monotone_ && seg_a >= 0 && seg_b >= 0) {
    lo = std::min(seg_a, seg_b);
    hi = std::max(seg_a, seg_b);
  }
  // (A short hop without overhangs, over fewer than 2·kMarch runs, never comes here: see
  // max_height_runs.) h(t) = z(t) − ground(x(t)) is a concave quadratic on each segment: its
  // maximum over the part of the arc above the segment is at the stationary point or an end.
  auto bound = [&](const Node& nd) {
    if (nd.last <= lo || nd.first > hi) return -kInf;
    double ta, tb;
    if (!ax.window(nd.x_lo, nd.x_hi, t_end, ta, tb)) return -kInf;
    // h ≤ q(t) − off_lo with q(t) = z(t) − chord(x(t)), a concave quadratic.
    const double q0 = p0.z - nd.icpt - nd.slope * p0.x, q1 = v0.z - nd.slope * v0.x;
    const double t = std::clamp(q1 / g, ta, tb);
    return q0 + q1 * t - 0.5 * g * t * t - nd.off_lo;
  };
  struct Item {
    int node;
    double bound;
  };
  // Start at the smallest subtree that holds the whole range (found by climbing from the
  // leaf of its first segment): a short hop then never looks at the top of the tree.
  int start = 0;
  if (lo > 0 || hi < static_cast<int>(segments_.size()) - 1) {
    start = leaf_of_[lo];
    while (start != 0 && nodes_[start].last <= hi) start = parents_[start];
  }
  Item stack[128];
  int top = 0;
  stack[top++] = {start, bound(nodes_[start])};
  while (top > 0) {
    const Item it = stack[--top];
    if (it.bound <= best) continue;  // cannot beat the best so far
    const Node& nd = nodes_[it.node];
    if (nd.straight && x_monotone_) {  // the ground is the chord itself: the bound is the value
      best = it.bound;
      continue;
    }
    if (nd.left >= 0) {
      // Best first: the child with the larger bound is popped first, so `best` rises early
      // and most of the other nodes are cut.
      const Item l{nd.left, bound(nodes_[nd.left])}, r{nd.right, bound(nodes_[nd.right])};
      if (l.bound > r.bound) {
        stack[top++] = r;
        stack[top++] = l;
      } else {
        stack[top++] = l;
        stack[top++] = r;
      }
      continue;
    }
    for (int j = std::max(nd.first, lo); j < std::min(nd.last, hi + 1); ++j) {
      const Segment& s = segments_[j];
      if (s.d.x == 0.0) continue;
      double sa, sb;
      if (!ax.window(s.x_lo, s.x_hi, t_end, sa, sb)) continue;
      // h(t) = z(t) - ground(x(t)) is a concave quadratic on this segment.
      const double slope = s.d.z / s.d.x;
      const double t_star = std::clamp((v0.z - v0.x * slope) / g, sa, sb);
      const double x = p0.x + v0.x * t_star;
      const double h = z_at(t_star) - (s.a.z + (x - s.a.x) * slope);
      if (h <= best) continue;
      if (x_monotone_) {
        best = h;
      } else {
        visible_max(j, sa, sb);
      }
    }
  }
  return best;
}

}  // namespace pierre::geometry
