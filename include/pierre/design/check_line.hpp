// One design check, as every check reports it (design-checks.md: id, what, value, limit, unit,
// rule, status). FAIL makes `pierre check` exit 1; WARN is advisory and never does.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace pierre::design {

enum class CheckStatus { pass, fail, warn, not_applicable };

std::string_view to_string(CheckStatus s);  // "PASS", "FAIL", "WARN", "N/A"

struct CheckLine {
  std::string subject;  // what is checked: a barrier or a quarry section, by name
  std::string id;       // e.g. "energy.mel", "height.interception", "zone.crusher"
  std::string what;     // a sentence an engineer reads: what the value and the limit are
  double value = std::numeric_limits<double>::quiet_NaN();
  double limit = std::numeric_limits<double>::quiet_NaN();
  std::string unit;     // of value and limit: "kJ", "m", "%", "" …
  std::string rule;     // rule set and clause, e.g. "peila-ronco-2009 §4 (γE,MEL)"
  CheckStatus status = CheckStatus::not_applicable;
  std::string reason;   // why it passes or fails, in words ("candidate MEL 2000 kJ < required 2241 kJ")
};

// value >= limit, up to rounding: a limit worked out from decimal inputs (1.3 × 3 m is
// 3.9000000000000004 m in binary) is met by the value it equals on paper. The slack, 1e-9 of
// the larger magnitude, is far below anything an engineer could measure or build.
inline bool at_least(double value, double limit) {
  return value >= limit - 1e-9 * std::max(std::abs(value), std::abs(limit));
}
// value <= limit, up to rounding (as at_least).
inline bool at_most(double value, double limit) { return at_least(limit, value); }

// True when any line FAILs (or, with `warn_fails`, WARNs): the exit code of `pierre check`
// (--fail-on-warn for a gate that takes no advisory line either).
bool any_failure(const std::vector<CheckLine>& lines, bool warn_fails = false);
// How many lines have `status`: the verdict's counts (console, summary.json, report).
std::size_t count_status(const std::vector<CheckLine>& lines, CheckStatus status);

// An input the reader noted as a likely slip (a density in t/m³, a work area in cm), and the
// check lines it bears on.
struct DoubtedInput {
  std::string field;    // as the note names it: "blocks.density"
  std::string subject;  // the lines' subject (a barrier, a quarry section); empty: every subject
  // Check ids, a prefix where one ends in '.'; empty: every line that rests on the simulation
  // (all but `elongation`, which compares two declared values: a distance and an elongation).
  std::vector<std::string> ids;
  double value = std::numeric_limits<double>::quiet_NaN();  // as noted: what [confirmed] restates
};
// Each PASS among the lines a doubted input bears on is a WARN, its reason saying which input
// to confirm: `pierre check` is the gate a pipeline relies on, and a result the program itself
// doubts must not come out as a plain PASS. FAIL, WARN and N/A stay as they are.
void doubt_passes(std::vector<CheckLine>& lines, const std::vector<DoubtedInput>& doubts);

// sample.size, barriers' and quarries' alike (design-checks.md §1 step 8, docs/quarry.md): a
// bootstrap interval's half-width falls as 1/√n, so a relative half-width `relative` above
// `tolerance` asks for n · (relative / tolerance)² trajectories instead of the n = `trajectories`
// run, i.e. `throws` · (relative / tolerance)² throws per block and source. Both rounded up.
struct SampleNeeded {
  double trajectories = 0;
  double throws = 0;  // per block and source; 0 when the run's throws are not known (0)
};
SampleNeeded sample_needed(double trajectories, std::uint32_t throws, double relative,
                           double tolerance);
// ", i.e. throws = 17 per block and source (… 22 leaves a margin)", the end of a sample.size
// reason; empty when the throws are not known. The estimate moves with the run's own interval
// (a half-width squared: 653 trajectories in one run, 834 in another), so a quarter more is
// offered as a margin.
inline constexpr double kSampleMargin = 1.25;
std::string throws_needed_text(const SampleNeeded& needed);

// A PASS whose margin lies inside the bootstrap interval of what it is judged against, barriers'
// capacities and quarries' zones alike: "within <whose> 90 % bootstrap interval (<bound>)",
// bound "up to 25.1 m" (a limit to stay above) or "down to 20.4 m" (one to stay below), and
// what follows from it.
std::string within_interval_text(std::string_view whose, double confidence, const std::string& bound);
inline constexpr std::string_view kWithinUncertainty =
    ": the margin is within the sampling uncertainty; more throws settle it";

}  // namespace pierre::design
