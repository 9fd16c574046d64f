// The exact-contact core against the time-stepping oracle (tests/oracle/time_step_oracle.hpp),
// trajectory by trajectory, fed the same random draws impact by impact, on the two shipped
// examples (and on a sliding chute that the examples hardly exercise).
//
// Nothing here is an expected value taken from the program's output: every reference number is
// the oracle's, computed in the test by a different algorithm (fixed steps and revert, §3.3).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "oracle/time_step_oracle.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "pierre/sim/runner.hpp"
#include "pierre/stats/kolmogorov_smirnov.hpp"
#include "support/builders.hpp"

using namespace pierre;
using geometry::Vec2;

namespace {

constexpr double kDt = 1e-4;  // the oracle's step, s (the choice; the thesis used 0.02 s)
constexpr double kG = 9.81;   // both examples and the chute use the default gravity

double tan_deg(double a) { return std::tan(a * std::numbers::pi / 180.0); }

// ---- the scenarios ----

// The two shipped examples, loaded as a user would run them.
sim::Scenario example(const char* folder) {
  return io::load_scenario(std::string(PIERRE_SOURCE_DIR "/examples/") + folder + "/scenario.toml",
                           PIERRE_SOURCE_DIR "/rules")
      .scenario;
}
sim::Scenario vaujany() { return example("vaujany-2d"); }
sim::Scenario quarry() { return example("quarry-preg"); }

// Not an example: a chute that makes blocks slide, so that the sliding code of both is compared
// too (the two examples hardly slide: on their rough talus and faces almost every impact is a
// rebound, since v⁺·n ≤ 0 needs a strong backward slip). A 45° stretch (φ = 30°: sliding
// accelerates to the launch speed), a concave break to 25° (sliding decelerates), a convex break
// to 38°, a concave break to a level floor; low roughness on the chute keeps the hops small.
// Sources on or just below the ground start sliding (§3.2.2): from rest at the top (slides,
// launches); from rest 2.8 m above the concave break (reaches it below the launch speed: a
// concave-vertex impact); upslope at 3 m/s on the 45° stretch (slides up, comes to rest, restarts
// downslope); at 4 m/s down the 25° stretch (stops by friction); at 4.99 m/s down the 25°
// stretch 10 m above the convex break (flies off it); at 4.9 m/s on the floor (stops by friction).
sim::Scenario chute() {
  std::vector<Vec2> v{{0, 100}};
  auto down = [&](double dx, double deg) { v.push_back({v.back().x + dx, v.back().z - dx * tan_deg(deg)}); };
  down(20, 45);
  down(30, 25);
  down(10, 38);
  down(60, 0);
  std::vector<model::Block> blocks;
  for (int i = 0; i < 5; ++i) blocks.push_back(test::make_block(500.0 + 600.0 * i, 1.0, 1.2));
  sim::Scenario s = test::make_scenario(test::make_profile(v, {0, 0, 0, 1}), test::make_material(15, 50, 0.1),
                                        blocks, {1.0, 98.99}, 10, 7);
  s.materials.push_back(test::make_material(15, 50, 0.5));  // the floor
  const Vec2 d25{std::cos(25 * std::numbers::pi / 180), -std::sin(25 * std::numbers::pi / 180)};
  const Vec2 d45{std::sqrt(0.5), -std::sqrt(0.5)};
  const double z25_at = v[1].z;  // the 25° stretch starts at x = 20
  auto on25 = [&](double x) { return z25_at - (x - 20) * tan_deg(25) - 0.01; };
  s.sources.push_back({"above the concave break", {18.0, 100 - 18.0 - 0.01}, {0, 0}, 0});
  s.sources.push_back({"upslope", {10.0, 90.0 - 0.01}, -3.0 * d45, 0});
  s.sources.push_back({"slow on 25°", {25.0, on25(25)}, 4.0 * d25, 0});
  s.sources.push_back({"to the convex break", {40.0, on25(40)}, 4.99 * d25, 0});
  s.sources.push_back({"floor", {80.0, v[3].z - 0.01}, {4.9, 0}, 0});
  s.lines = {{"mid 25°", 35.0}, {"floor + 5 m", 65.0}};
  return s;
}


// ---- running both ----

struct RunPair {
  sim::Scenario scenario;
  sim::ResultCollector core;
  std::vector<std::size_t> impact_begin;  // core impacts of trajectory i: [begin[i], begin[i+1])
  std::vector<std::vector<const sim::Crossing*>> core_crossings;  // per trajectory
  std::vector<oracle::OracleResult> oracle;
  double core_seconds = 0, oracle_seconds = 0;
  std::uint64_t oracle_steps = 0;
};

// `oracle_scenario`, when given, is what the oracle runs instead (a deliberately changed model,
// to show that the comparison would see the difference).
RunPair run_both(sim::Scenario scenario, const sim::Scenario* oracle_scenario = nullptr) {
  RunPair r;
  r.scenario = std::move(scenario);
  const sim::Scenario& s = r.scenario;
  sim::RunOptions o;
  o.record_impacts = true;
  auto t0 = std::chrono::steady_clock::now();
  sim::run_simulation(s, o, r.core);
  r.core_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::size_t n = s.trajectory_count();
  r.impact_begin.assign(n + 1, r.core.impacts.size());
  for (std::size_t k = r.core.impacts.size(); k-- > 0;) r.impact_begin[r.core.impacts[k].trajectory] = k;
  for (std::size_t i = n; i-- > 0;) r.impact_begin[i] = std::min(r.impact_begin[i], r.impact_begin[i + 1]);
  r.core_crossings.resize(n);
  for (const auto& c : r.core.crossings) r.core_crossings[c.trajectory].push_back(&c);
  oracle::OracleOptions opt;
  opt.dt = kDt;
  opt.record_impacts = true;
  t0 = std::chrono::steady_clock::now();
  for (std::uint64_t i = 0; i < n; ++i) {
    r.oracle.push_back(oracle::simulate_time_step(oracle_scenario ? *oracle_scenario : s, i, opt));
    r.oracle_steps += r.oracle.back().steps;
  }
  r.oracle_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

// ---- tolerances: the oracle's step error ----
//
// Where the oracle errs. Flight: its position and velocity are exact on the parabola at the step
// times; the only error is the revert (§3.3): an impact is resolved at the last point above the
// ground, at most one step before the exact contact — at most (|v| + g dt) dt away along the arc —
// with a velocity at most g dt off. Sliding: the per-step update is exact for the constant
// acceleration of Eq 3.3; its events (end of segment, launch, rest) come at most one step late,
// again at most |v| dt and g dt off. So impact k adds a position error ≤ |v_k| dt, and a velocity
// error ≤ g dt that moves the next impact by ≤ g dt τ_k over the following flight or slide of
// duration τ_k.
//
// How it propagates. An offset of the impact point along a plane changes nothing downstream. An
// inherited velocity error passes through the impact law, which damps it: at the energies of these
// slopes (E_d = R v_n² near E_n) k_n is about 0.5 and the tangential part is cut to about
// 5/7 k_t, so an inherited error shrinks by roughly half per impact. Taking a ratio of at most 2/3,
// the inherited errors sum to at most 1 + 2/3 + 4/9 + … = 3 times the fresh one. Hence, up to
// time t:
//   B(t) = dt · Σ_{impacts k before t} (|v_k| + g τ_k),   position tolerance = 3 B(t) + one step,
// and a speed tolerance of 3 g dt plus the speed change a position error brings (v δv = g δz).
// Two situations break the damping assumption, and the trajectories that meet them are counted as
// diverging (and said why): a grazing landing (incidence α: the landing point moves by the height
// error / tan α) and a low-energy flight down a steep stretch (k_n, k_t → 1 as E_d → 0 and the
// block gathers speed, so an error grows with it).
double budget(const oracle::OracleResult& o, double t) {
  double b = 0;
  for (std::size_t k = 0; k < o.impact_log.size() && o.impact_log[k].time < t; ++k) {
    const double next = k + 1 < o.impact_log.size() ? o.impact_log[k + 1].time : o.duration;
    b += (norm(o.impact_log[k].v_in) + kG * (std::min(next, t) - o.impact_log[k].time)) * kDt;
  }
  return b;
}
constexpr double kSafety = 3.0;  // the damped sum 1 + 2/3 + 4/9 + …: see above

// ---- one trajectory: does the core agree with the oracle within the oracle's step error? ----

struct Verdict {
  bool reason = true, first = true, stop = true, crossings = true;
  bool agree() const { return reason && first && stop && crossings; }
  double stop_err = 0, stop_tol = 0;
  double first_err = 0, first_tol = 0;
};

Verdict compare(const RunPair& r, std::size_t i) {
  Verdict v;
  const auto& c = r.core.trajectories[i];
  const auto& o = r.oracle[i];
  v.reason = c.stop_reason == o.stop_reason;
  // First impact: one step of arc (the revert) and nothing else, since no earlier impact exists.
  v.first = c.has_first_impact == o.has_first_impact;
  if (c.has_first_impact && o.has_first_impact && !o.impact_log.empty()) {
    v.first_err = norm(c.first_impact - o.first_impact);
    v.first_tol = (norm(o.impact_log.front().v_in) + kG * kDt) * kDt + 1e-9;
    v.first = v.first_err <= v.first_tol;
  }
  // Stop point.
  const double step = (c.max_speed + kG * kDt) * kDt;
  v.stop_err = norm(c.stop - o.stop);
  v.stop_tol = kSafety * budget(o, o.duration) + step + 1e-9;
  v.stop = v.stop_err <= v.stop_tol;
  // First crossing of each line in the main direction: the same lines, speed and passing height.
  const auto& cc = r.core_crossings[i];
  v.crossings = cc.size() == o.crossings.size();
  for (const sim::Crossing* x : cc) {
    const auto it = std::find_if(o.crossings.begin(), o.crossings.end(),
                                 [&](const oracle::OracleCrossing& y) { return y.line == x->line; });
    if (it == o.crossings.end()) {
      v.crossings = false;
      continue;
    }
    const double tol_h = kSafety * budget(o, it->time) + step + 1e-9;
    const double tol_v = kSafety * kG * kDt + kG * tol_h / std::max(x->speed, 1.0) + 1e-9;
    if (!(std::abs(x->speed - it->speed) <= tol_v && std::abs(x->height - it->height) <= tol_h))
      v.crossings = false;
  }
  return v;
}

// ---- why a trajectory diverges ----

struct Divergence {
  std::size_t impact = 0;  // index of the first impact that differs
  std::string kind;
  std::string detail;
};

bool is_vertex_near(const geometry::Profile& p, Vec2 x, double r) {
  for (const Vec2& v : p.vertices())
    if (norm(v - x) <= r) return true;
  return false;
}

// The travel direction along the surface, t̂ = sign(v·d) d, decides which way the roughness tilts
// the plane (model-2d.md §3 steps 1 and 3): with v·d within a hair of 0 the two may tilt it
// opposite ways.
bool tangential_hair(const model::ImpactDetail& a, const model::ImpactDetail& b) {
  return std::min(std::abs(a.vt_in), std::abs(b.vt_in)) < 0.01 ||
         std::min(std::abs(a.vt_out), std::abs(b.vt_out)) < 0.01;
}

const char* result_name(model::ImpactResult r) {
  return r == model::ImpactResult::rebound ? "rebound" : r == model::ImpactResult::sliding ? "sliding" : "stopped";
}

// The kinds of divergence that no decision within a hair of its threshold explains. A correct
// core shows none on these scenarios; a wrong one on a rare path does (changing a sliding result
// into a stop parted 0.6 % of the Vaujany trajectories "after the last impact", well inside the
// agreement share).
const std::string kAfterLastImpact = "after the last impact (final flight or slide)";
const std::string kFlippedByStepError = "a decision flipped by accumulated step error";
const std::string kUnclassified = "step error amplified (unclassified)";

// Walks the two impact sequences to the first impact where they part — a different decision
// (rebound, sliding, stop), a different segment, or a point or incident velocity outside the
// step-error budget — and says what decided it there.
Divergence classify(const RunPair& r, std::size_t i) {
  const auto& o = r.oracle[i].impact_log;
  const std::size_t b = r.impact_begin[i], e = r.impact_begin[i + 1];
  const std::size_t n = std::min(o.size(), e - b);
  const double vmax_slide = r.scenario.settings.max_sliding_speed;
  const auto& blk = r.scenario.blocks[sim::trajectory_key(r.scenario, i).block];
  const double h_stop = r.scenario.settings.stop_head_factor * blk.radius();
  Divergence d;
  std::size_t k = 0;
  for (; k < n; ++k) {
    const auto& ci = r.core.impacts[b + k];
    const auto& oi = o[k];
    const double speed = norm(oi.v_in);
    const double tol_p = kSafety * budget(r.oracle[i], oi.time) + (speed + kG * kDt) * kDt + 1e-9;
    const double tol_v = kSafety * kG * kDt + kG * tol_p / std::max(speed, 1.0);
    const Vec2 cv{ci.detail.vt_in, ci.detail.vn_in};  // true frame, t along the travel
    const Vec2 ov{oi.detail.vt_in, oi.detail.vn_in};
    if (ci.result != oi.result || static_cast<int>(ci.segment) != oi.segment ||
        norm(ci.position - oi.position) > tol_p || norm(cv - ov) > tol_v)
      break;
  }
  d.impact = k;
  std::ostringstream os;
  if (k == n) {
    // Every impact both made agrees; the difference arose after the last one.
    d.kind = kAfterLastImpact;
    os << "core " << e - b << " impacts, oracle " << o.size();
    d.detail = os.str();
    return d;
  }
  const auto& ci = r.core.impacts[b + k];
  const auto& oi = o[k];
  const double speed = norm(oi.v_in);
  // The values each decision was made on.
  const double head_c = ci.detail.energy_out / (blk.mass * kG) / h_stop;
  const double head_o = oi.detail.energy_out / (blk.mass * kG) / h_stop;
  const double inc_c = std::abs(ci.detail.incidence_deg), inc_o = std::abs(oi.detail.incidence_deg);
  const bool core_launch = std::abs(std::abs(ci.detail.vt_in) - vmax_slide) < 1e-9 && std::abs(ci.detail.vn_in) < 1e-9;
  const bool oracle_launch = oi.kind == oracle::ImpactKind::launch;
  os << "impact " << k << " at t " << ci.time << " s: core " << result_name(ci.result) << " on segment " << ci.segment
     << " at (" << ci.position.x << ", " << ci.position.z << "), incidence " << inc_c << "°, v⁺·n " << ci.detail.vn_out
     << " m/s, H/H_stop " << head_c << "; oracle " << result_name(oi.result) << " on segment " << oi.segment << " at ("
     << oi.position.x << ", " << oi.position.z << "), incidence " << inc_o << "°, v⁺·n " << oi.detail.vn_out
     << " m/s, H/H_stop " << head_o << "; |v_in| " << speed << " m/s";
  d.detail = os.str();
  const double near = 2 * (speed + kG * kDt) * kDt + 0.01;
  const bool flipped = ci.result != oi.result;
  if (ci.segment != static_cast<std::uint32_t>(oi.segment) || is_vertex_near(r.scenario.profile, ci.position, near) ||
      is_vertex_near(r.scenario.profile, oi.position, near))
    d.kind = "contact at a vertex (lands on one side or the other)";
  else if (core_launch != oracle_launch || (oracle_launch && std::abs(speed - vmax_slide) < 0.01))
    d.kind = "launch at the sliding limit decided by a hair";
  else if (flipped && (ci.result == model::ImpactResult::stopped || oi.result == model::ImpactResult::stopped) &&
           std::abs(std::min(head_c, head_o) - 1.0) < 0.02)
    d.kind = "stop criterion decided by a hair (H within 2 % of c_stop R)";
  else if (flipped && std::min(std::abs(ci.detail.vn_out), std::abs(oi.detail.vn_out)) < 0.05)
    d.kind = "rebound/sliding decided by a hair (v⁺·n near 1e-6 m/s)";
  else if (tangential_hair(ci.detail, oi.detail) ||
           (k > 0 && tangential_hair(r.core.impacts[b + k - 1].detail, o[k - 1].detail)))
    d.kind = "travel direction decided by a hair (rebound with v·d ≈ 0: the roughness tilts the other way)";
  else if (std::min(inc_c, inc_o) < 10.0)
    d.kind = "grazing landing (incidence < 10°: step error amplified ≈ 1/tan α)";
  else if (const auto g = std::find_if(r.core.impacts.begin() + b, r.core.impacts.begin() + b + k,
                                       [](const sim::ImpactRecord& x) { return std::abs(x.detail.incidence_deg) < 10.0; });
           g != r.core.impacts.begin() + b + k)
    d.kind = "grazing landing earlier (incidence < 10° at impact " + std::to_string(g - r.core.impacts.begin() - b) +
             "), error then grown with the speed";
  else if (k > 0 && r.core.impacts[b + k - 1].segment != ci.segment)
    d.kind = "flight across a slope break (landing point sensitive to the take-off)";
  else
    d.kind = flipped ? kFlippedByStepError : kUnclassified;
  return d;
}


const RunPair& vaujany_run() {
  static const RunPair r = run_both(vaujany());
  return r;
}
const RunPair& quarry_run() {
  static const RunPair r = run_both(quarry());
  return r;
}
const RunPair& chute_run() {
  static const RunPair r = run_both(chute());
  return r;
}

double agreeing_share(const RunPair& r) {
  std::size_t agree = 0;
  for (std::size_t i = 0; i < r.oracle.size(); ++i) agree += compare(r, i).agree();
  return static_cast<double>(agree) / static_cast<double>(r.oracle.size());
}

// The share of agreeing trajectories must reach kMinShare.
//
// Why 90 %. A correct core and a correct oracle part only where a decision of the model — the
// side of a vertex a landing falls on, the stop criterion H < c_stop R, rebound or sliding
// (v⁺·n ≤ 1e-6), the travel direction when v·d ≈ 0, the launch at the sliding limit — lies within
// the oracle's step error of its threshold, or where a grazing landing magnifies that error. With
// state errors of order 1e-4 relative and tens of decisions per trajectory, that is about 1 % of
// the trajectories (measured: 0.8 % on Vaujany, 0 % on the quarry, 1.7 % on the chute, every one
// of them explained in the printed report). A wrong core is different in kind: a change of 1 % in
// a single input the trajectories depend on (roughness, E_n), of 0.1 % in g, or one random draw out
// of order parts nearly every trajectory from its next impact on (the share drops below 50 %, see
// ComparisonSeesSmallModelChanges). 90 % leaves a factor of about ten for profiles with more
// vertices or other seeds, and still separates right from wrong by a wide margin.
constexpr double kMinShare = 0.90;

// What a comparison exercised (counted on the oracle's side), for each test to hold to the paths
// its scenario was built for.
struct Exercised {
  std::size_t impacts = 0, launches = 0, vertex_hits = 0, slides = 0, friction_stops = 0;
};

Exercised check_agreement(const RunPair& r, const char* name) {
  Exercised ex;
  const std::size_t n = r.scenario.trajectory_count();
  EXPECT_EQ(r.core.trajectories.size(), n);
  EXPECT_EQ(r.oracle.size(), n);
  if (r.core.trajectories.size() != n || r.oracle.size() != n) return ex;
  std::size_t agree = 0, same_impacts = 0, bad_reason = 0, bad_first = 0, bad_stop = 0, bad_cross = 0;
  std::vector<double> stop_ratio;
  std::map<std::string, int> kinds;
  std::vector<std::string> examples;
  for (std::size_t i = 0; i < n; ++i) {
    const Verdict v = compare(r, i);
    stop_ratio.push_back(v.stop_err / v.stop_tol);
    same_impacts += r.core.trajectories[i].impacts == r.oracle[i].impacts;
    bad_reason += !v.reason;
    bad_first += !v.first;
    bad_stop += !v.stop;
    bad_cross += !v.crossings;
    for (const auto& im : r.oracle[i].impact_log) {
      ++ex.impacts;
      ex.launches += im.kind == oracle::ImpactKind::launch;
      ex.vertex_hits += im.kind == oracle::ImpactKind::vertex;
      ex.slides += im.result == model::ImpactResult::sliding;
    }
    ex.friction_stops += r.oracle[i].stop_reason == sim::StopReason::friction;
    if (v.agree()) {
      ++agree;
      continue;
    }
    const Divergence d = classify(r, i);
    ++kinds[d.kind];
    if (examples.size() < 6) {
      const auto& c = r.core.trajectories[i];
      const auto& o = r.oracle[i];
      std::ostringstream os;
      os << "  trajectory " << i << " (seed " << r.scenario.settings.seed << "): stop " << sim::to_string(c.stop_reason)
         << " at (" << c.stop.x << ", " << c.stop.z << ") vs oracle " << sim::to_string(o.stop_reason) << " at ("
         << o.stop.x << ", " << o.stop.z << "), " << v.stop_err << " m apart (tolerance " << v.stop_tol << " m)"
         << (v.crossings ? "" : ", crossings differ") << " — " << d.kind << "\n      " << d.detail;
      examples.push_back(os.str());
    }
  }
  std::sort(stop_ratio.begin(), stop_ratio.end());
  const double share = static_cast<double>(agree) / static_cast<double>(n);
  std::cout << "[oracle] " << name << ": " << agree << " / " << n << " trajectories agree (" << 100.0 * share
            << " %); outside tolerance: stop reason " << bad_reason << ", first impact " << bad_first
            << ", stop point " << bad_stop << ", crossings " << bad_cross << "; " << same_impacts
            << " with the same number of impacts\n"
            << "  stop error / tolerance: median " << stop_ratio[n / 2] << ", 90 % " << stop_ratio[9 * n / 10]
            << "; exercised " << ex.impacts << " impacts (" << ex.slides << " ending in sliding, "
            << ex.launches << " launches, " << ex.vertex_hits << " concave-vertex impacts), " << ex.friction_stops
            << " friction stops; core " << r.core_seconds << " s, oracle " << r.oracle_seconds << " s ("
            << r.oracle_steps << " steps)\n";
  for (const auto& [k, m] : kinds) std::cout << "  diverging: " << m << " × " << k << "\n";
  for (const auto& e : examples) std::cout << e << "\n";
  ::testing::Test::RecordProperty(std::string(name) + "_agreeing_share", std::to_string(share));
  EXPECT_GE(share, kMinShare) << name;
  // The first impact precedes every decision: it must agree for every trajectory.
  EXPECT_EQ(bad_first, 0u) << name;
  // Every diverging trajectory is explained by a decision within a hair of its threshold (or a
  // grazing landing): the share above cannot see a bug confined to a few percent of them.
  for (const std::string& unexplained : {kAfterLastImpact, kFlippedByStepError, kUnclassified})
    EXPECT_EQ(kinds.count(unexplained) ? kinds.at(unexplained) : 0, 0) << name << ": " << unexplained;
  return ex;
}

// Two-sample KS of oracle against core (the issue asks for it). Tolerance p > 0.01: were the two
// independent samples of one distribution, the test would fail once in a hundred runs. They are
// not independent: they share every random draw, so D is at most about the share of diverging
// trajectories, and with 90 % or more agreeing (the test above) D stays near or below the
// critical value at these sizes: on its own it adds little. What would slip past both — the
// diverging trajectories all diverging one way, a bias in a decision — is the sign test's below.
constexpr double kMinP = 0.01;

// Two-sided exact binomial test of `up` successes in `n` trials at p = 1/2.
double sign_test_p(std::size_t up, std::size_t n) {
  const std::size_t k = std::min(up, n - up);
  double tail = 0;
  for (std::size_t i = 0; i <= k; ++i)
    tail += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) -
                     static_cast<double>(n) * std::log(2.0));
  return std::min(1.0, 2 * tail);
}

