// Time of the design report (bench/README.md) for 10^6 crossings at one barrier: the barrier
// procedure (design::design_barrier: Weibull and log-normal ML fits, KS tests, 1000-resample
// bootstraps) and report.xlsx (io::write_report: statistics, histograms and CDFs over every
// crossing, charts, data sheets capped by templates/report.toml). The scenario is
// examples/vaujany-2d (its first barrier, "Screen 1 design", thesis-2015); the crossings are
// drawn here from known Weibulls (speed k = 3.2, λ = 22 m/s; height k = 1.37, λ = 1.55 m) by
// inversion on Philox uniforms, so every run times the same numbers. Wall-clock seconds, one
// thread.
//
//   bench_report [n] [out.xlsx]          n crossings (default 1000000); the workbook goes to
//                                        out.xlsx (default: a temporary file, removed)
//   bench_report --run SCENARIO out.xlsx a real run instead: simulate the scenario, design
//                                        every barrier, write the report (to look at it)
#include <Random123/philox.h>
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "pierre/design/barrier_check.hpp"
#include "pierre/design/run_statistics.hpp"
#include "pierre/io/report_data.hpp"
#include "pierre/io/report_template.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "pierre/io/xlsx_report.hpp"
#include "pierre/sim/runner.hpp"
#include "pierre/sim/trajectory.hpp"
#include "pierre/stats/bootstrap.hpp"
#include "pierre/stats/kolmogorov_smirnov.hpp"
#include "pierre/stats/lognormal_fit.hpp"
#include "pierre/stats/resample_index_stream.hpp"
#include "pierre/stats/weibull_fit.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace pierre;

