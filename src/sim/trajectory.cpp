#include "pierre/sim/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pierre::sim {
namespace {

using geometry::Contact;
using geometry::Departure;
using geometry::Segment;
using geometry::Vec2;
using geometry::VertexTurn;

constexpr double kInf = std::numeric_limits<double>::infinity();
// A contact this close to a segment end is at the vertex: its neighbour is departed from too.
constexpr double kVertexSlack = 1e-9;
// Points drawn along one flight arc at most (see advance_flight).
constexpr double kMaxPathPointsPerArc = 1000;

// True when no value is infinite or NaN: x − x is 0 for a finite x and NaN otherwise, so one
// test of the sum does for all of them.
template <class... T>
bool all_finite(T... x) {
  return std::isfinite(((x - x) + ...));
}

enum class Mode { flight, sliding, stopped };

// The state of one block and the bookkeeping of its summary.
class Integrator {
 public:
  Integrator(const TrajectoryModel& m, std::uint64_t index, TrajectoryKey key,
             ObservationTally& tally, std::vector<ImpactRecord>* impacts, std::vector<Vec2>* path,
             double path_step, TrajectorySummary& out)
      : m_(m),
        sc_(m.scenario()),
        profile_(sc_.profile),
        set_(sc_.settings),
        g_(set_.gravity),
        tally_(tally),
        impacts_(impacts),
        path_(path),
        path_step_(path_step),
        rng_(m.random_key(), index),
        blk_(&m.block(key.block)),
        next_(m.law().sample(rng_.impact_draws(), *blk_)),
        out_(out),
        // 0.5·m is exact, so (0.5·m)·v² is the same number as the 0.5·m·v² it replaces.
        half_mass_(0.5 * blk_->mass),
        half_inertia_(0.5 * blk_->inertia),
        floor_from_(set_.floor_segment < 0 ? std::numeric_limits<int>::max() : set_.floor_segment) {
    const Source& src = sc_.sources[key.source];
    out_ = TrajectorySummary{};
    out_.trajectory = index;
    out_.source = key.source;
    out_.block = key.block;
    out_.throw_index = key.throw_index;
    out_.mass = blk_->mass;
    tally_.begin(index, key.block, blk_->mass, blk_->inertia);
    p_ = src.position;
    v_ = src.velocity;
    omega_ = src.omega;
    out_.start = p_;
  }

  void run() {
    start();
    if (path_) path_->push_back(p_);
    while (mode_ != Mode::stopped) {
      if (mode_ == Mode::flight)
        fly();
      else
        slide();
    }
    if (path_) path_->push_back(p_);
    out_.stop = p_;
    out_.duration = t_;
    out_.impacts = static_cast<std::uint32_t>(impacts_done_);
    out_.max_speed = std::sqrt(max_speed2_);
  }

 private:
  void stop(StopReason r) {
    out_.stop_reason = r;
    mode_ = Mode::stopped;
  }

  // The first contact with the floor (design-checks.md §2: ID), by impact or by sliding.
  void note_floor(int segment) {
    if (segment < floor_from_ || out_.has_floor_contact) return;
    out_.has_floor_contact = true;
    out_.floor_contact = p_;
  }

  // The largest squared speed is kept and its root taken once at the end: sqrt is monotone and
  // correctly rounded, so sqrt(max v²) is bit for bit max sqrt(v²), the norm of the old code.
  void note_speed(Vec2 v, double omega) {
    const double v2 = dot(v, v);
    const double e = half_mass_ * v2 + half_inertia_ * omega * omega;
    max_speed2_ = std::max(max_speed2_, v2);
    out_.max_energy = std::max(out_.max_energy, e);
  }

  void start() {
    // Where the source's blocks start was found once for the run (TrajectoryModel).
    const TrajectoryModel::SourceStart& st = m_.source_start(out_.source);
    using Kind = TrajectoryModel::SourceStart::Kind;
    if (st.kind == Kind::flight) {  // above the ground: starts in flight
      mode_ = Mode::flight;
      dep_ = Departure{};
      check_flight();
    } else if (st.kind == Kind::outside) {
      stop(StopReason::boundary);
    } else {
      // On or below the ground: placed on the ground, starts sliding (§3.2.2).
      p_.z = st.z;
      out_.start = p_;
      enter_ground(st.segment, v_);
    }
    // The speed it starts with: on the ground, what is left once the part into (or out of)
    // the ground is dropped.
    note_speed(v_, omega_);
  }

