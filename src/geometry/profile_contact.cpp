// The profile's contact search (Profile::first_contact): the earliest root of a flight's
// parabola on the ground, exact (model-2d.md §2), by closed-form fast paths for the common hops
// and a search of the segment tree for the rest.
#include <algorithm>
#include <cmath>
#include <optional>

#include "pierre/geometry/profile.hpp"
#include "profile_arc.hpp"

namespace pierre::geometry {

using detail::ArcX;
using detail::kEps;
using detail::kInf;
using detail::kMarch;

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


}  // namespace pierre::geometry
