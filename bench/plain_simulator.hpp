// A plain implementation of the model: the yardstick of the issue's speed goal ("a plain
// implementation of this model (linear segment scan, mt19937 and std::normal_distribution)
// reaches about 660 000 quarry trajectories per second on one core of this machine"; the goal
// is 10⁶, ×1.52 of it). The host's speed varies from session to session by a sixth and more
// (bench/README.md); running this plain version on the same host turns the absolute goal
// into a ratio that can be measured on any host.
//
// What makes it plain: every flight tests every segment for its contact (a quadratic each);
// the random numbers come from one std::mt19937 per run (as the issue names it), the roughness from
// std::normal_distribution redrawing negatives (Eq 3.5 as the thesis draws it) and the shape
// factor from std::uniform_real_distribution; each first crossing and each stop point is kept
// in a vector. The impact itself is pierre's ImpactLaw::resolve (a plain implementation
// would write the same equations), with the block and surface constants made once.
//
// Its sliding is simpler than the model's (to rest on the segment or over its end, into
// flight at a convex vertex, an impact at a concave one; no sliding launch): quarry-preg's
// blocks all stop by the energy criterion, and vaujany-2d's slide rarely. It is a yardstick
// of speed, not a second model: the mean stop point is printed next to the simulator's so
// that a yardstick that simulates something else shows.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "pierre/sim/scenario.hpp"
#include "pierre/sim/trajectory.hpp"

namespace pierre::bench {

struct PlainRunResult {
  std::uint64_t trajectories = 0, impacts = 0;
  double mean_stop_x = 0;  // m
};

class PlainSimulator {
 public:
  explicit PlainSimulator(const sim::Scenario& s)
      : s_(s), model_(s), gen_(s.settings.seed), g_(s.settings.gravity) {
    for (const auto& line : s.lines) {
      const auto top = s.profile.top_ground(line.x);
      line_ground_.push_back(top ? top->z : 0.0);
    }
    const auto& r = s.settings.roughness;
    truncated_normal_ = r.distribution == model::RoughnessDistribution::truncated_normal;
    // (σ = 0 is a valid scenario, but not a valid std::normal_distribution: X is then μ.)
    if (r.sd > 0) normal_ = std::normal_distribution<double>(r.mean, r.sd);
    fixed_x_ = r.sd > 0 ? 0.0 : r.mean;
  }

  PlainRunResult run() {
    stops_.clear();
    crossings_.clear();
    stops_.reserve(s_.trajectory_count());
    PlainRunResult out;
    for (std::uint64_t i = 0; i < s_.trajectory_count(); ++i) out.impacts += trajectory(i);
    out.trajectories = stops_.size();
    double sum = 0;
    for (const Stop& st : stops_) sum += st.x;
    out.mean_stop_x = out.trajectories ? sum / out.trajectories : 0.0;
    return out;
  }

 private:
  using Vec2 = geometry::Vec2;
  using Segment = geometry::Segment;
  struct Stop {
    double x, z;
    std::uint32_t impacts;
  };
  struct Crossing {
    std::uint64_t trajectory;
    std::uint32_t line;
    double speed, height, energy;
  };

  model::ImpactSample draw(const model::BlockConstants& blk) {
    model::ImpactSample smp;
    if (truncated_normal_ && fixed_x_ > 0) {
      smp.x = fixed_x_;
    } else if (truncated_normal_) {
      do smp.x = normal_(gen_);
      while (smp.x <= 0.0);
    } else {
      smp.x = unit_(gen_);
    }
    smp.f = blk.f_min + blk.f_range * unit_(gen_);
    smp.r_eff = smp.f * blk.radius;
    smp.kappa = 1.0 + 2.5 * smp.f * smp.f;
    smp.level_sign = unit_(gen_) < 0.5;
    return smp;
  }

  // The first contact of the arc from p with velocity v: every segment is tested.
  bool first_contact(Vec2 p, Vec2 v, double& t_hit, int& j_hit) const {
    t_hit = INFINITY;
    j_hit = -1;
    const auto& pr = s_.profile;
    for (std::size_t j = 0; j < pr.segment_count(); ++j) {
      const Segment& sg = pr.segment(j);
      // Distance above the segment's line along n: c0 + c1 t + c2 t².
      const double c0 = dot(p - sg.a, sg.n), c1 = dot(v, sg.n), c2 = -0.5 * g_ * sg.n.z;
      double roots[2];
      int nr = 0;
      if (c2 == 0.0) {
        if (c1 != 0.0) roots[nr++] = -c0 / c1;
      } else {
        const double disc = c1 * c1 - 4.0 * c2 * c0;
        if (disc < 0.0) continue;
        const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
        if (q != 0.0) roots[nr++] = c0 / q;
        roots[nr++] = q / c2;
      }
      for (int k = 0; k < nr; ++k) {
        const double t = roots[k];
        if (!(t > 1e-9 && t < t_hit)) continue;
        if (c1 + 2.0 * c2 * t >= 0.0) continue;  // leaving the line, not entering it
        const Vec2 q{p.x + v.x * t, p.z + v.z * t - 0.5 * g_ * t * t};
        const double along = dot(q - sg.a, sg.d);
        if (along < 0.0 || along > sg.length) continue;
        t_hit = t;
        j_hit = static_cast<int>(j);
      }
    }
    return j_hit >= 0;
  }

