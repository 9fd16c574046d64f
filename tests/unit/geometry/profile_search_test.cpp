// The accelerated searches of Profile (fast paths for a bounce on one segment, the march over
// straight runs, the tree) against a brute-force reference written here from the definitions:
// every segment's quadratic solved on its own, every ground point found by a linear scan. Random
// sections with and without overhangs, collinear runs and vertical steps; random arcs from the
// air and from a departure. A wrong skip in any acceleration shows as a later contact, another
// segment or a lower jump height.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "pierre/geometry/profile.hpp"

using namespace pierre::geometry;

namespace {

constexpr double g = 9.81;
constexpr double kInf = std::numeric_limits<double>::infinity();

Vec2 at(Vec2 p0, Vec2 v0, double t) { return {p0.x + v0.x * t, p0.z + v0.z * t - 0.5 * g * t * t}; }

// Earliest time in (0, t_max) at which the parabola enters any segment from its air side.
// Segments in `departed` pass through p0 (c = 0): their root t = 0 is the departure itself.
struct Hit {
  double t = kInf;
  int segment = -1;
};
Hit brute_contact(const Profile& p, Vec2 p0, Vec2 v0, double t_max, const Departure& dep) {
  Hit best;
  for (std::size_t j = 0; j < p.segment_count(); ++j) {
    const Segment& s = p.segment(j);
    const bool departed = dep.segment[0] == int(j) || dep.segment[1] == int(j);
    const bool tangent = (dep.segment[0] == int(j) && dep.tangent[0]) ||
                         (dep.segment[1] == int(j) && dep.tangent[1]);
    if (tangent) continue;
    const double a = -0.5 * g * s.n.z, b = dot(v0, s.n);
    const double c = departed ? 0.0 : dot(p0 - s.a, s.n);
    std::vector<double> roots;
    if (departed) {
      if (a != 0.0) roots.push_back(-b / a);
    } else if (a == 0.0) {
      if (b != 0.0) roots.push_back(-c / b);
    } else {
      const double disc = b * b - 4 * a * c;
      if (disc < 0) continue;
      roots.push_back((-b - std::sqrt(disc)) / (2 * a));
      roots.push_back((-b + std::sqrt(disc)) / (2 * a));
    }
    for (double t : roots) {
      if (!(t > 1e-12) || t >= t_max || t >= best.t) continue;
      if (!(b + 2 * a * t < 0.0)) continue;  // entering from the air side
      const double along = dot(at(p0, v0, t) - s.a, s.d);
      if (along < -1e-9 || along > s.length + 1e-9) continue;
      best = {t, int(j)};
    }
  }
  return best;
}

// Highest ground point at or below (x, z) by a linear scan.
std::optional<double> brute_ground(const Profile& p, double x, double z) {
  std::optional<double> best;
  for (const Segment& s : p.segments()) {
    if (s.d.x == 0.0 || x < s.x_lo || x > s.x_hi) continue;
    const double zs = s.a.z + (x - s.a.x) * s.d.z / s.d.x;
    if (zs <= z + 1e-9 && (!best || zs > *best)) best = zs;
  }
  return best;
}

// A random section: x advances (or, with overhangs, sometimes steps back under a ledge),
// z falls on the whole with rises, level stretches, collinear subdivisions and vertical steps.
std::optional<Profile> random_profile(std::mt19937_64& rng, int vertices, bool overhangs) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> pts{{0.0, 100.0}};
  while (int(pts.size()) < vertices) {
    const Vec2 last = pts.back();
    const double kind = u(rng);
    if (kind < 0.1) {  // a vertical step down
      pts.push_back({last.x, last.z - 1 - 4 * u(rng)});
    } else if (kind < 0.25 && pts.size() >= 2) {  // collinear pieces continuing the last segment
      const Vec2 d = last - pts[pts.size() - 2];
      const int pieces = 2 + int(4 * u(rng));
      const double scale = 0.3 + u(rng);
      for (int k = 1; k <= pieces; ++k) pts.push_back(last + (scale * k / pieces) * d);
    } else if (kind < 0.3 && overhangs && pts.size() >= 2) {  // a ledge: out, back under, down
      pts.push_back({last.x + 3, last.z});
      pts.push_back({last.x + 1, last.z - 2});
      pts.push_back({last.x + 4, last.z - 6});
    } else {
      const double dx = 0.5 + 8 * u(rng);
      const double slope = -1.5 + 1.9 * u(rng);  // mostly down, some rises
      pts.push_back({last.x + dx, last.z + slope * dx});
    }
  }
  return Profile::build(pts, std::vector<int>(pts.size() - 1, 0), nullptr);
}

}  // namespace

