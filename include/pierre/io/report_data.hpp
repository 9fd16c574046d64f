// What the design report (report.xlsx) shows: everything gathered by the run and the checks,
// as plain data. The layout (sheets, headings, units, formats, charts) comes from templates/.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pierre/design/barrier_check.hpp"
#include "pierre/design/check_line.hpp"
#include "pierre/design/quarry_zones.hpp"
#include "pierre/design/run_statistics.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "pierre/sim/results.hpp"

namespace pierre::io {

struct ReportData {
  const LoadedScenario* scenario = nullptr;  // inputs as read (echoed on the Inputs sheet)
  std::string pierre_version;
  std::string date;           // ISO date of the run (the workbook's creation time is fixed)
  std::uint64_t seed = 0;
  std::uint32_t throws = 0;
  std::vector<std::string> rule_sets;  // names and titles of the rule sets used
  design::RunStatistics statistics;
  const design::RunSamples* samples = nullptr;  // the samples at the lines (barrier charts)
  std::vector<design::BarrierDesign> barriers;
  std::vector<design::CheckLine> checks;        // every check line, all subjects
  // Quarry danger zones (design-checks.md §2): the design, and per section its profile and a
  // few trajectory paths (sections have their own profiles).
  std::optional<design::QuarryDesign> quarry;
  struct QuarrySectionView {
    std::string name;
    const geometry::Profile* profile = nullptr;
    std::vector<std::vector<geometry::Vec2>> paths;
    std::uint64_t seed = 0;  // of the section's own run: with it the run can be repeated
  };
  std::vector<QuarrySectionView> quarry_sections;
  std::vector<std::vector<geometry::Vec2>> sample_paths;  // a few trajectories, for drawing
  // The first rows of the data sheets (the CSVs hold everything); the caps are stated on
  // the sheets.
  std::vector<sim::TrajectorySummary> trajectories;
  std::vector<sim::Crossing> crossings;
  std::uint64_t total_trajectories = 0, total_crossings = 0;
  // A quarry run: the section of each row above (an index into scenario->quarries); the
  // sheets then lead with a section column and take names from that section. Empty otherwise.
  std::vector<std::uint32_t> trajectory_sections, crossing_sections;
};

}  // namespace pierre::io