void expect_same_distribution(const std::vector<double>& core, const std::vector<double>& oracle,
                              const std::string& what) {
  const auto ks = stats::kolmogorov_smirnov_two_sample(core, oracle);
  ASSERT_TRUE(ks.ok()) << what << ": " << ks.error;
  std::cout << "[oracle] KS " << what << " (" << core.size() << " vs " << oracle.size() << "): D " << ks->statistic
            << ", p " << ks->p_value << " (Stephens " << ks->p_value_stephens << ")\n";
  EXPECT_GT(ks->p_value, kMinP) << what;
}

void check_distributions(const RunPair& r) {
  const std::string name = r.scenario.name;
  // The diverging trajectories' runouts: the core's longer as often as the oracle's (sign test,
  // two-sided, p > 0.01). Its power grows with the divergences: below 8 of them no split can
  // reach p = 0.01, so on these cases (a few divergences) it guards a future change that makes
  // many, as the KS does.
  std::size_t longer = 0, diverging = 0;
  for (std::size_t i = 0; i < r.oracle.size(); ++i) {
    if (compare(r, i).agree()) {
      continue;
    }
    const double dc = r.core.trajectories[i].runout(),
                 dor = std::abs(r.oracle[i].stop.x - r.oracle[i].start.x);
    if (dc == dor) continue;
    ++diverging;
    longer += dc > dor;
  }
  const double p_sign = diverging ? sign_test_p(longer, diverging) : 1.0;
  std::cout << "[oracle] " << name << ": of " << diverging << " diverging runouts the core's is longer in "
            << longer << " (sign test p " << p_sign << ")\n";
  EXPECT_GT(p_sign, kMinP) << name;
  std::vector<double> run_c, run_o;
  for (const auto& t : r.core.trajectories) run_c.push_back(t.runout());
  for (const auto& t : r.oracle) run_o.push_back(std::abs(t.stop.x - t.start.x));
  expect_same_distribution(run_c, run_o, name + ", runout");
  for (std::size_t l = 0; l < r.scenario.lines.size(); ++l) {
    std::vector<double> sc, so, hc, ho;
    for (const auto& c : r.core.crossings)
      if (c.line == l) {
        sc.push_back(c.speed);
        hc.push_back(c.height);
      }
    for (const auto& t : r.oracle)
      for (const auto& c : t.crossings)
        if (c.line == l) {
          so.push_back(c.speed);
          ho.push_back(c.height);
        }
    if (sc.empty() && so.empty()) continue;
    expect_same_distribution(sc, so, name + ", " + r.scenario.lines[l].name + " speed");
    expect_same_distribution(hc, ho, name + ", " + r.scenario.lines[l].name + " passing height");
  }
}

}  // namespace

