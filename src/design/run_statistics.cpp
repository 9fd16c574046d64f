#include "pierre/design/run_statistics.hpp"

#include "pierre/design/number_text.hpp"
#include "pierre/stats/percentile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace pierre::design {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

RunSamples::RunSamples(std::size_t line_count, int main_direction, bool every_crossing)
    : lines_(line_count),
      every_crossing_(every_crossing),
      every_(every_crossing ? line_count : 0),
      last_kept_(line_count, 0),
      main_direction_(main_direction) {}

namespace {
void keep(LineSamples& l, const sim::Crossing& c) {
  l.speed.push_back(c.speed);
  l.height.push_back(c.height);
  l.translational_energy.push_back(c.translational_energy);
  l.rotational_energy.push_back(c.rotational_energy);
}
}  // namespace

void RunSamples::begin_section(std::string name, int main_direction) {
  steep_sections_.push_back({std::move(name)});
  main_direction_ = main_direction;
}

void RunSamples::add(const sim::TrajectorySummary& t) {
  runout_.push_back(t.runout());
  // Still moving at its end, onwards: a block that left at the profile's upper end (thrown back)
  // bounds nothing of the runouts downslope.
  if (t.stop_reason != sim::StopReason::energy && t.stop_reason != sim::StopReason::friction &&
      !(t.stop_reason == sim::StopReason::boundary && (t.stop.x - t.start.x) * main_direction_ <= 0))
    moving_runout_min_ = std::min(moving_runout_min_, t.runout());
  const auto r = static_cast<std::size_t>(t.stop_reason);
  if (r < stops_.size()) ++stops_[r];
  if (t.steep_stop_tan > 0) {
    ++steep_energy_stops_;
    steepest_tan_ = std::max(steepest_tan_, double{t.steep_stop_tan});
    steep_x_min_ = std::min(steep_x_min_, t.stop.x);
    steep_x_max_ = std::max(steep_x_max_, t.stop.x);
    if (!steep_sections_.empty()) {
      SectionSteepStops& s = steep_sections_.back();
      ++s.count;
      s.x_min = std::min(s.x_min, t.stop.x);
      s.x_max = std::max(s.x_max, t.stop.x);
    }
  }
  if (t.stop_reason == sim::StopReason::energy && t.impacts == 1) {
    ++first_impact_stops_;
    first_stop_speed_min_ = std::min(first_stop_speed_min_, t.max_speed);
    first_stop_speed_max_ = std::max(first_stop_speed_max_, t.max_speed);
  }
}

void RunSamples::add(const sim::Crossing& c) {
  if (c.line >= lines_.size()) return;
  if (every_crossing_) keep(every_[c.line], c);
  if (c.direction != main_direction_) return;
  if (last_kept_[c.line] == c.trajectory + 1) return;  // not the first of its trajectory
  last_kept_[c.line] = c.trajectory + 1;
  keep(lines_[c.line], c);
}

QuantityStatistics quantity_statistics(std::span<const double> v) {
  QuantityStatistics q;
  q.count = v.size();
  if (v.empty()) {
    q.mean = q.p50 = q.p95 = q.max = kNaN;
    return q;
  }
  // Neumaier's compensated sum: its error does not grow with the count (10^7 crossings), and
  // the samples come in trajectory order, so it is the same for any thread count.
  double sum = 0, carry = 0;
  for (double x : v) {
    const double t = sum + x;
    carry += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  }
  q.mean = (sum + carry) / static_cast<double>(v.size());
  static constexpr double kPs[] = {50, 95, 100};
  const std::vector<double> p = stats::percentiles(v, kPs);
  q.p50 = p[0];
  q.p95 = p[1];
  q.max = p[2];
  return q;
}

