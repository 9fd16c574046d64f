// The quarry danger-zone procedure (design-checks.md §2, thesis chapter 6): per section and
// per row (a lone section, or sections pooled by `group`, as the thesis combines near-identical
// sections), the statistics of ID and RD, the governing distances of the rule set, the danger
// zone [0, RD_gov] and first-impact zone [0, ID_gov] from the toe, and the check lines:
//
//   zone.<area>      a work area's distance from the toe vs RD_gov       FAIL if less
//   bench.retention  share of all blocks with RD <= bench width vs target FAIL if below
//   bench.ritchie    bench width vs 0.2·H + 4.5 m (Call 1986; Ryan & Pryor 2000)   WARN if below
//   sample.size      bootstrap CI half-width / RD_p, and blocks reaching the floor  WARN
//   fit.ID, fit.RD   KS p-value of the log-normal fits                   WARN if below
//
// Governing distances are computed on the row's /H sample (each value divided by its own
// section's H) and applied to a section as gov/H × its own H: for a lone section exactly the
// metre values; for a pooled group of equal H the pooled metre values. Pure: data in, a
// QuarryDesign out.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pierre/design/check_line.hpp"
#include "pierre/design/quarry_distances.hpp"
#include "pierre/design/quarry_geometry.hpp"
#include "pierre/design/quarry_rules.hpp"
#include "pierre/design/quarry_statistics.hpp"
#include "pierre/stats/bootstrap.hpp"