// Each comparison is held to the paths it is there for (the counts were printed, never asserted).
TEST(TimeStepOracle, VaujanyTrajectoriesAgree) {
  const Exercised ex = check_agreement(vaujany_run(), "vaujany-2d");
  EXPECT_GE(ex.impacts, 500u * 20);  // a long talus slope: tens of impacts a trajectory
  EXPECT_GE(ex.slides, 1u);          // impacts that end in sliding: rare on rough talus
}
TEST(TimeStepOracle, QuarryTrajectoriesAgree) {
  const Exercised ex = check_agreement(quarry_run(), "quarry-preg");
  EXPECT_GE(ex.impacts, 250u * 5);
}
// The chute's sources were placed for these paths (see chute()): 50 trajectories each from the top
// (slides to the launch speed), above the concave break (a concave-vertex impact), slow on 25° and
// on the floor (friction stops).
TEST(TimeStepOracle, SlidingChuteTrajectoriesAgree) {
  const Exercised ex = check_agreement(chute_run(), "sliding chute");
  EXPECT_GE(ex.launches, 50u);
  EXPECT_GE(ex.vertex_hits, 50u);
  EXPECT_GE(ex.friction_stops, 100u);
}

TEST(TimeStepOracle, VaujanyDistributionsAreStatisticallyEqual) { check_distributions(vaujany_run()); }
TEST(TimeStepOracle, QuarryDistributionsAreStatisticallyEqual) { check_distributions(quarry_run()); }