TEST(ProfileSearch, FirstContactAgreesWithBruteForceOnRandomSections) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int arcs = 0, departures = 0, hits = 0;
  for (int prof = 0; prof < 120; ++prof) {
    const bool overhangs = prof % 3 == 2;
    const int n = prof % 4 == 0 ? 300 : 4 + prof % 40;
    const auto p = random_profile(rng, n, overhangs);
    if (!p) continue;  // a ledge that crossed the section: not a valid profile
    for (int k = 0; k < 200; ++k) {
      Departure dep;
      Vec2 p0, v0{-12 + 30 * u(rng), -5 + 20 * u(rng)};
      if (k % 2 == 0) {  // from the air, above the ground
        const double x = p->x_min() + (p->x_max() - p->x_min()) * u(rng);
        const auto top = p->top_ground(x);
        if (!top) continue;
        p0 = {x, top->z + 0.05 + 10 * u(rng)};
      } else {  // departing from a segment, away from it
        const int j = int(u(rng) * p->segment_count());
        const Segment& s = p->segment(j);
        p0 = s.a + (0.05 + 0.9 * u(rng)) * s.length * s.d;
        if (dot(v0, s.n) <= 0) v0 = v0 - 2 * dot(v0, s.n) * s.n;
        dep.segment[0] = j;
        ++departures;
      }
      const double t_max = 1 + 20 * u(rng);
      const auto c = p->first_contact(p0, v0, g, t_max, dep);
      const Hit ref = brute_contact(*p, p0, v0, t_max, dep);
      ++arcs;
      ASSERT_EQ(c.has_value(), ref.segment >= 0) << "profile " << prof << " arc " << k;
      if (!c) continue;
      ++hits;
      ASSERT_NEAR(c->t, ref.t, 1e-9 * (1 + ref.t)) << "profile " << prof << " arc " << k;
      if (c->segment != ref.segment) {  // a tie at a shared vertex: the same point
        const Vec2 pc = at(p0, v0, c->t), pr = at(p0, v0, ref.t);
        EXPECT_LT(norm(pc - pr), 1e-7) << "profile " << prof << " arc " << k;
      }
      const Segment& s = p->segment(c->segment);
      EXPECT_NEAR(norm(s.a + c->s * s.d - at(p0, v0, c->t)), 0.0, 1e-7);
    }
  }
  // The sample must exercise every path: most arcs hit something, half depart from a segment.
  EXPECT_GT(arcs, 15000);
  EXPECT_GT(departures, 7000);
  EXPECT_GT(hits, arcs / 2);
}

TEST(ProfileSearch, MaxJumpHeightAgreesWithDenseSamplingOnRandomSections) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (int prof = 0; prof < 60; ++prof) {
    const auto p = random_profile(rng, prof % 4 == 0 ? 300 : 4 + prof % 40, prof % 3 == 2);
    if (!p) continue;
    for (int k = 0; k < 60; ++k) {
      // An arc from a departure to its first contact, as the simulator asks for it.
      const int j = int(u(rng) * p->segment_count());
      const Segment& s = p->segment(j);
      Vec2 v0{-12 + 30 * u(rng), -5 + 20 * u(rng)};
      if (dot(v0, s.n) <= 0) v0 = v0 - 2 * dot(v0, s.n) * s.n;
      const Vec2 p0 = s.a + (0.05 + 0.9 * u(rng)) * s.length * s.d;
      Departure dep;
      dep.segment[0] = j;
      const auto c = p->first_contact(p0, v0, g, 30.0, dep);
      if (!c || v0.x == 0.0) continue;
      const double h = p->max_height_above_ground(p0, v0, g, c->t, 0.0, j, c->segment);
      // Dense sampling from below: h(t) is piecewise concave with kinks at vertices, so the
      // sampled maximum is at most |h'| Δt below the true one.
      const int steps = 4000;
      double sampled = 0.0, slope_bound = 0.0;
      for (const Segment& q : p->segments())
        if (q.d.x != 0.0) slope_bound = std::max(slope_bound, std::abs(q.d.z / q.d.x));
      for (int i = 0; i <= steps; ++i) {
        const double t = c->t * i / steps;
        const Vec2 pt = at(p0, v0, t);
        if (const auto gz = brute_ground(*p, pt.x, pt.z)) sampled = std::max(sampled, pt.z - *gz);
      }
      const double dt = c->t / steps;
      const double tol = (std::abs(v0.z) + g * c->t + std::abs(v0.x) * slope_bound) * dt + 1e-9;
      ASSERT_GE(h, sampled - 1e-9) << "profile " << prof << " arc " << k << " p0 " << p0.x << ","
                                   << p0.z << " v0 " << v0.x << "," << v0.z << " seg " << j
                                   << " -> " << c->segment << " t " << c->t;
      ASSERT_LE(h, sampled + tol) << "profile " << prof << " arc " << k;
      // The running maximum passed in is returned when the arc cannot beat it.
      EXPECT_EQ(p->max_height_above_ground(p0, v0, g, c->t, h + 1.0, j, c->segment), h + 1.0);
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
}