  // The block is on segment j at p_ with velocity v (tangential part kept): slide where the
  // normal points up, else fall along the face.
  void enter_ground(int j, Vec2 v) {
    const Segment& s = profile_.segment(j);
    if (s.n.z <= 0.0) {  // vertical or overhanging: no sliding, flight along the face
      v_ = v - dot(v, s.n) * s.n;
      mode_ = Mode::flight;
      // At the face's foot the ground beside it is departed from too, as from a rebound there:
      // a block that comes down the face enters it at once (its line, solved from coordinates,
      // could hold p_ a rounding below it, with no root, and the block fell through).
      depart(j, std::clamp(dot(p_ - s.a, s.d), 0.0, s.length));
      dep_.tangent[0] = true;
      return check_flight();
    }
    seg_ = j;
    note_floor(j);
    along_ = std::clamp(dot(p_ - s.a, s.d), 0.0, s.length);
    w_ = dot(v, s.d);
    v_ = w_ * s.d;
    mode_ = Mode::sliding;
  }

  // A flight starts only from a finite state (fly() relies on it): else the block stops here,
  // as the flight would have before it began. A rebound checks just its position (below).
  void check_flight() {
    if (!all_finite(p_.x, p_.z, v_.x, v_.z, omega_)) stop(StopReason::numerical);
  }

  void fly() {
    // When the block would leave the profile's horizontal extent, or run out of time.
    double t_leave = kInf;
    if (v_.x > 0) t_leave = (profile_.x_max() - p_.x) / v_.x;
    if (v_.x < 0) t_leave = (profile_.x_min() - p_.x) / v_.x;
    t_leave = std::max(t_leave, 0.0);
    const double t_left = set_.max_time - t_;
    // A wall that ends the profile stands at x_min or x_max itself, and is met at t_leave: the
    // search looks a hair beyond (kVertexSlack in x, and no more than kVertexSlack seconds for
    // a block that barely moves in x), so that the block hits it, not leaves.
    const double t_reach =
        v_.x != 0 ? t_leave + std::min(kVertexSlack / std::abs(v_.x), kVertexSlack) : kInf;
    const auto contact = profile_.first_contact(p_, v_, g_, std::min(t_reach, t_left), dep_);

    double tau;
    if (contact) {
      tau = contact->t;
    } else if (t_leave <= t_left) {
      tau = t_leave;
    } else if (t_leave < kInf || profile_.first_contact(p_, v_, g_, kInf, dep_)) {
      tau = t_left;  // the landing or the leaving lies beyond the time limit
    } else {
      return stop(StopReason::numerical);  // no contact and no way out: lost through the ground
    }
    // The segments under the arc's ends: where it departs (if on the ground) and lands.
    const int seg_from = dep_.segment[0];  // -1 when none
    const int seg_to = contact ? contact->segment : (v_.x * profile_.main_direction() > 0
                                                         ? static_cast<int>(profile_.segment_count()) - 1
                                                         : 0);
    advance_flight(tau, seg_from, seg_to);
    if (contact) {
      const Segment& s = profile_.segment(contact->segment);
      p_ = s.a + contact->s * s.d;  // snap onto the line the block hit
      impact(contact->segment, contact->s);
    } else if (!all_finite(p_.x, p_.z, v_.x, v_.z)) {
      // An arc beyond what a double holds (a gravity of 1e308): the contact search found no
      // root in its overflowed numbers, and the block did not leave, it was lost.
      stop(StopReason::numerical);
    } else if (tau == t_leave && t_leave <= t_left) {
      stop(StopReason::boundary);
    } else {
      stop(StopReason::time_limit);
    }
  }

  void advance_flight(double tau, int seg_from, int seg_to) {
    if (!tally_.empty()) tally_.flight(p_, v_, omega_, t_, tau, g_);
    if (path_) {
      // path_step_ apart, but no more than kMaxPathPointsPerArc: a drawing needs no more, and a
      // flight of days (a tiny gravity with a long max_time, both valid) asked for billions of
      // points (bad_alloc), or for more than an int holds (undefined behaviour).
      const double steps = std::ceil(tau / path_step_);
      const int n = steps > 1 ? static_cast<int>(std::min(steps, kMaxPathPointsPerArc)) : 1;
      for (int k = 1; k <= n; ++k) {
        const double t = tau * k / n;
        path_->push_back({p_.x + v_.x * t, p_.z + v_.z * t - 0.5 * g_ * t * t});
      }
    }
    out_.max_jump_height = profile_.max_height_above_ground(p_, v_, g_, tau, out_.max_jump_height,
                                                            seg_from, seg_to);
    p_ = {p_.x + v_.x * tau, p_.z + v_.z * tau - 0.5 * g_ * tau * tau};
    v_ = {v_.x, v_.z - g_ * tau};
    t_ += tau;
    note_speed(v_, omega_);  // a concave arc's speed is largest at one of its ends
  }

