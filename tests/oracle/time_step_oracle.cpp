// The time-stepping oracle (see the header). Written to be read against the thesis, not to be
// fast: one loop, one fixed step, every decision a plain comparison.
#include "oracle/time_step_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pierre/sim/random_stream.hpp"

namespace pierre::oracle {
namespace {

using geometry::Segment;
using geometry::Vec2;

// A vertex where the direction changes by less than this is not an event (model-2d.md §2).
constexpr double kStraightAngle = 1e-9;

Vec2 lerp(Vec2 a, Vec2 b, double f) { return a + f * (b - a); }

// Elevation of segment s at x (the top of a vertical segment).
double segment_z(const Segment& s, double x) {
  if (s.b.x == s.a.x) return std::max(s.a.z, s.b.z);
  return s.a.z + (x - s.a.x) / (s.b.x - s.a.x) * (s.b.z - s.a.z);
}

bool covers(const Segment& s, double x) { return s.x_lo <= x && x <= s.x_hi; }

// The top ground elevation at x, by a plain scan over the segments. On a profile without
// overhangs the segments' x-ranges follow their index, so the scan starts from the segment found
// last time and walks to the one under x (the block moves a few millimetres per step); with an
// overhang every segment is looked at.
class Ground {
 public:
  explicit Ground(const geometry::Profile& p) : p_(p) {
    for (const Segment& s : p.segments())
      if (s.d.x * p.main_direction() < 0) monotone_ = false;
  }

  struct Hit {
    double z = -std::numeric_limits<double>::infinity();
    int segment = -1;
  };

  // False when x lies outside the profile.
  bool at(double x, Hit& out) {
    out = Hit{};
    if (x < p_.x_min() || x > p_.x_max()) return false;
    const int n = static_cast<int>(p_.segment_count());
    if (!monotone_) {
      for (int i = 0; i < n; ++i) consider(i, x, out);
      return out.segment >= 0;
    }
    int i = hint_;
    while (!covers(p_.segment(i), x)) {
      // Towards the segments with smaller x, or larger x.
      const bool go_up_in_x = x > p_.segment(i).x_hi;
      i += (go_up_in_x == (p_.main_direction() > 0)) ? 1 : -1;
    }
    hint_ = i;
    // At a vertex (or on a vertical segment) the neighbours cover x as well: take the highest.
    for (int k = i; k >= 0 && covers(p_.segment(k), x); --k) consider(k, x, out);
    for (int k = i + 1; k < n && covers(p_.segment(k), x); ++k) consider(k, x, out);
    return true;
  }

 private:
  void consider(int i, double x, Hit& out) const {
    const Segment& s = p_.segment(i);
    if (!covers(s, x)) return;
    const double z = segment_z(s, x);
    if (z > out.z) out = Hit{z, i};
  }

  const geometry::Profile& p_;
  bool monotone_ = true;
  int hint_ = 0;
};

enum class Mode { flight, sliding, stopped };

class Stepper {
 public:
  Stepper(const sim::Scenario& sc, std::uint64_t index, const OracleOptions& opt)
      : sc_(sc),
        prof_(sc.profile),
        set_(sc.settings),
        g_(sc.settings.gravity),
        dt_(opt.dt),
        record_(opt.record_impacts),
        ground_(sc.profile),
        law_(sc.settings.roughness, sc.settings.stop_head_factor, sc.settings.gravity),
        rng_(sc.settings.seed, index) {
    const sim::TrajectoryKey key = sim::trajectory_key(sc, index);
    const sim::Source& src = sc.sources[key.source];
    blk_ = law_.block(sc.blocks[key.block]);
    for (const auto& m : sc.materials) surfaces_.push_back(law_.surface(m));
    p_ = src.position;
    v_ = src.velocity;
    omega_ = src.omega;
    seen_.assign(sc.lines.size(), false);
    Ground lines_ground(prof_);
    for (const auto& l : sc.lines) {
      Ground::Hit h;
      lines_ground.at(l.x, h);
      line_ground_.push_back(h.z);
    }
  }

  OracleResult run() {
    out_.start = p_;
    Ground::Hit h;
    if (!ground_.at(p_.x, h)) {
      stop(sim::StopReason::boundary);
    } else if (p_.z > h.z) {
      mode_ = Mode::flight;  // above the ground: starts in flight (§3.2.1)
    } else {
      p_.z = h.z;  // on or below: placed on the ground, starts sliding (§3.2.2)
      out_.start = p_;
      enter_ground(h.segment, v_);
    }
    while (mode_ != Mode::stopped) {
      ++out_.steps;
      if (mode_ == Mode::flight)
        flight_step();
      else
        slide_step();
    }
    out_.stop = p_;
    out_.duration = t_;
    return std::move(out_);
  }

