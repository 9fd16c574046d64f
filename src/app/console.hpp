// Console output of `pierre run`: the progress bar on stderr and the results table on stdout.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "pierre/design/run_statistics.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::app {

// Percentage, trajectories per second and ETA on one line of stderr, redrawn at most five times
// a second. Disabled (does nothing) unless `enabled`; the caller passes isatty(2) && !quiet.
class ProgressBar {
 public:
  explicit ProgressBar(bool enabled);
  void update(std::uint64_t done, std::uint64_t total);  // from one thread at a time
  void finish();                                         // erases the line

 private:
  using clock = std::chrono::steady_clock;
  bool enabled_;
  bool drawn_ = false;
  clock::time_point start_, last_;
};

// A note for each source whose ground falls towards the profile's first vertex (its blocks
// travel against the main direction, in which observation lines count first crossings).
void print_source_notes(std::FILE* out, const sim::Scenario& scenario);

void print_results(std::FILE* out, const design::RunStatistics& stats, double seconds,
                   const std::vector<std::filesystem::path>& files);

// The barriers' design values, then every check line as a table (subject, id, value, limit,
// unit, status, rule), then the reason of each line that is not PASS or N/A.
void print_design(std::FILE* out, const io::DesignResults& results);

}  // namespace pierre::app