  bool count_event() {
    if (++events_ > set_.max_impacts) {
      stop(StopReason::impact_limit);
      return false;
    }
    return true;
  }

  // An impact from the ground (a launch, a concave vertex): rare, so one copy out of line,
  // while fly() has impact() inlined, without a call's register saves and restores.
  [[gnu::noinline]] void impact_from_ground(int j, double along) { impact(j, along); }

  // An impact on segment j at p_, `along` metres from its start vertex.
  [[gnu::always_inline]] void impact(int j, double along) {
    if (!count_event()) return;
    const Segment& s = profile_.segment(j);
    if (!out_.has_first_impact) {
      out_.has_first_impact = true;
      out_.first_impact = p_;
    }
    note_floor(j);
    ImpactRecord* rec = nullptr;  // the TR record, only when asked for
    if (impacts_) {
      rec = &impacts_->emplace_back();
      rec->trajectory = out_.trajectory;
      rec->index = static_cast<std::uint32_t>(impacts_done_);
      rec->time = t_;
      rec->position = p_;
      rec->segment = static_cast<std::uint32_t>(j);
    }
    const auto res = m_.law().resolve(v_, omega_, s, m_.surface(s.material), *blk_, next_,
                                      rec ? &rec->detail : nullptr);
    // The next impact's sample is made now: it needs only the stream, so the processor can
    // work it out while the coming flight's contact search waits on its own results. (Not
    // after the impact that stops the block, which is most trajectories' last.)
    if (res.result != model::ImpactResult::stopped) next_ = m_.law().sample(rng_.impact_draws(), *blk_);
    if (rec) rec->result = res.result;
    ++impacts_done_;
    v_ = res.v;
    omega_ = res.omega;
    if (!all_finite(v_.x, v_.z, omega_)) return stop(StopReason::numerical);
    // A rebound can leave faster than the block came (spin turned into translation), and the
    // arc after it may end slower: the rebound is one of the trajectory's speeds too.
    note_speed(v_, omega_);
    switch (res.result) {
      case model::ImpactResult::stopped: {
        // Said in the run's notes: tan β > tan φ, where sliding would not have stopped, on
        // ground falling onwards (not a counter-slope: sliding back ends short of here). A block
        // whose centre stops within its radius of a segment's end vertex rests on the next
        // segment too (one stopped a few centimetres up the face above the toe rests on the
        // floor): that one is the ground it is judged on. The physics is not touched.
        const bool at_end =
            along > s.length - blk_->radius && j + 1 < static_cast<int>(profile_.segment_count());
        const Segment& on = at_end ? profile_.segment(j + 1) : s;
        if (std::abs(on.d.z) > m_.surface(on.material).tan_phi * std::abs(on.d.x) &&
            !(on.d.z * on.d.x * profile_.main_direction() > 0))
          out_.steep_stop_tan = static_cast<float>(std::abs(on.d.z) / std::abs(on.d.x));
        return stop(StopReason::energy);
      }
      case model::ImpactResult::sliding:
        return enter_ground(j, v_);
      case model::ImpactResult::rebound:
        break;
    }
    // Rebound: flight departing from the segment, and from its neighbour at a vertex.
    mode_ = Mode::flight;
    depart(j, along);
    // The rebound's velocity and spin were checked above; its position is the contact's.
    if (!all_finite(p_.x, p_.z)) stop(StopReason::numerical);
  }

  // A flight leaves segment j `along` metres from its start vertex: the segment, and at a vertex
  // its neighbour, are departed from (model-2d.md §2); entering the neighbour at a concave vertex
  // is a contact at once (profile_contact.cpp, line_root).
  void depart(int j, double along) {
    const Segment& s = profile_.segment(j);
    dep_ = Departure{};
    dep_.segment[0] = j;
    const double slack = kVertexSlack * std::max(1.0, s.length);
    if (along <= slack && j > 0) {
      dep_.segment[1] = j - 1;
      dep_.concave_vertex = profile_.turn_after(j - 1) == VertexTurn::concave;
    } else if (along >= s.length - slack && j + 1 < static_cast<int>(profile_.segment_count())) {
      dep_.segment[1] = j + 1;
      dep_.concave_vertex = profile_.turn_after(j) == VertexTurn::concave;
    }
  }