namespace pierre::design {

struct WorkArea {
  std::string name;      // check id zone.<name>
  double distance = 0;   // m, horizontal from the toe
};

// Everything a scenario says about one quarry section (io parses it from [[quarries]]).
struct QuarrySpec {
  std::string name;
  std::string group;  // sections with the same non-empty group are pooled into one row
  std::string rules = kDefaultQuarryRules;
  QuarryGeometryInput geometry;  // optional crest, toe, H (floor angle from the rule set)
  std::vector<WorkArea> work_areas;
  std::optional<double> bench_width;  // m, planned catch bench
  std::vector<double> exceedance{0.05, 0.01};  // probabilities asked for (0..1)
  std::string observed_source;  // where the observed values come from (echo)
};

struct QuarryObserved {
  ObservedDistance id, rd;
  std::string source;
};

// One section, ready for the procedure.
struct QuarrySectionInput {
  QuarrySpec spec;
  QuarryRuleSet rules;
  QuarryGeometry geometry;
  QuarryDistances distances;
  QuarryObserved observed;  // may be empty
  std::uint32_t throws = 0;  // per block and source (0: unknown), for sample.size's advice
};

struct ExceedanceDistance {  // one asked probability of exceedance
  double probability = 0;
  double rd_fit_h = 0, rd_empirical_h = 0;  // / H (fit: NaN without a fit)
  double id_fit_h = 0, id_empirical_h = 0;
  double rd_fit = 0, rd_empirical = 0, id_fit = 0, id_empirical = 0;  // m, × the row's H
};

struct GoverningDistance {
  double value_h = 0;      // / H; +infinity: beyond the profile; NaN: no data
  double percentile_h = 0, maximum_h = 0, lognormal_h = 0;  // the candidates (NaN if not used)
  std::string how;         // "P95 = 0.81 H" or "max(max 1.45 H, log-normal P99 1.30 H)"
};

// A line of Tables 6.2/6.3: a lone section, or a group of sections pooled.
struct QuarryRow {
  std::string name;
  std::vector<std::size_t> sections;  // indices into QuarryDesign::sections
  bool pooled = false;
  std::string rules;                 // rule set name
  std::size_t min_reached = 0;       // its min_reached (the report says why a fit is doubtful)
  std::uint32_t throws = 0;          // per block and source of its sections (0: unknown, or unequal)
  double height = 0;                 // m: the section's H, or the mean H of the group
  std::uint64_t thrown = 0, reached_floor = 0, not_reached_floor = 0, above_toe = 0,
                left_profile = 0, left_upslope = 0, abnormal = 0;
  DistanceSample id_sample, rd_sample;  // m and / H
  DistanceStatistics id, rd;
  DurationStatistics duration;
  std::vector<ExceedanceDistance> exceedance;
  GoverningDistance rd_gov, id_gov;
  // RD_gov's bootstrap interval (/H): the governing rule applied afresh to each resample.
  std::optional<stats::BootstrapInterval> rd_interval;
  std::optional<ObservedComparison> observed_id, observed_rd;
};

// What each section gets: its geometry, its own distances, and its zones.
struct QuarrySectionResult {
  QuarrySpec spec;
  std::string rules_title, rules_source;
  std::string rules_file;  // where the rule set was read from
  QuarryGeometry geometry;
  QuarryDistances distances;  // per-trajectory ID/RD (histograms, CDFs)
  std::size_t row = 0;        // index into QuarryDesign::rows
  // Its own statistics (design-checks.md §2: "per section and for sections pooled"); for a
  // lone section the same as its row's.
  DistanceStatistics rd, id;
  double danger_zone = 0;       // m: [0, RD_gov] from the toe (+infinity: beyond the profile)
  double first_impact_zone = 0;  // m: [0, ID_gov]
  std::optional<double> bench_retention;  // share of the row's blocks with RD <= bench width
  std::optional<double> ritchie_width;    // m
  // The danger zone reaches past the section's floor: infinite (more than 1 − p of the blocks
  // left, and the zone checks FAIL) or extrapolated past the floor's end (a WARN says so).
  bool danger_zone_beyond_profile() const {
    return std::isinf(danger_zone) || danger_zone > geometry.floor_length;
  }
};

// The "Average (normalized by H)" lines: means over the rows of the per-row ratios.
struct QuarryAverage {
  std::size_t rows = 0;
  double rd50_h = 0, rd95_h = 0, rdmax_h = 0, id50_h = 0, id95_h = 0, idmax_h = 0;
  std::size_t observed_rows = 0;  // rows with observed values (each mean over those giving it)
  double obs_rd50_h = 0, obs_rd95_h = 0, obs_rdmax_h = 0, obs_id50_h = 0, obs_id95_h = 0,
         obs_idmax_h = 0;
};

struct QuarryDesign {
  std::vector<QuarrySectionResult> sections;
  std::vector<QuarryRow> rows;
  QuarryAverage average;
  DistanceSample all_id, all_rd;   // every section pooled, / H (thesis Fig 6.5)
  DistanceStatistics all_id_statistics, all_rd_statistics;
  std::vector<CheckLine> checks;
};

struct QuarryOutcome {
  std::optional<QuarryDesign> design;
  std::string error;
};

// Runs the procedure. `seed` keys the bootstrap's own streams (row k uses seed + k). Fails only
// when the input is inconsistent (no section; sections of one group with different rule sets;
// a section without H).
QuarryOutcome design_quarry(const std::vector<QuarrySectionInput>& sections, std::uint64_t seed);

// The doubts (check_line.hpp) with those on a section's inputs widened to its row (a group's,
// even of one section) and, for an input of its simulation (blocks, sources: a doubt of every
// line), to the group's other sections, whose zones come from the pooled distances.
std::vector<DoubtedInput> pooled_doubts(const QuarryDesign& design, std::vector<DoubtedInput> doubts);

// The governing distance (/H) of a sample under a rule set.
GoverningDistance governing_distance(const DistanceSample& sample, const DistanceStatistics& stats,
                                     const QuarryRuleSet& rules);

// The same value computed from the sample alone (its normalized values, censoring thresholds
// and `beyond`; the metres are not used), without the text: what the bootstrap evaluates on
// each resample.
double governing_value_h(const DistanceSample& sample, const QuarryRuleSet& rules);

// The bootstrap interval (/H) of the governing distance at the rule set's confidence, from
// `sample_resamples` resamples of the blocks (stream `seed`). A rule of one percentile uses the
// exact order-statistic bootstrap (stats::bootstrap_percentile_interval); any other rule is
// refitted on every resample (a block keeps its censoring threshold). Empty with fewer than two
// values or a resample without a value (e.g. no log-normal fit).
std::optional<stats::BootstrapInterval> governing_interval(const DistanceSample& sample,
                                                           const QuarryRuleSet& rules,
                                                           std::uint64_t seed);

}  // namespace pierre::design