template <class F>
double seconds(F&& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double uniform(std::uint32_t i, std::uint32_t stream) {
  const r123::Philox4x32::key_type key{{2015u, stream}};
  r123::Philox4x32 philox;
  const auto b = philox(r123::Philox4x32::ctr_type{{i, 0u, 0u, 0u}}, key);
  return stats::open_unit_interval((std::uint64_t{b[0]} << 32) | b[1]);
}

const char* kVersion = PIERRE_VERSION;

// The barrier sample of line `line` from time-ordered results (design-checks.md §1 step 1).
design::BarrierSample barrier_sample(const sim::Scenario& sc, const design::RunSamples& rs,
                                     std::size_t line) {
  design::BarrierSample s;
  if (line < rs.lines().size()) {
    const auto& ls = rs.lines()[line];
    s.speed = ls.speed;
    s.height = ls.height;
    s.energy = ls.translational_energy;
    s.rotational_energy = ls.rotational_energy;
  }
  s.not_reached = rs.trajectories() >= s.speed.size() ? rs.trajectories() - s.speed.size() : 0;
  s.blocks = design::blocks_thrown(sc.blocks);
  s.throws = sc.settings.throws;
  return s;
}

std::size_t line_of(const sim::Scenario& sc, const std::string& name) {
  for (std::size_t i = 0; i < sc.lines.size(); ++i)
    if (sc.lines[i].name == name) return i;
  return sc.lines.size();
}

void design_all(const io::LoadedScenario& loaded, const design::RunSamples& rs,
                io::ReportData& d) {
  const auto& sc = loaded.scenario;
  for (std::size_t i = 0; i < loaded.barriers.size(); ++i) {
    const auto& spec = loaded.barriers[i];
    const std::size_t li = line_of(sc, spec.line);
    const auto o = design::design_barrier(
        spec, loaded.barrier_rules[i], loaded.barrier_classes[i], barrier_sample(sc, rs, li),
        loaded.barrier_observed[i], li < sc.lines.size() ? sc.lines[li].x : 0.0,
        design::barrier_bootstrap_seed(sc.settings.seed, i));
    if (!o.design) {
      fmt::print(stderr, "barrier {}: no design: {}\n", spec.name, o.error);
      continue;
    }
    d.checks.insert(d.checks.end(), o.design->checks.begin(), o.design->checks.end());
    d.barriers.push_back(*o.design);
    const std::string rs_name = loaded.barrier_rules[i].name + " — " + loaded.barrier_rules[i].title;
    if (std::find(d.rule_sets.begin(), d.rule_sets.end(), rs_name) == d.rule_sets.end())
      d.rule_sets.push_back(rs_name);
  }
}

int real_run(const fs::path& scenario, const fs::path& out) {
  const auto loaded = io::load_scenario(scenario, fs::path(PIERRE_SOURCE_DIR) / "rules");
  const auto& sc = loaded.scenario;
  sim::ResultCollector collector;
  sim::RunOptions opt;
  const auto report = sim::run_simulation(sc, opt, collector);
  if (report.error) {
    fmt::print(stderr, "run failed: {}\n", *report.error);
    return 1;
  }
  auto& tr = collector.trajectories;
  auto& cr = collector.crossings;
  std::sort(tr.begin(), tr.end(), [](auto& a, auto& b) { return a.trajectory < b.trajectory; });
  std::stable_sort(cr.begin(), cr.end(),
                   [](auto& a, auto& b) { return a.trajectory < b.trajectory; });
  design::RunSamples rs(sc.lines.size(), sc.profile.main_direction());
  for (const auto& t : tr) rs.add(t);
  for (const auto& c : cr) rs.add(c);

  io::ReportData d;
  d.scenario = &loaded;
  d.pierre_version = kVersion;
  d.date = "2024-05-17";
  d.seed = sc.settings.seed;
  d.throws = sc.settings.throws;
  d.statistics = design::run_statistics(sc.lines, rs);
  design_all(loaded, rs, d);
  // A few paths to draw.
  const sim::TrajectoryModel model(sc);
  sim::ObservationTally tally(sc.lines, sc.profile, false);
  std::vector<sim::Crossing> sink;
  tally.output(&sink);
  const std::uint64_t n = sc.trajectory_count();
  for (std::uint64_t k = 0; k < 12 && k < n; ++k) {
    std::vector<geometry::Vec2> path;
    (void)sim::simulate_trajectory(model, k * (n / 12), tally, nullptr, &path, 0.05);
    d.sample_paths.push_back(std::move(path));
  }
  d.total_trajectories = tr.size();
  d.total_crossings = cr.size();
  d.trajectories = std::move(tr);
  d.crossings = std::move(cr);
  const auto tpl = io::load_report_template(fs::path(PIERRE_SOURCE_DIR) / "templates/report.toml");
  const double t = seconds([&] { io::write_report(out, d, tpl); });
  fmt::print("{} trajectories, {} crossings, {} barriers: report written in {:.2f} s to {}\n",
             d.total_trajectories, d.total_crossings, d.barriers.size(), t, out.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc > 1 && std::string(argv[1]) == "--run") {
    if (argc != 4) {
      fmt::print(stderr, "usage: bench_report --run SCENARIO OUT.xlsx\n");
      return 2;
    }
    return real_run(argv[2], argv[3]);
  }
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1'000'000;
  const fs::path out = argc > 2 ? fs::path(argv[2])
                                : fs::temp_directory_path() /
                                      fmt::format("bench-report-{}.xlsx", std::rand());

  double t_load = 0;
  io::LoadedScenario loaded;
  io::ReportTemplate tpl;
  t_load = seconds([&] {
    loaded = io::load_scenario(fs::path(PIERRE_SOURCE_DIR) / "examples/vaujany-2d/scenario.toml",
                               fs::path(PIERRE_SOURCE_DIR) / "rules");
    tpl = io::load_report_template(fs::path(PIERRE_SOURCE_DIR) / "templates/report.toml");
  });
  const auto& sc = loaded.scenario;
  const auto& spec = loaded.barriers.at(0);
  const std::size_t li = line_of(sc, spec.line);
  const int dir = sc.profile.main_direction();

  // n first crossings at the barrier's line, one per trajectory, in trajectory order.
  io::ReportData d;
  d.scenario = &loaded;
  d.pierre_version = kVersion;
  d.date = "2024-05-17";
  d.seed = sc.settings.seed;
  d.throws = sc.settings.throws;
  d.crossings.resize(n);
  const double mass = 3180;
  for (std::size_t i = 0; i < n; ++i) {
    sim::Crossing& c = d.crossings[i];
    c.trajectory = i;
    c.line = static_cast<std::uint32_t>(li);
    c.mass = mass;
    c.direction = dir;
    c.speed = 22.0 * std::pow(-std::log(uniform(static_cast<std::uint32_t>(i), 1)), 1 / 3.2);
    c.height = 1.55 * std::pow(-std::log(uniform(static_cast<std::uint32_t>(i), 2)), 1 / 1.37);
    c.velocity = {0.95 * c.speed, -0.31 * c.speed};
    c.translational_energy = 0.5 * mass * c.speed * c.speed;
    c.rotational_energy = 0.04 * c.translational_energy;
    c.time = 6;
  }
  d.total_crossings = n;
  d.total_trajectories = n;
  for (std::size_t i = 0; i < 20000 && i < n; ++i) {
    sim::TrajectorySummary t;
    t.trajectory = i;
    t.mass = mass;
    t.start = {6.5, 350.6};
    t.stop = {250, 180};
    t.stop_reason = sim::StopReason::energy;
    d.trajectories.push_back(t);
  }

  // The barrier procedure on the whole sample.
  design::RunSamples rs(sc.lines.size(), dir);
  for (std::size_t i = 0; i < n; ++i) {
    sim::TrajectorySummary t;
    t.trajectory = i;
    rs.add(t);
    rs.add(d.crossings[i]);
  }
  d.statistics = design::run_statistics(sc.lines, rs);
  io::LoadedScenario one = loaded;  // the first barrier only
  one.barriers.resize(1);
  one.barrier_rules.resize(1);
  one.barrier_rules_files.resize(1);
  one.barrier_classes.resize(1);
  one.barrier_observed.resize(1);
  // The statistics calls the procedure makes, timed on their own: ML fits and KS tests of
  // speed, height and energy, and the order-statistic bootstrap of v_k and h_k.
  const auto& ls = rs.lines()[li];
  std::vector<double> e_kJ(ls.translational_energy);
  for (double& e : e_kJ) e /= 1000;
  const double t_stats = seconds([&] {
    for (const std::vector<double>* x : {&ls.speed, &ls.height, static_cast<const std::vector<double>*>(&e_kJ)}) {
      const auto w = stats::fit_weibull(*x);
      const auto l = stats::fit_lognormal(*x);
      if (w) (void)stats::kolmogorov_smirnov(*x, [&](double v) { return stats::cdf(*w, v); });
      if (l) (void)stats::kolmogorov_smirnov(*x, [&](double v) { return stats::cdf(*l, v); });
    }
    (void)stats::bootstrap_percentile_interval(ls.speed, 95, 1);
    (void)stats::bootstrap_percentile_interval(ls.height, 95, 2);
  });
  const double t_design = seconds([&] { design_all(one, rs, d); });
  const double t_write = seconds([&] { io::write_report(out, d, tpl); });
  const auto bytes = fs::file_size(out);
  if (argc <= 2) fs::remove(out);

  fmt::print("bench_report: {} crossings at \"{}\" (one barrier), data sheets capped at {} / {} "
             "rows\n",
             n, spec.line, tpl.trajectory_rows, tpl.crossing_rows);
  fmt::print("  load scenario and template   {:8.3f} s\n", t_load);
  fmt::print("  stats calls alone (3 × Weibull + log-normal fit and KS, 2 percentile "
             "bootstraps)  {:8.3f} s\n", t_stats);
  fmt::print("  design_barrier (fits, KS, bootstrap)  {:8.3f} s\n", t_design);
  fmt::print("  write_report ({:.1f} MB)        {:8.3f} s\n", static_cast<double>(bytes) / 1e6,
             t_write);
  fmt::print("  total (design + report)      {:8.3f} s   (goal < 5 s on one core)\n",
             t_design + t_write);
  return 0;
} catch (const std::exception& e) {
  fmt::print(stderr, "bench_report: {}\n", e.what());
  return 1;
}