  void slide() {
    const Segment& s = profile_.segment(seg_);
    const auto& surf = m_.surface(s.material);
    const double g_along = -g_ * s.d.z;              // gravity along d
    const double friction = g_ * s.n.z * surf.tan_phi;  // friction deceleration (n_z > 0)
    if (w_ == 0.0) {
      // At rest: stays when tan β ≤ tan φ, else starts downslope (Eq 3.3).
      if (std::abs(g_along) <= friction) return stop(StopReason::friction);
    }
    const double dir = w_ != 0.0 ? (w_ > 0 ? 1.0 : -1.0) : (g_along > 0 ? 1.0 : -1.0);
    const double acc = g_along - dir * friction;

    // The next event, each in closed form: end of segment, speed zero, maximum sliding speed.
    enum class Event { end, rest, launch, time } ev = Event::time;
    double tau = set_.max_time - t_;
    const double target = dir > 0 ? s.length - along_ : -along_;  // signed distance to the end
    {
      // Solve w τ + acc τ²/2 = target for the first τ ≥ 0 (stable form; the observation lines
      // solve it for a crossing, observation_line.cpp, where the root is known to exist).
      const double disc = w_ * w_ + 2.0 * acc * target;
      if (disc >= 0.0) {
        const double denom = w_ + std::copysign(std::sqrt(disc), target);
        const double te = denom != 0.0 ? 2.0 * target / denom : 0.0;
        if (te >= 0.0 && te <= tau) {
          tau = te;
          ev = Event::end;
        }
      }
    }
    if (acc * dir < 0.0) {
      const double tr = -w_ / acc;
      if (tr >= 0.0 && tr < tau) {
        tau = tr;
        ev = Event::rest;
      }
    } else if (acc * dir > 0.0) {
      const double tl = std::max(0.0, (dir * set_.max_sliding_speed - w_) / acc);
      if (tl < tau) {
        tau = tl;
        ev = Event::launch;
      }
    }
    if (std::abs(w_) > set_.max_sliding_speed) {  // already too fast to slide: launch now
      tau = 0.0;
      ev = Event::launch;
    }

    // Advance along the segment.
    const Vec2 p0 = p_;
    if (path_) path_->push_back(p0);
    if (!tally_.empty()) tally_.slide(p0, s.d, w_, acc, omega_, t_, tau);
    const double w0 = w_;
    if (ev == Event::end) {
      along_ = dir > 0 ? s.length : 0.0;
      p_ = dir > 0 ? s.b : s.a;
    } else {
      along_ = std::clamp(along_ + w0 * tau + 0.5 * acc * tau * tau, 0.0, s.length);
      p_ = s.a + along_ * s.d;
    }
    w_ = ev == Event::rest ? 0.0 : w0 + acc * tau;
    if (ev == Event::launch && tau > 0.0) w_ = dir * set_.max_sliding_speed;
    v_ = w_ * s.d;
    t_ += tau;
    note_speed(v_, omega_);
    if (!all_finite(p_.x, p_.z, w_)) return stop(StopReason::numerical);

    switch (ev) {
      case Event::time:
        return stop(StopReason::time_limit);
      case Event::rest:
        if (!count_event()) return;  // guards against endless rest-restart cycles
        return;                      // next call decides: stop by friction or restart
      case Event::launch:
        // Forced into flight: the roughness tilts the plane so v_n' = −v sin θ < 0 (§3.2.2).
        return impact_from_ground(seg_, along_);
      case Event::end:
        return vertex(dir);
    }
  }

