#include "quarries.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "commands.hpp"
#include "interrupt.hpp"
#include "console.hpp"
#include "report.hpp"
#include "run_steps.hpp"
#include "pierre/design/number_kind.hpp"
#include "pierre/design/quarry_distances.hpp"
#include "pierre/design/run_statistics.hpp"
#include "pierre/io/output_folder.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/io/xlsx_report.hpp"
#include "pierre/sim/runner.hpp"

namespace pierre::app {
namespace {

// Feeds a section's distances (and the run's overall runout and stop reasons) from each chunk,
// then hands the chunk on to the CSV files. Chunks arrive in trajectory order, one at a time.
class QuarrySink final : public sim::ResultSink {
 public:
  QuarrySink(sim::ResultSink& next, const design::QuarryGeometry& geometry, design::RunSamples& all)
      : next_(next), geometry_(geometry), all_(all) {
    distances.censor_distance = geometry.floor_length;
  }
  void prepare(sim::ChunkResult& chunk) const override { next_.prepare(chunk); }
  void consume(sim::ChunkResult&& chunk) override {
    for (const sim::TrajectorySummary& t : chunk.trajectories) {
      distances.add(t, geometry_);
      all_.add(t);
    }
    next_.consume(std::move(chunk));
  }
  design::QuarryDistances distances;