RunStatistics run_statistics(const std::vector<sim::ObservationLine>& lines,
                             const RunSamples& samples) {
  RunStatistics s;
  s.trajectories = samples.trajectories();
  s.every_crossing = samples.every_crossing();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    LineStatistics l;
    l.name = lines[i].name;
    l.chainage = lines[i].x;
    std::uint64_t reached = 0;
    if (i < samples.lines().size()) {
      reached = samples.lines()[i].speed.size();
      const LineSamples& ls = s.every_crossing ? samples.every()[i] : samples.lines()[i];
      l.speed = quantity_statistics(ls.speed);
      l.height = quantity_statistics(ls.height);
      l.translational_energy = quantity_statistics(ls.translational_energy);
    } else {
      l.speed = l.height = l.translational_energy = quantity_statistics({});
    }
    l.count = l.speed.count;
    l.not_reached = s.trajectories >= reached ? s.trajectories - reached : 0;
    s.lines.push_back(std::move(l));
  }
  static constexpr double kRunoutPs[] = {50, 95, 99, 100};
  const std::vector<double> r = stats::percentiles(samples.runout(), kRunoutPs);
  s.runout.count = samples.runout().size();
  s.runout.p50 = r[0];
  s.runout.p95 = r[1];
  s.runout.p99 = r[2];
  s.runout.max = r[3];
  // A type-7 percentile interpolates towards the order statistic above its rank: it is a lower
  // bound once that one is a censored runout, i.e. as soon as it exceeds the largest runout
  // below the shortest censored one.
  {
    const double m = samples.moving_runout_min();
    double below = -std::numeric_limits<double>::infinity();
    for (double r : samples.runout())
      if (r < m) below = std::max(below, r);
    s.runout.lower_bound_from = std::isinf(m) ? m : below;
  }
  for (std::size_t k = 0; k < kStopReasonCount; ++k)
    s.stop_reasons.push_back({static_cast<sim::StopReason>(k), samples.stop_reasons()[k]});
  s.energy_stops_on_steep_ground = samples.steep_energy_stops();
  s.steepest_energy_stop_deg = geometry::degrees(std::atan(samples.steepest_energy_stop_tan()));
  for (const auto& section : samples.steep_energy_stops_by_section())
    if (section.count > 0) s.energy_stops_on_steep_ground_by_section.push_back(section);
  if (samples.steep_energy_stops() > 0 && samples.steep_energy_stops_by_section().empty()) {
    s.energy_stop_steep_x_min = samples.steep_energy_stop_x_min();
    s.energy_stop_steep_x_max = samples.steep_energy_stop_x_max();
  }
  s.energy_stops_at_first_impact = samples.first_impact_stops();
  s.first_impact_stop_speed_min = samples.first_impact_stop_speed_min();
  s.first_impact_stop_speed_max = samples.first_impact_stop_speed_max();
  return s;
}

