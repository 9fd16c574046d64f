// The design report of a run (report.xlsx): gathers what io::write_report shows. Shared by
// `pierre run` and `pierre check`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "pierre/design/run_statistics.hpp"
#include "pierre/io/report_data.hpp"
#include "pierre/io/report_template.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "pierre/sim/runner.hpp"

namespace pierre::app {

// Passes every chunk on to another sink and keeps the first rows for the report's data sheets
// (the CSV files hold everything).
class FirstRows final : public sim::ResultSink {
 public:
  FirstRows(sim::ResultSink& next, std::size_t trajectories, std::size_t crossings)
      : next_(next), max_trajectories_(trajectories), max_crossings_(crossings) {}
  void prepare(sim::ChunkResult& chunk) const override { next_.prepare(chunk); }
  void consume(sim::ChunkResult&& chunk) override;

  std::vector<sim::TrajectorySummary> trajectories;
  std::vector<sim::Crossing> crossings;
  std::uint64_t total_trajectories = 0, total_crossings = 0;

 private:
  sim::ResultSink& next_;
  std::size_t max_trajectories_, max_crossings_;
};

// A few trajectories of the scenario re-run with their paths recorded (the same random streams,
// so the same trajectories as in the results), evenly spread over the run.
std::vector<std::vector<geometry::Vec2>> sample_paths(const sim::Scenario& scenario,
                                                      std::size_t count);

// The report's date, YYYY-MM-DD: SOURCE_DATE_EPOCH's when set, else today's (UTC). Throws
// io::InputError for a SOURCE_DATE_EPOCH that is not whole seconds up to the year 9999.
std::string report_date();

// The report's common part: scenario, version, date (SOURCE_DATE_EPOCH or today), seed, throws,
// run statistics.
io::ReportData report_data(const io::LoadedScenario& loaded, const design::RunStatistics& statistics);

// Writes report.xlsx of a run with barriers into `file`, laid out by `layout`.
void write_run_report(const std::filesystem::path& file, const io::ReportTemplate& layout,
                      const io::LoadedScenario& loaded,
                      const design::RunStatistics& statistics, const design::RunSamples& samples,
                      const io::DesignResults& design, FirstRows&& first);

}  // namespace pierre::app