 private:
  void stop(sim::StopReason r) {
    out_.stop_reason = r;
    mode_ = Mode::stopped;
  }

  // One flight step: p += v dt − ½ g dt² ẑ, v_z −= g dt. Below the ground → revert and impact.
  void flight_step() {
    if (t_ >= set_.max_time) return stop(sim::StopReason::time_limit);
    const Vec2 p1{p_.x + v_.x * dt_, p_.z + v_.z * dt_ - 0.5 * g_ * dt_ * dt_};
    const Vec2 v1{v_.x, v_.z - g_ * dt_};
    if (!std::isfinite(p1.x) || !std::isfinite(p1.z)) return stop(sim::StopReason::numerical);
    Ground::Hit h;
    if (p1.x < prof_.x_min() || p1.x > prof_.x_max()) {
      // The step leaves the profile: where does it pass the end?
      const double xb = p1.x < prof_.x_min() ? prof_.x_min() : prof_.x_max();
      const double f = (xb - p_.x) / (p1.x - p_.x);
      const Vec2 pb = lerp(p_, p1, f);
      ground_.at(xb, h);
      if (pb.z >= h.z) {
        path(p_, v_, pb, lerp(v_, v1, f), f * dt_, false);
        p_ = pb;
        t_ += f * dt_;
        return stop(sim::StopReason::boundary);
      }
      return impact(h.segment, v_, ImpactKind::penetration);  // through the end segment first
    }
    ground_.at(p1.x, h);
    if (p1.z < h.z) {
      // §3.3: "the position of the particle is reverted back to its position at the previous
      // time step so that the particle is just above the ground surface". p_ and v_ stay (the
      // velocity of the state reverted to), the segment is the one under the penetration point.
      return impact(h.segment, v_, ImpactKind::penetration);
    }
    path(p_, v_, p1, v1, dt_, false);
    p_ = p1;
    v_ = v1;
    t_ += dt_;
  }

  // One sliding step along segment seg_ (Eq 3.3 with constant acceleration over the step).
  void slide_step() {
    const Segment& s = prof_.segment(seg_);
    const double tan_phi = surfaces_[s.material].tan_phi;
    const double g_along = -g_ * s.d.z;             // gravity along d
    const double friction = g_ * s.n.z * tan_phi;   // friction deceleration, n_z > 0 here
    if (std::abs(w_) > set_.max_sliding_speed)      // too fast to slide: forced into flight
      return impact(seg_, w_ * s.d, ImpactKind::launch);
    if (w_ == 0.0 && std::abs(g_along) <= friction) return stop(sim::StopReason::friction);
    if (t_ >= set_.max_time) return stop(sim::StopReason::time_limit);
    const double dir = w_ != 0.0 ? (w_ > 0 ? 1.0 : -1.0) : (g_along > 0 ? 1.0 : -1.0);
    const double acc = g_along - dir * friction;  // friction opposes the motion

    double h = dt_;
    double w1 = w_ + acc * h;
    bool rest = false;
    if (acc * dir < 0 && w1 * dir <= 0) {  // the speed reaches zero within this step
      h = -w_ / acc;
      w1 = 0.0;
      rest = true;
    }
    const double along1 = along_ + w_ * h + 0.5 * acc * h * h;
    const Vec2 v0 = w_ * s.d;
    if (dir > 0 ? along1 >= s.length : along1 <= 0.0) {  // passes the end of the segment
      const Vec2 end = dir > 0 ? s.b : s.a;
      path(p_, v0, end, w1 * s.d, h, true);
      t_ += h;
      p_ = end;
      along_ = dir > 0 ? s.length : 0.0;
      w_ = w1;  // the speed at the end of the step: at most one step's change off
      v_ = w_ * s.d;
      return vertex(dir > 0 ? 1 : -1);
    }
    const Vec2 p1 = s.a + along1 * s.d;
    path(p_, v0, p1, w1 * s.d, h, true);
    t_ += h;
    p_ = p1;
    along_ = along1;
    w_ = w1;
    v_ = w_ * s.d;
    if (rest && !count_event()) return;  // at rest: the next step stops or restarts downslope
  }

  // The block slid to the end of seg_ moving in direction dir (±1 in segment order).
  void vertex(int dir) {
    const int next = seg_ + dir;
    if (next < 0 || next >= static_cast<int>(prof_.segment_count()))
      return stop(sim::StopReason::boundary);
    const Segment& ns = prof_.segment(next);
    const int first = std::min(seg_, next);
    const Vec2 d0 = prof_.segment(first).d, d1 = prof_.segment(first + 1).d;
    const double turn = std::atan2(cross(d0, d1), dot(d0, d1));  // > 0: concave (turns to the air)
    if (std::abs(turn) < kStraightAngle && ns.n.z > 0.0) {     // no event: carry on
      seg_ = next;
      along_ = dir > 0 ? 0.0 : ns.length;
      return;
    }
    if (!count_event()) return;
    if (turn > 0) return impact(next, v_, ImpactKind::vertex);  // concave: hits the next segment
    // Convex: the next segment is steeper, a point mass flies off the vertex.
    if (w_ == 0.0) return enter_ground(next, v_);
    mode_ = Mode::flight;
  }