std::vector<std::string> stop_reason_notes(const RunStatistics& s) {
  std::vector<std::string> notes;
  for (const auto& r : s.stop_reasons) {
    if (r.count == 0) continue;
    const bool one = r.count == 1;
    const std::string n = std::to_string(r.count);
    const char* limit = nullptr;
    switch (r.reason) {
      case sim::StopReason::time_limit:
        limit = "simulation.max_time";
        break;
      case sim::StopReason::impact_limit:
        limit = "simulation.max_impacts (a block bouncing in place, e.g. on a very small roughness)";
        break;
      case sim::StopReason::numerical:
        limit = "a numerical failure (a non-finite value or a lost contact)";
        break;
      case sim::StopReason::boundary:
        notes.push_back(n + (one ? " trajectory left the profile; its runout is where it left it"
                                 : " trajectories left the profile; their runout is where they left it") +
                        ", so the runout percentiles are lower bounds (extend the profile to see "
                        "where they stop).");
        break;
      case sim::StopReason::energy:
      case sim::StopReason::friction:
        break;
    }
    if (limit)
      notes.push_back(n + (one ? " trajectory was" : " trajectories were") + " cut off by " + limit +
                      ", not at rest; " +
                      (one ? "its stop point and runout are where it was cut off."
                           : "their stop points and runouts are where they were cut off."));
  }
  if (const std::uint64_t k = s.energy_stops_on_steep_ground; k > 0) {
    // Not an error: the model (Eq 3.13) stops a block whose energy head after an impact is below
    // c_stop·R whatever the slope. On a talus near its angle of repose blocks do stop; on a rock
    // face they would not, and the runouts and reach counts then fall short.
    const std::string steepest = fixed_text(s.steepest_energy_stop_deg, 1);
    const bool one = k == 1;
    auto at = [](double x0, double x1) {  // as printed: not "16.1 to 16.1 m"
      const std::string a = fixed_text(x0, 1), b = fixed_text(x1, 1);
      return a == b ? "at x = " + a + " m" : "at x = " + a + " to " + b + " m";
    };
    std::string where;
    const bool several = s.energy_stops_on_steep_ground_by_section.size() > 1;
    for (const auto& sec : s.energy_stops_on_steep_ground_by_section)  // "14 in section Kloech at …"
      where += (where.empty() ? "" : "; ") + (several ? std::to_string(sec.count) + " " : "") +
               "in section " + sec.section + " " + at(sec.x_min, sec.x_max);
    if (where.empty()) where = at(s.energy_stop_steep_x_min, s.energy_stop_steep_x_max);
    notes.push_back(std::to_string(k) + (one ? " block was" : " blocks were") +
                    " stopped by the energy criterion (Eq 3.13) on ground steeper than its "
                    "friction angle (up to " + steepest + "°, " + where +
                    "), where a block at rest would slide on down the slope: the model stops a "
                    "block whose energy head after an impact is below c_stop·R whatever the "
                    "slope. Check that " + (one ? "it" : "they") +
                    " can rest there (on a talus near its angle of repose, likely; on a rock face, "
                    "not: a smaller stop_head_factor lets blocks go on).");
  }
  if (const std::uint64_t k = s.energy_stops_at_first_impact;
      k > 0 && static_cast<double>(k) >= kFirstImpactStopShare * static_cast<double>(s.trajectories)) {
    // A block dropped from a few decimetres strikes the ground too slowly for the rebound to
    // keep it going; one that falls far strikes so hard that the impact takes nearly all its
    // energy (the restitution factors fall as the impact energy rises). Either way the energy
    // criterion stops it where it landed, and a line downslope counts it as not reached. Their
    // largest speeds (at the impact, unless thrown faster) tell which.
    const std::string share =
        fixed_text(100.0 * static_cast<double>(k) / static_cast<double>(s.trajectories), 1);
    const double lo = s.first_impact_stop_speed_min, hi = s.first_impact_stop_speed_max;
    const std::string speeds = lo == hi ? fixed_text(hi, 1) + " m/s"
                                        : fixed_text(lo, 1) + " to " + fixed_text(hi, 1) + " m/s";
    std::string why;
    if (lo < kHardFirstImpactSpeed)
      why += " A source a little above the ground drops its blocks so: if they should start by "
             "sliding or rolling, put it on the ground (z at or below it) or give it a starting "
             "velocity (vx, vz).";
    if (hi >= kHardFirstImpactSpeed)
      why += std::string(" A hard impact does it too: the restitution factors fall as the "
                         "impact's energy rises (Eq 6.4), so a block that falls far onto the ground "
                         "keeps almost nothing") +
             (lo < kHardFirstImpactSpeed ? "." : "; check the source's height (z) against the profile's.");
    notes.push_back(std::to_string(k) + " of " + std::to_string(s.trajectories) + " blocks (" +
                    share + " %) came to rest at their first impact (their largest speed, that "
                    "of the impact unless thrown faster: " + speeds +
                    "): the energy criterion (Eq 3.13) stopped them there." + why);
  }
  return notes;
}

}  // namespace pierre::design