  void cross(std::uint64_t index, Vec2 p, Vec2 v, double tau, const model::BlockConstants& blk,
             std::vector<bool>& crossed) {
    const double x1 = p.x + v.x * tau;
    for (std::uint32_t l = 0; l < s_.lines.size(); ++l) {
      const double xl = s_.lines[l].x;
      if (crossed[l] || (xl - p.x) * (xl - x1) > 0.0 || v.x == 0.0) continue;
      const double t = (xl - p.x) / v.x;
      const Vec2 vl{v.x, v.z - g_ * t};
      const double speed = std::sqrt(dot(vl, vl));
      crossings_.push_back({index, l, speed, p.z + v.z * t - 0.5 * g_ * t * t - line_ground_[l],
                            0.5e-3 * blk.mass * speed * speed});
      crossed[l] = true;
    }
  }

  // One trajectory; returns its impacts.
  std::uint32_t trajectory(std::uint64_t index) {
    const auto key = sim::trajectory_key(s_, index);
    const auto& src = s_.sources[key.source];
    const auto& blk = model_.block(key.block);
    const auto& pr = s_.profile;
    const auto start = model_.source_start(key.source);
    std::vector<bool> crossed(s_.lines.size(), false);
    Vec2 p = src.position, v = src.velocity;
    double omega = src.omega;
    std::uint32_t impacts = 0;
    int slide_on = -1;
    if (start.kind == sim::TrajectoryModel::SourceStart::Kind::ground) {
      p.z = start.z;
      slide_on = start.segment;
    }
    for (long events = 0; events < s_.settings.max_impacts; ++events) {
      int j;
      if (slide_on >= 0) {
        j = slide_on;
        slide_on = -1;
        if (!slide(j, p, v)) break;  // at rest
        if (j < 0) break;            // off the profile
        if (j >= static_cast<int>(pr.segment_count())) break;
        const double vn = dot(v, pr.segment(j).n);
        if (vn > 1e-9) continue;  // flies from a convex vertex
        if (vn >= -1e-9) {        // a straight vertex: slides on
          slide_on = j;
          continue;
        }
      } else {
        double t;
        if (!first_contact(p, v, t, j)) break;  // leaves the profile
        cross(index, p, v, t, blk, crossed);
        p = {p.x + v.x * t, p.z + v.z * t - 0.5 * g_ * t * t};
        v = {v.x, v.z - g_ * t};
      }
      const Segment& sg = pr.segment(j);
      const auto res = model_.law().resolve(v, omega, sg, model_.surface(sg.material), blk, draw(blk));
      ++impacts;
      v = res.v;
      omega = res.omega;
      if (res.result == model::ImpactResult::stopped) break;
      if (res.result == model::ImpactResult::sliding) slide_on = j;
    }
    stops_.push_back({p.x, p.z, impacts});
    return impacts;
  }

  // Slides on segment j from p: false when the block comes to rest on it. Otherwise p and v
  // are at the segment's end and j is the next segment: a concave vertex is an impact there
  // (v points into it), a convex one a flight (v along the segment left).
  bool slide(int& j, Vec2& p, Vec2& v) {
    const auto& pr = s_.profile;
    const Segment& sg = pr.segment(j);
    const double tan_phi = model_.surface(sg.material).tan_phi;
    double w = dot(v, sg.d);
    const double g_along = -g_ * sg.d.z, friction = g_ * sg.n.z * tan_phi;
    if (w == 0.0 && std::abs(g_along) <= friction) return false;
    const double dir = w != 0.0 ? (w > 0 ? 1.0 : -1.0) : (g_along > 0 ? 1.0 : -1.0);
    const double acc = g_along - dir * friction;
    const double left = dir > 0 ? sg.length - dot(p - sg.a, sg.d) : dot(p - sg.a, sg.d);
    const double w2_end = w * w + 2.0 * acc * dir * left;
    if (w2_end <= 0.0) {  // at rest before the end
      p = p + (-w * w / (2.0 * acc)) * sg.d;
      return false;
    }
    p = dir > 0 ? sg.b : sg.a;
    v = (dir * std::sqrt(w2_end)) * sg.d;
    j += dir > 0 ? 1 : -1;
    return true;
  }

  const sim::Scenario& s_;
  sim::TrajectoryModel model_;
  std::mt19937 gen_;
  std::normal_distribution<double> normal_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  bool truncated_normal_ = true;
  double fixed_x_ = 0;  // X when σ = 0
  double g_;
  std::vector<double> line_ground_;
  std::vector<Stop> stops_;
  std::vector<Crossing> crossings_;
};

}  // namespace pierre::bench