  bool count_event() {
    if (++events_ > set_.max_impacts) {
      stop(sim::StopReason::impact_limit);
      return false;
    }
    return true;
  }

  // An impact on segment j with incident velocity v at the current point.
  void impact(int j, Vec2 v, ImpactKind kind) {
    if (!count_event()) return;
    if (!out_.has_first_impact) {
      out_.has_first_impact = true;
      out_.first_impact = p_;
    }
    const Segment& s = prof_.segment(j);
    const model::ImpactDraws draws = rng_.impact_draws();
    OracleImpact rec;
    const model::ImpactOutcome res =
        law_.resolve(v, omega_, s, surfaces_[s.material], blk_, draws, record_ ? &rec.detail : nullptr);
    ++out_.impacts;
    if (record_) {
      rec.time = t_;
      rec.position = p_;
      rec.segment = j;
      rec.v_in = v;
      rec.omega_in = omega_;
      rec.kind = kind;
      rec.result = res.result;
      out_.impact_log.push_back(rec);
    }
    v_ = res.v;
    omega_ = res.omega;
    if (!std::isfinite(v_.x) || !std::isfinite(v_.z) || !std::isfinite(omega_))
      return stop(sim::StopReason::numerical);
    switch (res.result) {
      case model::ImpactResult::stopped:
        return stop(sim::StopReason::energy);
      case model::ImpactResult::sliding:
        return enter_ground(j, v_);
      case model::ImpactResult::rebound:
        mode_ = Mode::flight;
        return;
    }
  }

  // Onto segment j with velocity v: slide along it where its normal points up, else fall
  // along the face.
  void enter_ground(int j, Vec2 v) {
    const Segment& s = prof_.segment(j);
    if (s.n.z <= 0.0) {
      v_ = v - dot(v, s.n) * s.n;
      mode_ = Mode::flight;
      return;
    }
    seg_ = j;
    along_ = std::clamp(dot(p_ - s.a, s.d), 0.0, s.length);
    p_ = s.a + along_ * s.d;
    w_ = dot(v, s.d);
    v_ = w_ * s.d;
    mode_ = Mode::sliding;
  }

  // The block moved from p0 to p1 in one step: the first crossing of each observation line in
  // the main direction, by linear interpolation between the two. h: the piece's duration.
  void path(Vec2 p0, Vec2 v0, Vec2 p1, Vec2 v1, double h, bool sliding) {
    const int md = prof_.main_direction();
    for (std::size_t i = 0; i < seen_.size(); ++i) {
      if (seen_[i]) continue;
      const double xc = sc_.lines[i].x;
      const bool crosses = md > 0 ? (p0.x < xc && xc <= p1.x) : (p0.x > xc && xc >= p1.x);
      if (!crosses) continue;
      const double f = (xc - p0.x) / (p1.x - p0.x);
      OracleCrossing c;
      c.line = static_cast<std::uint32_t>(i);
      c.time = t_ + f * h;
      c.velocity = lerp(v0, v1, f);
      c.speed = norm(c.velocity);
      c.height = lerp(p0, p1, f).z - line_ground_[i];
      c.sliding = sliding;
      out_.crossings.push_back(c);
      seen_[i] = true;
    }
  }

  const sim::Scenario& sc_;
  const geometry::Profile& prof_;
  const sim::SimulationSettings& set_;
  const double g_;
  const double dt_;
  const bool record_;
  Ground ground_;
  model::ImpactLaw law_;
  sim::RandomStream rng_;
  model::BlockConstants blk_;
  std::vector<model::SurfaceConstants> surfaces_;
  std::vector<double> line_ground_;
  std::vector<bool> seen_;
  OracleResult out_;

  Mode mode_ = Mode::flight;
  Vec2 p_, v_;
  double omega_ = 0, t_ = 0;
  int seg_ = -1;      // sliding: the segment
  double along_ = 0;  // sliding: distance from its start vertex
  double w_ = 0;      // sliding: signed speed along the segment direction
  long events_ = 0;   // impacts, vertex and rest events, against the limit
};

}  // namespace

OracleResult simulate_time_step(const sim::Scenario& scenario, std::uint64_t index,
                                const OracleOptions& options) {
  return Stepper(scenario, index, options).run();
}

}  // namespace pierre::oracle