 private:
  sim::ResultSink& next_;
  const design::QuarryGeometry& geometry_;
  design::RunSamples& all_;
};

// A distance in m or in /H, as the quarry sheets and the zone check lines round it (0.01).
std::string metres(double v) { return design::number_cell(v, design::NumberKind::length); }

// "calc / obs" (or "calc" alone when nothing was observed).
std::string pair(double calc, const std::optional<double>& obs) {
  std::string s = metres(calc);
  if (obs) s += " / " + metres(*obs);
  return s;
}

std::optional<double> observed_value(const std::optional<design::ObservedComparison>& o,
                                     double design::ObservedComparison::*field) {
  if (!o) return std::nullopt;
  const double v = (*o).*field;
  if (std::isnan(v)) return std::nullopt;
  return v;
}

}  // namespace

void print_quarries(std::FILE* out, const design::QuarryDesign& d, bool follows_output) {
  fmt::print(out,
             "{}Quarry danger zones (docs/quarry.md; thesis Tables 6.2, 6.3): horizontal "
             "distances from the toe,\ncalculated / observed where observed values are given\n",
             follows_output ? "\n" : "");
  std::size_t wq = column_width(d.rows, 18, [](const design::QuarryRow& r) { return r.name; });
  wq = column_width(d.sections, wq, [](const auto& sec) { return "  " + sec.spec.name; });
  fmt::print(out, "{:<{}} {:>6} {:>6}  {:<6} {:>15} {:>15} {:>8} {:>15}  {}\n", "row", wq, "n", "H m",
             "", "P50", "P95", "P99", "max", "governing");
  for (const design::QuarryRow& r : d.rows) {
    const double H = r.height;
    struct Line {
      const char* label;
      const design::DistanceStatistics* s;
      const std::optional<design::ObservedComparison>* obs;
      bool per_h;
      const design::GoverningDistance* gov;
    };
    const Line lines[] = {{"RD m", &r.rd, &r.observed_rd, false, &r.rd_gov},
                          {"RD/H", &r.rd, &r.observed_rd, true, nullptr},
                          {"ID m", &r.id, &r.observed_id, false, &r.id_gov},
                          {"ID/H", &r.id, &r.observed_id, true, nullptr}};
    bool first = true;
    for (const Line& l : lines) {
      using OC = design::ObservedComparison;
      const double p50 = l.per_h ? l.s->p50_h : l.s->p50, p95 = l.per_h ? l.s->p95_h : l.s->p95,
                   p99 = l.per_h ? l.s->p99_h : l.s->p99, mx = l.per_h ? l.s->max_h : l.s->max;
      const auto o50 = observed_value(*l.obs, l.per_h ? &OC::p50_h : &OC::p50);
      const auto o95 = observed_value(*l.obs, l.per_h ? &OC::p95_h : &OC::p95);
      const auto omx = observed_value(*l.obs, l.per_h ? &OC::max_h : &OC::max);
      std::string gov;
      if (l.gov)
        gov = fmt::format("{}_gov {}{} ({})", l.s == &r.rd ? "RD" : "ID",
                          metres(l.gov->value_h * H),  // as the check lines' m
                          std::isfinite(l.gov->value_h)  ? " m"
                          : std::isinf(l.gov->value_h) ? " the profile"
                                                        : "",  // "-": no values
                          l.gov->how);
      if (first)
        fmt::print(out, "{:<{}} {:>6} {:>6}  ", r.name, wq, l.s->count, metres(H));
      else if (l.s == &r.id && !l.per_h)
        fmt::print(out, "{:<{}} {:>6} {:>6}  ", "", wq, l.s->count, "");
      else
        fmt::print(out, "{:<{}} {:>6} {:>6}  ", "", wq, "", "");
      first = false;
      fmt::print(out, "{:<6} {:>15} {:>15} {:>8} {:>15}{}\n", l.label, pair(p50, o50),
                 pair(p95, o95), metres(p99), pair(mx, omx), gov.empty() ? "" : "  " + gov);
    }
    // A group's sections, each on its own (docs/quarry.md: per section and pooled).
    if (r.sections.size() > 1)
      for (std::size_t i : r.sections) {
        const design::QuarrySectionResult& sec = d.sections[i];
        for (const auto* st : {&sec.rd, &sec.id})
          fmt::print(out, "{:<{}} {:>6} {:>6}  {:<6} {:>15} {:>15} {:>8} {:>15}\n",
                     st == &sec.rd ? "  " + sec.spec.name : "", wq, st->count,
                     st == &sec.rd ? metres(sec.geometry.height) : "",
                     st == &sec.rd ? "RD m" : "ID m", metres(st->p50), metres(st->p95),
                     metres(st->p99), metres(st->max));
      }
  }
  const design::QuarryAverage& a = d.average;
  auto avg = [&](double calc, double obs) {
    return a.observed_rows ? pair(calc, obs) : metres(calc);
  };
  // n is left blank: the average is a mean of the rows' ratios, not a sample of its own.
  fmt::print(out, "{:<{}} {:>6} {:>6}  {:<6} {:>15} {:>15} {:>8} {:>15}\n", "Average /H", wq, "",
             "", "RD/H", avg(a.rd50_h, a.obs_rd50_h), avg(a.rd95_h, a.obs_rd95_h), "",
             avg(a.rdmax_h, a.obs_rdmax_h));
  fmt::print(out, "{:<{}} {:>6} {:>6}  {:<6} {:>15} {:>15} {:>8} {:>15}\n", "", wq, "", "", "ID/H",
             avg(a.id50_h, a.obs_id50_h), avg(a.id95_h, a.obs_id95_h), "",
             avg(a.idmax_h, a.obs_idmax_h));
  fmt::print(out, "n: RD over every block thrown, ID over the blocks that reached the floor.\n");
  fmt::print(out,
             "Average /H: the mean over the {} row{} of each row's ratio, so no n of its own; no P99:\n"
             "  as in Tables 6.2/6.3, the average line has P50, P95 and max.\n",
             a.rows, a.rows == 1 ? "" : "s");

  fmt::print(out, "\nSections\n");
  for (const design::QuarrySectionResult& s : d.sections) {
    const design::QuarryGeometry& g = s.geometry;
    const design::QuarryDistances& q = s.distances;
    // [0, 12.4] m; [0, beyond the profile]; or none when no block gave a value (e.g. no
    // first impact when none reached the floor).
    auto zone = [](double v) {
      if (std::isnan(v)) return std::string("none (no values)");
      return fmt::format("[0, {}]{}", metres(v), std::isfinite(v) ? " m" : "");
    };
    fmt::print(out,
               "{}: crest x = {:.2f} m ({}), toe x = {:.2f} m ({}), H = {:.2f} m ({}); from the "
               "toe, danger zone {}, first-impact zone {}; {} thrown: {} reached the floor (the "
               "ID sample), {} came to rest at or above the toe (RD = 0; a block that lands at the "
               "toe and stops there is in both), {} left the section{}\n",
               s.spec.name, g.crest.x, design::to_string(g.crest_origin), g.toe.x,
               design::to_string(g.toe_origin), g.height, design::to_string(g.height_origin),
               zone(s.danger_zone), zone(s.first_impact_zone),
               q.thrown,
               q.reached_floor, q.above_toe, q.left_profile,
               q.abnormal ? fmt::format(", {} stopped by a time/impact limit or numerically",
                                        q.abnormal)
                          : std::string());
  }
}

void add_quarry_report_data(io::ReportData& data, const io::LoadedScenario& loaded,
                            const design::QuarryDesign& design, std::size_t paths_per_section) {
  data.quarry = design;
  data.quarry_sections.clear();
  for (const io::QuarrySection& s : loaded.quarries) {
    io::ReportData::QuarrySectionView v;
    v.name = s.spec.name;
    v.profile = &s.scenario.profile;
    v.paths = sample_paths(s.scenario, paths_per_section);
    v.seed = s.scenario.settings.seed;
    data.quarry_sections.push_back(std::move(v));
  }
  for (const io::QuarrySection& s : loaded.quarries) {
    const std::string entry = s.rules.title.empty() ? s.rules.name : s.rules.name + " — " + s.rules.title;
    if (std::find(data.rule_sets.begin(), data.rule_sets.end(), entry) == data.rule_sets.end())
      data.rule_sets.push_back(entry);
  }
}

int run_quarries(io::LoadedScenario& loaded, const io::ReportTemplate& layout,
                 const QuarryRunOptions& o) {
  sim::RunOptions opt;
  opt.threads = o.threads;
  opt.record_impacts = o.flags.impacts;
  opt.all_crossings = o.flags.all_crossings;
  std::uint64_t total = 0, blocks = 0, sources = 0, chunks = 0;
  for (const io::QuarrySection& s : loaded.quarries) {
    const std::uint64_t n = s.scenario.trajectory_count();
    total += n;
    blocks += s.scenario.blocks.size();
    sources += s.scenario.sources.size();
    chunks = std::max<std::uint64_t>(chunks, (n + opt.chunk_size - 1) / opt.chunk_size);
  }
  const unsigned used = threads_used(o.threads, chunks);

  // The output folder; a failure from here on leaves nothing behind. Ctrl-C is caught from
  // before the folder exists, so that it is always taken away again.
  const InterruptGuard interrupt;
  opt.stop = interrupt.flag();
  const std::unique_ptr<io::OutputFolder> folder = open_output_folder(o.out, loaded.inputs);
  if (!folder) return kExitInput;
  io::ResultFiles files(folder->staging(), o.flags.impacts);
  design::RunSamples all(0, 1);
  std::vector<design::QuarrySectionInput> inputs;
  std::vector<std::uint64_t> seeds;
  ProgressBar bar(progress_mode(o.quiet), o.log_seconds);
  const auto t0 = std::chrono::steady_clock::now();
  std::uint64_t before = 0;
  // The report's data sheets: the first rows over all sections, each with its section.
  std::vector<sim::TrajectorySummary> first_trajectories;
  std::vector<sim::Crossing> first_crossings;
  std::vector<std::uint32_t> trajectory_sections, crossing_sections;
  std::uint64_t total_trajectories = 0, total_crossings = 0;
  // Out of memory between the sections' runs (their bookkeeping, the next section's set-up):
  // said with the trajectories the finished sections ran.
  try {
    for (io::QuarrySection& s : loaded.quarries) {
      files.begin_section(s.scenario, s.spec.name, s.geometry);
      all.begin_section(s.spec.name, s.scenario.profile.main_direction());
      QuarrySink sink(files, s.geometry, all);
      FirstRows first(sink, layout.trajectory_rows - first_trajectories.size(),
                      layout.crossing_rows - first_crossings.size());
      const sim::RunReport rep = sim::run_simulation(
          s.scenario, opt, first,
          [&](std::uint64_t done, std::uint64_t) { bar.update(before + done, total); });
      if (rep.out_of_memory)
        throw RunOutOfMemory(out_of_memory_message(loaded, total, before + rep.delivered, o.out));
      if (rep.error)
        throw std::runtime_error(fmt::format("writing the results of section \"{}\" failed: {}",
                                             s.spec.name, *rep.error));
      if (rep.interrupted || interrupt.interrupted()) {
        bar.finish();
        return report_interrupted(o.out.c_str());
      }
      before += s.scenario.trajectory_count();
      const auto section = static_cast<std::uint32_t>(&s - loaded.quarries.data());
      trajectory_sections.insert(trajectory_sections.end(), first.trajectories.size(), section);
      crossing_sections.insert(crossing_sections.end(), first.crossings.size(), section);
      first_trajectories.insert(first_trajectories.end(), first.trajectories.begin(), first.trajectories.end());
      first_crossings.insert(first_crossings.end(), first.crossings.begin(), first.crossings.end());
      total_trajectories += first.total_trajectories;
      total_crossings += first.total_crossings;
      inputs.push_back({s.spec, s.rules, s.geometry, std::move(sink.distances), s.observed,
                        s.scenario.settings.throws});
      seeds.push_back(s.scenario.settings.seed);
    }
  } catch (const std::bad_alloc&) {
    throw RunOutOfMemory(out_of_memory_message(loaded, total, before, o.out));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  bar.finish();
  bar.stage("statistics and the danger zones' bootstraps");
  files.close();

  // The bootstrap streams of row k: [simulation].seed + k.
  design::QuarryOutcome outcome = design::design_quarry(inputs, loaded.scenario.settings.seed);
  if (interrupt.interrupted()) {  // (as run_command)
    bar.finish();
    return report_interrupted(o.out.c_str());
  }
  bar.stage("writing summary.json and report.xlsx");
  if (!outcome.design) throw std::runtime_error("quarry danger zones: " + outcome.error);
  design::doubt_passes(outcome.design->checks,
                       design::pooled_doubts(*outcome.design, doubted_inputs(loaded.notes)));
  io::DesignResults results;
  results.checks = outcome.design->checks;
  results.quarry_seeds = seeds;
  results.quarry = std::move(*outcome.design);

  const design::RunStatistics stats = design::run_statistics({}, all);
  const io::RunInfo info = run_info(loaded, total, blocks, sources, used, o.flags, layout);
  io::write_summary_json(folder->staged(io::kSummaryJson), info, stats, results);
  io::ReportData report = report_data(loaded, stats);
  report.samples = &all;
  report.checks = results.checks;
  add_quarry_report_data(report, loaded, *results.quarry);
  report.trajectories = std::move(first_trajectories);
  report.crossings = std::move(first_crossings);
  report.trajectory_sections = std::move(trajectory_sections);
  report.crossing_sections = std::move(crossing_sections);
  report.total_trajectories = total_trajectories;
  report.total_crossings = total_crossings;
  io::write_report(folder->staged(io::kReportXlsx), report, layout);
  bar.finish();
  if (interrupt.interrupted()) return report_interrupted(o.out.c_str());
  const auto written = commit_results(*folder);
  if (o.committed) *o.committed = true;
  if (o.quiet) print_run_notes(stderr, stats);
  print_to_stdout([&] {
    if (!o.quiet) print_results(stdout, stats, seconds, written, loaded.quarries.size());
    if (!o.quiet || o.flags.check) {
      print_quarries(stdout, *results.quarry, !o.quiet);
      print_design(stdout, results);
    }
  });
  return check_exit_code(o.flags, results.checks);
}

}  // namespace pierre::app