// The same distributions from independent draws: the oracle runs with another seed, so its
// sample is a second, independent sample of the model, and the two-sample KS can fail on its own
// (with shared draws it fails only through the divergences the agreement tests already bound).
// Twelve comparisons (the runout, and each line's speed and passing height: two lines at
// Vaujany, three at Preg) at a family-wise 1 %: p > 0.01 / 12 each (Bonferroni).
TEST(TimeStepOracle, IndependentDrawsGiveTheSameDistributions) {
  int compared = 0;
  for (sim::Scenario s : {vaujany(), quarry()}) {
    SCOPED_TRACE(s.name);
    sim::Scenario other = s;
    other.settings.seed = s.settings.seed + 1;
    const RunPair r = run_both(s, &other);
    std::vector<std::pair<std::vector<double>, std::vector<double>>> samples;
    std::vector<std::string> what;
    samples.emplace_back();
    what.push_back("runout");
    for (const auto& t : r.core.trajectories) samples.back().first.push_back(t.runout());
    for (const auto& t : r.oracle) samples.back().second.push_back(std::abs(t.stop.x - t.start.x));
    for (std::size_t l = 0; l < s.lines.size(); ++l)
      for (const bool speed : {true, false}) {
        samples.emplace_back();
        what.push_back(s.lines[l].name + (speed ? " speed" : " passing height"));
        for (const auto& c : r.core.crossings)
          if (c.line == l) samples.back().first.push_back(speed ? c.speed : c.height);
        for (const auto& t : r.oracle)
          for (const auto& c : t.crossings)
            if (c.line == l) samples.back().second.push_back(speed ? c.speed : c.height);
      }
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const auto& [core, oracle] = samples[k];
      if (core.empty() && oracle.empty()) continue;
      const auto ks = stats::kolmogorov_smirnov_two_sample(core, oracle);
      ASSERT_TRUE(ks.ok()) << what[k] << ": " << ks.error;
      std::cout << "[oracle] independent draws, " << s.name << " " << what[k] << " (" << core.size()
                << " vs " << oracle.size() << "): D " << ks->statistic << ", p " << ks->p_value << "\n";
      EXPECT_GT(ks->p_value, 0.01 / 12) << what[k];
      ++compared;
    }
  }
  EXPECT_EQ(compared, 12);  // the count the threshold is divided by
}

