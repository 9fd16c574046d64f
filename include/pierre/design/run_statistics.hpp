// Statistics of a run for the console table and summary.json: per observation line the
// speed, passing height and translational energy of the crossings (model-2d.md §5: the first
// crossing of each trajectory in the main travel direction, or every crossing when the user
// asks for all crossings), the runout distribution and the
// stop-reason counts. Pure: samples in, plain structs out. Percentiles are the empirical
// type-7 estimator (Hyndman & Fan 1996; R's and NumPy's default).
#pragma once

#include <array>
#include <limits>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pierre/sim/observation_line.hpp"
#include "pierre/sim/results.hpp"

namespace pierre::design {

inline constexpr std::size_t kStopReasonCount = 6;  // the values of sim::StopReason

// Samples kept while a run streams by: only what the statistics need.
struct LineSamples {
  std::vector<double> speed;                 // m/s
  std::vector<double> height;                // m, passing height
  std::vector<double> translational_energy;  // J
  std::vector<double> rotational_energy;     // J (for the barrier design, design-checks.md §1)
};

class RunSamples {
 public:
  RunSamples() = default;
  // `main_direction`: +1 when the profile runs towards increasing x (Profile::main_direction).
  // `every_crossing`: the statistics use every crossing given (model-2d.md §5: when the user
  // asks for all crossings); the first ones are kept beside them for the barrier design.
  RunSamples(std::size_t line_count, int main_direction, bool every_crossing = false);

  // A quarry scenario's sections, run one after the other into one RunSamples: each has its own
  // profile, so where energy stops fell is kept per section (an x range over two profiles
  // means nothing), and the trajectories that follow run in `main_direction`.
  void begin_section(std::string name, int main_direction);

  void add(const sim::TrajectorySummary& t);
  // Keeps the crossing in lines() when it is its trajectory's first on that line in the main
  // direction, and in every() when every crossing is asked for. Crossings must arrive in
  // trajectory order (as the runner delivers them).
  void add(const sim::Crossing& c);

  // First crossings in the main direction: the barrier design's sample (design-checks.md §1).
  const std::vector<LineSamples>& lines() const { return lines_; }
  bool every_crossing() const { return every_crossing_; }
  const std::vector<LineSamples>& every() const { return every_; }  // empty unless asked for
  const std::vector<double>& runout() const { return runout_; }  // m, one per trajectory
  // The shortest runout of a block still moving where its trajectory ended (it left the
  // profile, or a limit or a numerical failure cut it off); +inf when none was.
  double moving_runout_min() const { return moving_runout_min_; }
  const std::array<std::uint64_t, kStopReasonCount>& stop_reasons() const { return stops_; }
  // Energy stops on ground steeper than its friction angle (TrajectorySummary), and the
  // steepest such ground's tan β.
  std::uint64_t steep_energy_stops() const { return steep_energy_stops_; }
  double steepest_energy_stop_tan() const { return steepest_tan_; }
  // Where they stopped: the least and the largest x (m; +inf and −inf when none did).
  double steep_energy_stop_x_min() const { return steep_x_min_; }
  double steep_energy_stop_x_max() const { return steep_x_max_; }
  // The same per section (begin_section), in the order they ran; empty without sections.
  struct SectionSteepStops {
    std::string section;
    std::uint64_t count = 0;
    double x_min = std::numeric_limits<double>::infinity();
    double x_max = -std::numeric_limits<double>::infinity();
  };
  const std::vector<SectionSteepStops>& steep_energy_stops_by_section() const { return steep_sections_; }
  // Energy stops at the trajectory's first impact, and the range of their largest speeds (m/s;
  // 0 and 0 when there are none).
  std::uint64_t first_impact_stops() const { return first_impact_stops_; }
  double first_impact_stop_speed_min() const { return first_impact_stops_ ? first_stop_speed_min_ : 0.0; }
  double first_impact_stop_speed_max() const { return first_stop_speed_max_; }
  std::uint64_t trajectories() const { return runout_.size(); }

