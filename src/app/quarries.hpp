// `pierre run` and `pierre check` on a quarry scenario (docs/quarry.md, design-checks.md §2):
// every [[quarries]] section simulated in file order with its own seed, its trajectories
// streamed to the shared CSV files (a `section` column first) and to its first-impact and
// runout distances, then the danger-zone procedure (design::design_quarry), summary.json with
// "quarries" and "checks", the tables on stdout. Memory: the per-trajectory distances the
// procedure needs, not the trajectories.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "pierre/design/quarry_zones.hpp"
#include "pierre/io/report_data.hpp"
#include "pierre/io/report_template.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "run_steps.hpp"

namespace pierre::app {

struct QuarryRunOptions {
  std::string out;                       // output folder
  unsigned threads = 0;
  RunFlags flags;
  bool quiet = false;
  double log_seconds = 60;  // progress lines when stderr is not a terminal (progress_log_seconds)
  bool* committed = nullptr;  // set once the results are in place (a failure after it wrote them)
};

// Runs a quarry scenario (loaded.quarries not empty); returns the exit code: 0, or 1 when
// `check` and a check line FAILs. Nothing is written in `out` unless every section ran.
int run_quarries(io::LoadedScenario& loaded, const io::ReportTemplate& layout,
                 const QuarryRunOptions& options);

// The quarry table (Tables 6.2/6.3: n, RD and ID P50/P95/P99/max in m and /H, calculated beside
// observed where given, RD_gov and ID_gov) and each section's geometry and zones. A blank line
// leads only when `follows_output` (`check --quiet` starts with the table).
void print_quarries(std::FILE* out, const design::QuarryDesign& design, bool follows_output = true);

// What the report shows of a quarry run: the design and, per section, its profile and
// `paths_per_section` trajectories re-run with their paths recorded (the section's own random
// streams: the same trajectories as in the results).
void add_quarry_report_data(io::ReportData& data, const io::LoadedScenario& loaded,
                            const design::QuarryDesign& design, std::size_t paths_per_section = 10);

}  // namespace pierre::app
