// A quarry danger-zone rule set (design-checks.md §2, "Zones"): plain data read by io from
// rules/<name>.toml (io::load_quarry_rules). The code knows the procedure; every number lives
// in the file, with its source, so an engineer can add a rule set without recompiling.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "pierre/design/bootstrap_size.hpp"

namespace pierre::design {

// One candidate for the governing distance; the governing distance is the LARGEST of the
// candidates the rule set lists.
enum class QuarryGoverning {
  percentile,  // the empirical percentile `percentile` of the simulated sample
  maximum,     // the simulated maximum
  lognormal,   // the distance exceeded with probability 1 − lognormal_percentile/100 under the
               // fitted log-normal with its point mass of zeros (P = (1 − p0) S_logn)
};

// The rule set of a quarry section that names none (rules/quarry-thesis-2015.toml).
inline constexpr const char* kDefaultQuarryRules = "quarry-thesis-2015";

struct QuarryRuleSet {
  std::string name;    // file stem, e.g. "quarry-thesis-2015"
  std::string title;   // human title
  std::string source;  // citation
  std::string file;    // where it was read from (empty when made in code); for the record
  double floor_angle_deg = 15;  // toe detection: the floor is flatter than this
  std::vector<QuarryGoverning> governing{QuarryGoverning::percentile};
  double percentile = 95;             // % (percentile candidate)
  double lognormal_percentile = 99;   // % (lognormal candidate)
  double retention_target = 0.90;     // bench.retention: share of all blocks (0..1)
  double ritchie_factor = 0.2;        // bench.ritchie: width = factor · H + offset
  double ritchie_offset = 4.5;        // m
  std::size_t min_reached = 30;       // sample.size: fewest blocks reaching the floor
  double sample_tolerance = 0.05;     // sample.size: RD_gov's CI half-width / RD_gov above which it WARNs
  double sample_confidence = kMinBootstrapConfidence;  // of the bootstrap interval
  std::size_t sample_resamples = kMinBootstrapResamples;
  double fit_p_value = 0.05;          // fit.ID, fit.RD: KS p-value below which they WARN
  std::map<std::string, std::string> clauses;  // check id ("zone", "bench.retention", …) -> clause
};

}  // namespace pierre::design