  void vertex(double dir) {
    const int next = seg_ + (dir > 0 ? 1 : -1);
    if (next < 0 || next >= static_cast<int>(profile_.segment_count()))
      return stop(StopReason::boundary);
    const VertexTurn turn = profile_.turn_after(std::min(seg_, next));
    const Segment& ns = profile_.segment(next);
    if (turn == VertexTurn::straight && ns.n.z > 0.0) {  // not an event: carry on
      seg_ = next;
      note_floor(next);
      along_ = dir > 0 ? 0.0 : ns.length;
      return;
    }
    // A concave vertex is an impact on the next segment, and impact() counts it.
    if (turn == VertexTurn::concave) return impact_from_ground(next, dir > 0 ? 0.0 : ns.length);
    if (!count_event()) return;
    // Convex: a point mass cannot follow the bend, it flies from the vertex. At rest it simply
    // moves on to the next segment.
    if (w_ == 0.0) return enter_ground(next, v_);
    mode_ = Mode::flight;
    dep_ = Departure{};
    dep_.segment[0] = seg_;
    dep_.tangent[0] = true;
    dep_.segment[1] = next;
    check_flight();
  }

  const TrajectoryModel& m_;
  const Scenario& sc_;
  const geometry::Profile& profile_;
  const SimulationSettings& set_;
  const double g_;
  ObservationTally& tally_;
  std::vector<ImpactRecord>* impacts_;
  std::vector<Vec2>* path_;
  double path_step_;
  RandomStream rng_;
  const model::BlockConstants* blk_;
  model::ImpactSample next_;  // the random part of the next impact, made ahead
  TrajectorySummary& out_;
  const double half_mass_, half_inertia_;
  const int floor_from_;   // the first floor segment; none: beyond every segment
  double max_speed2_ = 0;  // the largest squared speed so far (out_.max_speed at the end)

  Mode mode_ = Mode::flight;
  Vec2 p_, v_;
  double omega_ = 0, t_ = 0;
  Departure dep_;
  int seg_ = -1;       // sliding: current segment
  double along_ = 0;   // sliding: distance from its start vertex
  double w_ = 0;       // sliding: signed speed along d
  long events_ = 0;    // impacts and vertex events, against the limit
  long impacts_done_ = 0;
};

}  // namespace

TrajectoryModel::TrajectoryModel(const Scenario& scenario)
    : scenario_(&scenario),
      law_(scenario.settings.roughness, scenario.settings.stop_head_factor,
           scenario.settings.gravity),
      key_(scenario.settings.seed) {
  for (const auto& m : scenario.materials) surfaces_.push_back(law_.surface(m));
  for (const auto& b : scenario.blocks) blocks_.push_back(law_.block(b));
  const geometry::Profile& profile = scenario.profile;
  for (const Source& src : scenario.sources) {
    const Vec2 p = src.position;
    // Inside the rock (the first line straight up is a ground line, e.g. in a ledge or under
    // the slope beneath an overhang): placed on that line, the ground over it.
    if (const auto above = profile.line_above(p.x, p.z); above && above->ground) {
      starts_.push_back({SourceStart::Kind::ground, above->z, above->segment});
      continue;
    }
    const auto below = profile.ground_below(p.x, p.z);
    if (below && p.z > below->z) {
      starts_.push_back({SourceStart::Kind::flight, 0.0, below->segment});
      continue;
    }
    const auto top = below ? below : profile.top_ground(p.x);
    if (!top)
      starts_.push_back({SourceStart::Kind::outside, 0.0, -1});
    else
      starts_.push_back({SourceStart::Kind::ground, top->z, top->segment});
  }
}

std::vector<std::size_t> sources_against_main_direction(const Scenario& s) {
  const TrajectoryModel model(s);
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < s.sources.size(); ++i) {
    const int segment = model.source_start(i).segment;
    // Rising along the vertex order: it falls towards the first vertex. (Level ground says
    // nothing; a vertical face is never the ground under a point.)
    if (segment >= 0 && s.profile.segment(segment).d.z > 0.0) out.push_back(i);
  }
  return out;
}

TrajectorySummary simulate_trajectory(const TrajectoryModel& model, std::uint64_t index,
                                      ObservationTally& tally,
                                      std::vector<ImpactRecord>* impacts,
                                      std::vector<geometry::Vec2>* path, double path_step) {
  TrajectorySummary out;
  Integrator(model, index, trajectory_key(model.scenario(), index), tally, impacts, path,
             path_step, out)
      .run();
  return out;
}

void simulate_trajectory(const TrajectoryModel& model, std::uint64_t index, TrajectoryKey key,
                         ObservationTally& tally, std::vector<ImpactRecord>* impacts,
                         TrajectorySummary& out) {
  Integrator(model, index, key, tally, impacts, nullptr, 0.0, out).run();
}

}  // namespace pierre::sim