// The comparison has power: small changes of the model given to the oracle alone are seen.
TEST(TimeStepOracle, ComparisonSeesSmallModelChanges) {
  sim::Scenario rough = vaujany();
  for (auto& m : rough.materials) m.roughness *= 1.01;
  const double s_rough = agreeing_share(run_both(vaujany(), &rough));
  sim::Scenario friction = chute();
  for (auto& m : friction.materials) m.friction_angle_deg += 0.3;
  const double s_friction = agreeing_share(run_both(chute(), &friction));
  std::cout << "[oracle] agreeing share with the oracle's roughness 1 % higher (Vaujany) " << s_rough
            << ", with its friction angle 0.3° higher (chute) " << s_friction << "\n";
  EXPECT_LT(s_rough, 0.5);
  EXPECT_LT(s_friction, 0.5);
}

// Diagnostics, run by hand: ORACLE_CASE=vaujany|quarry|chute ORACLE_TRAJ=<index>
//   pierre_tests_regression --gtest_also_run_disabled_tests --gtest_filter='*DISABLED_Dump*'
// prints both impact sequences of one trajectory side by side.
TEST(TimeStepOracle, DISABLED_Dump) {
  const char* which = std::getenv("ORACLE_CASE");
  const char* idx = std::getenv("ORACLE_TRAJ");
  if (!which || !idx) GTEST_SKIP() << "set ORACLE_CASE and ORACLE_TRAJ";
  const std::string w = which;
  const RunPair& r = w == "vaujany" ? vaujany_run() : w == "quarry" ? quarry_run() : chute_run();
  const std::size_t i = std::stoul(idx);
  ASSERT_LT(i, r.oracle.size());
  const auto& o = r.oracle[i].impact_log;
  const std::size_t b = r.impact_begin[i], e = r.impact_begin[i + 1];
  for (std::size_t k = 0; k < std::max(o.size(), e - b); ++k) {
    if (k < e - b) {
      const auto& c = r.core.impacts[b + k];
      std::printf("core   %3zu t %9.5f seg %3u (%10.5f, %10.5f) %-8s in (t %9.5f, n %9.5f) out (t %9.5f, n %9.5f)\n", k,
                  c.time, c.segment, c.position.x, c.position.z, result_name(c.result), c.detail.vt_in, c.detail.vn_in,
                  c.detail.vt_out, c.detail.vn_out);
    }
    if (k < o.size()) {
      const auto& c = o[k];
      std::printf("oracle %3zu t %9.5f seg %3d (%10.5f, %10.5f) %-8s in (t %9.5f, n %9.5f) out (t %9.5f, n %9.5f)\n", k,
                  c.time, c.segment, c.position.x, c.position.z, result_name(c.result), c.detail.vt_in, c.detail.vn_in,
                  c.detail.vt_out, c.detail.vn_out);
    }
  }
  const auto& c = r.core.trajectories[i];
  std::printf("core stop (%.5f, %.5f) %s at t %.4f; oracle stop (%.5f, %.5f) %s at t %.4f\n", c.stop.x, c.stop.z,
              std::string(sim::to_string(c.stop_reason)).c_str(), c.duration, r.oracle[i].stop.x, r.oracle[i].stop.z,
              std::string(sim::to_string(r.oracle[i].stop_reason)).c_str(), r.oracle[i].duration);
}
