#include "report.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>

#include <fmt/format.h>

#include "pierre/io/input_error.hpp"
#include "pierre/io/report_template.hpp"
#include "pierre/io/version.hpp"
#include "pierre/io/xlsx_report.hpp"
#include "pierre/sim/trajectory.hpp"

namespace pierre::app {

void FirstRows::consume(sim::ChunkResult&& chunk) {
  total_trajectories += chunk.trajectories.size();
  total_crossings += chunk.crossings.size();
  for (const auto& t : chunk.trajectories) {
    if (trajectories.size() >= max_trajectories_) break;
    trajectories.push_back(t);
  }
  for (const auto& c : chunk.crossings) {
    if (crossings.size() >= max_crossings_) break;
    crossings.push_back(c);
  }
  next_.consume(std::move(chunk));
}

std::vector<std::vector<geometry::Vec2>> sample_paths(const sim::Scenario& scenario,
                                                      std::size_t count) {
  std::vector<std::vector<geometry::Vec2>> paths;
  const std::uint64_t total = scenario.trajectory_count();
  if (total == 0) return paths;
  const sim::TrajectoryModel model(scenario);
  sim::ObservationTally tally(scenario.lines, scenario.profile, false);
  std::vector<sim::Crossing> ignored;
  tally.output(&ignored);
  const std::uint64_t n = std::min<std::uint64_t>(count, total);
  for (std::uint64_t k = 0; k < n; ++k) {
    std::vector<geometry::Vec2> path;
    sim::simulate_trajectory(model, k * total / n, tally, nullptr, &path, 0.05);
    paths.push_back(std::move(path));
  }
  return paths;
}

namespace {
std::string iso_date(std::time_t t) {
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[16];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
  return buf;
}
}  // namespace

std::string report_date() {
  // SOURCE_DATE_EPOCH (reproducible-builds.org) pins the date, so a regenerated report is
  // byte-identical; else today's date. Seconds since 1970 up to the end of year 9999, the last
  // day a workbook's date holds (milliseconds, a common slip, are 1000 times too many).
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch || !*epoch) return iso_date(std::time(nullptr));
  const std::string text = epoch;
  constexpr long long kLast = 253402300799;  // 9999-12-31T23:59:59Z
  const bool digits = text.size() <= 12 && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits || std::stoll(text) > kLast)
    throw io::InputError("environment", 0, "SOURCE_DATE_EPOCH", "\"" + text + "\"",
                         "whole seconds since 1970-01-01 UTC, 0 to 253402300799 (the report's "
                         "date; unset it for today's)");
  return iso_date(static_cast<std::time_t>(std::stoll(text)));
}

io::ReportData report_data(const io::LoadedScenario& loaded,
                           const design::RunStatistics& statistics) {
  io::ReportData d;
  d.scenario = &loaded;
  d.pierre_version = io::version_text();
  d.date = report_date();
  d.seed = loaded.scenario.settings.seed;
  d.throws = loaded.scenario.settings.throws;
  d.statistics = statistics;
  return d;
}

void write_run_report(const std::filesystem::path& file, const io::ReportTemplate& layout,
                      const io::LoadedScenario& loaded,
                      const design::RunStatistics& statistics, const design::RunSamples& samples,
                      const io::DesignResults& design, FirstRows&& first) {
  io::ReportData d = report_data(loaded, statistics);
  for (const auto& r : loaded.barrier_rules) {
    const std::string entry = r.title.empty() ? r.name : r.name + " — " + r.title;
    if (std::find(d.rule_sets.begin(), d.rule_sets.end(), entry) == d.rule_sets.end())
      d.rule_sets.push_back(entry);
  }
  d.samples = &samples;
  d.barriers = design.barriers;
  d.checks = design.checks;
  d.sample_paths = sample_paths(loaded.scenario, 30);
  d.trajectories = std::move(first.trajectories);
  d.crossings = std::move(first.crossings);
  d.total_trajectories = first.total_trajectories;
  d.total_crossings = first.total_crossings;
  io::write_report(file, d, layout);
}

}  // namespace pierre::app
