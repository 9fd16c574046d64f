// The jump height (Profile::max_height_above_ground, model-2d.md §4): the largest vertical
// distance between a flight's parabola and the ground below it, exact, by closed forms for the
// common hops and a best-first search of the segment tree for the rest.
#include <algorithm>
#include <vector>

#include "pierre/geometry/profile.hpp"
#include "profile_arc.hpp"

namespace pierre::geometry {

using detail::ArcX;
using detail::kEps;
using detail::kInf;
using detail::kMarch;

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