 private:
  std::vector<LineSamples> lines_;
  bool every_crossing_ = false;
  std::vector<LineSamples> every_;
  std::vector<std::uint64_t> last_kept_;  // per line: 1 + trajectory of the last kept crossing
  int main_direction_ = 1;
  std::vector<double> runout_;
  double moving_runout_min_ = std::numeric_limits<double>::infinity();
  std::array<std::uint64_t, kStopReasonCount> stops_{};
  std::uint64_t steep_energy_stops_ = 0;
  double steepest_tan_ = 0;
  double steep_x_min_ = std::numeric_limits<double>::infinity();
  double steep_x_max_ = -std::numeric_limits<double>::infinity();
  std::vector<SectionSteepStops> steep_sections_;
  std::uint64_t first_impact_stops_ = 0;
  double first_stop_speed_min_ = std::numeric_limits<double>::infinity(), first_stop_speed_max_ = 0;
};

// count, mean, P50, P95 and max of one quantity; NaN statistics when count is 0.
struct QuantityStatistics {
  std::uint64_t count = 0;
  double mean = 0, p50 = 0, p95 = 0, max = 0;
};

struct LineStatistics {
  std::string name;
  double chainage = 0;            // m
  std::uint64_t count = 0;        // crossings in the statistics (= trajectories that crossed in
                                  // the main direction, unless every crossing is counted)
  std::uint64_t not_reached = 0;  // trajectories that did not cross in the main direction
  QuantityStatistics speed;                 // m/s
  QuantityStatistics height;                // m
  QuantityStatistics translational_energy;  // J
};

struct RunoutStatistics {
  std::uint64_t count = 0;
  double p50 = 0, p95 = 0, p99 = 0, max = 0;  // m; NaN when count is 0
  // A block that left the profile onwards or was cut off was still moving: its runout is a
  // lower bound (right-censored), and so is every percentile that reaches, or interpolates
  // towards, the shortest of theirs: every one above `lower_bound_from`, the largest runout
  // below that shortest (m; −inf when none is below it, +inf when every block came to rest).
  // User review: P95 = P99 = max = 85.00 m, the profile's end, read as runouts.
  double lower_bound_from = std::numeric_limits<double>::infinity();
  bool is_lower_bound(double v) const { return v > lower_bound_from; }
};

struct StopReasonCount {
  sim::StopReason reason;
  std::uint64_t count = 0;
};

struct RunStatistics {
  std::uint64_t trajectories = 0;
  bool every_crossing = false;  // the lines' statistics count every crossing, both directions
  std::vector<LineStatistics> lines;
  RunoutStatistics runout;
  std::vector<StopReasonCount> stop_reasons;  // every reason, in enum order, zeros included
  // Of the energy stops, those on ground steeper than its friction angle (model-2d.md §3 step 8
  // stops a block whatever the slope).
  std::uint64_t energy_stops_on_steep_ground = 0;
  double steepest_energy_stop_deg = 0;  // the steepest ground of those (°)
  double energy_stop_steep_x_min = 0, energy_stop_steep_x_max = 0;  // where they stopped (m)
  // In a quarry scenario, per section with such stops (each its own profile's x); the pooled
  // range above is then not given (0, 0).
  std::vector<RunSamples::SectionSteepStops> energy_stops_on_steep_ground_by_section;
  // Energy stops at the first impact: blocks that never got going, dropped gently (a source a
  // little above the ground) or hard (a fall so long that the impact takes nearly everything:
  // the restitution factors fall as its energy rises, Eq 6.4). Their largest speed, from the
  // slowest to the fastest, m/s: the speed they struck at, unless thrown faster than that.
  std::uint64_t energy_stops_at_first_impact = 0;
  double first_impact_stop_speed_min = 0, first_impact_stop_speed_max = 0;
};

RunStatistics run_statistics(const std::vector<sim::ObservationLine>& lines,
                             const RunSamples& samples);
// Count, mean, 50th and 95th percentile (stats::percentiles) and maximum; NaN for an empty sample.
QuantityStatistics quantity_statistics(std::span<const double> values);

// What the engineer must know about how the trajectories ended, one sentence each (the console
// and the report print the same words): blocks cut off by a limit, whose stop points are not
// where they came to rest, and blocks that left the profile, whose runouts make the runout
// percentiles lower bounds; blocks the energy criterion stopped on ground steeper than its
// friction angle; a share of kFirstImpactStopShare or more stopped at their first impact.
// Empty when every block came to rest where it could stay.
std::vector<std::string> stop_reason_notes(const RunStatistics& s);
// From this share of the trajectories on, stops at the first impact are noted: a few are a
// block that struck flat ground gently; a twentieth is a source that drops its blocks dead.
inline constexpr double kFirstImpactStopShare = 0.05;
// A first impact at this speed or more (a free fall of some 5 m) is a hard one, not a drop.
inline constexpr double kHardFirstImpactSpeed = 10.0;  // m/s

}  // namespace pierre::design
