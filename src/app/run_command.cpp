// pierre run SCENARIO --out DIR: validate, simulate, compute the barriers, write the results
// atomically, print the tables; exit 0 whatever the checks say.
// pierre check SCENARIO --out DIR: the same, then exit 1 when a check line FAILs (or WARNs, with
// --fail-on-warn). Bad input is found before anything is created in DIR.
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "barriers.hpp"
#include "commands.hpp"
#include "console.hpp"
#include "data_folders.hpp"
#include "interrupt.hpp"
#include "quarries.hpp"
#include "report.hpp"
#include "run_steps.hpp"
#include "pierre/design/run_statistics.hpp"
#include "pierre/io/output_folder.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "pierre/io/xlsx_report.hpp"
#include "pierre/sim/runner.hpp"

namespace pierre::app {
namespace {

// A whole number in [lo, hi], checked as text: CLI11's own range check calls "1.5" out of
// range, and turns a number past the int64 range into its largest value (so two different
// seeds would give the same run).
CLI::Validator whole_number(std::int64_t lo, std::int64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        std::int64_t v = 0;
        const char* end = text.data() + text.size();
        const auto [p, ec] = std::from_chars(text.data(), end, v);
        if (ec == std::errc{} && p == end && v >= lo && v <= hi) return {};
        return fmt::format("found {}, expected a whole number from {} to {}", text, lo, hi);
      },
      "");  // the range is in each option's help text, not CLI11's "INT:INT in [...]"
}

class RunCommand final : public Command {
 public:
  explicit RunCommand(bool check) : check_(check) {}

  CLI::App* add_to(CLI::App& parent) override {
    CLI::App* c =
        check_ ? parent.add_subcommand(
                     "check",
                     "Simulate a scenario, design or check its barriers or quarry danger zones, "
                     "write the results; exit 1 when a check fails")
               : parent.add_subcommand("run", "Simulate a scenario and write its results");
    c->add_option("scenario", scenario_, "Scenario file (TOML, docs/scenario-format.md)")
        ->required()
        ->type_name("FILE");
    c->add_option("--out,-o", out_, "Output folder (created when missing)")
        ->required()
        ->type_name("DIR");
    seed_opt_ = c->add_option("--seed", seed_,
                              "Seed, a whole number from 0 to 2^63 - 1 (overrides simulation.seed)")
                    ->check(whole_number(0, std::numeric_limits<std::int64_t>::max()))
                    ->type_name("N");
    c->add_option("--threads", threads_, "Worker threads, 0 to 4096 (0: every hardware thread)")
        ->check(whole_number(0, 4096))
        ->type_name("N");
    throws_opt_ = c->add_option("--throws", throws_,
                                "Throws per block and source, 1 to 2^32 - 1 (overrides "
                                "simulation.throws)")
                      ->check(whole_number(1, std::numeric_limits<std::uint32_t>::max()))
                      ->type_name("N");
    c->add_flag("--quiet,-q", quiet_,
                check_ ? "No progress bar and no run statistics (the barrier and quarry tables and the check lines are still printed; a long run's progress lines still go to a stderr that is not a terminal)"
                       : "No progress bar and no results table (a long run's progress lines still go to a stderr that is not a terminal)");
    c->add_flag("--impacts", impacts_, "Also write impacts.csv (every impact; large)");
    c->add_flag("--all-crossings", all_crossings_,
                "Record every line crossing, both ways, and count them all (barriers still use "
                "each trajectory's first)");
    c->add_option("--rules", rules_,
                  "Rules folder holding materials.toml and the barrier and quarry rule sets")
        ->type_name("DIR");
    c->add_flag("--strict", strict_,
                "Refuse (exit 2, nothing run or written) an input noted as a likely slip that "
                "[confirmed] does not confirm; without it, such an input only keeps the lines "
                "resting on it from a PASS");
    if (check_)
      c->add_flag("--fail-on-warn", fail_on_warn_,
                  "Exit 1 when a check line WARNs too (a gate that takes no advisory line: too few "
                  "crossings, a doubtful fit, a sample too small)");
    if (check_)
      c->footer(
          "Example:\n"
          "  pierre check examples/vaujany-2d/scenario.toml --out results/vaujany\n"
          "runs like `pierre run`, computes every [[barriers]] entry (docs/barriers.md), writes\n"
          "summary.json with \"barriers\" and \"checks\" and report.xlsx, prints the check lines.\n"
          "A quarry scenario ([[quarries]], docs/quarry.md): every section's danger zone and its\n"
          "checks (zone.<work area>, bench.*), summary.json \"quarries\" and \"checks\".\n"
          "Exit code 0 when every check passes (WARN does not count), 1 when one FAILs (or WARNs, with\n"
          "--fail-on-warn), 2 on bad input\n"
          "or results that cannot be written in DIR (a full disk), 3 on an internal error or when the standard output\n"
          "cannot be written, 130 when interrupted (nothing written).");
    else
      c->footer(
          "Example:\n"
          "  pierre run examples/vaujany-2d/scenario.toml --out results/vaujany --seed 42 --threads 8\n"
          "writes results/vaujany/{trajectories.csv, crossings.csv, summary.json, report.xlsx}; with\n"
          "--impacts also impacts.csv. Barriers are computed and printed too; so are the danger\n"
          "zones of a quarry scenario (docs/quarry.md). Exit code 0 when it ran\n"
          "(whatever the checks say: see `pierre check`), 2 on bad input or results that cannot be\n"
          "written in DIR (a full disk), 3 on an internal error or when the standard output cannot be written,\n"
          "130 when interrupted (nothing written).");
    return c;
  }

  int run() override {
    // 1. Everything about the input is checked before DIR is touched.
    io::LoadedScenario loaded = io::load_scenario(scenario_, rules_folder(rules_));
    // Read now, not found missing after hours of running; its note (keys an older restyled
    // copy leaves out) goes to stderr even with --quiet: the firm running it must hear of it.
    const io::ReportTemplate layout = load_report_layout(stderr);
    (void)report_date();  // nor a bad SOURCE_DATE_EPOCH
    const double log_seconds = progress_log_seconds();  // nor a bad PIERRE_PROGRESS_SECONDS
    const auto seed =
        seed_opt_->count() ? std::optional<std::uint64_t>(seed_) : std::nullopt;
    const auto throws =
        throws_opt_->count() ? std::optional<std::uint32_t>(throws_) : std::nullopt;
    loaded.overrides = command_line_overrides(loaded, seed, throws);
    apply_command_line_overrides(loaded, seed, throws);
    const auto memory_note = check_run_memory(loaded, throws);
    // Likely mistakes that do not stop the run (an x out of order read as an overhang, a source
    // far above the ground or falling against the vertex order, a material no segment uses):
    // said even when quiet, on stderr, where a pipeline's log keeps them.
    print_input_notes(stderr, loaded.notes);
    if (strict_) refuse_doubted_inputs(loaded);
    if (memory_note) fmt::print(stderr, "Note: {}\n", *memory_note);
    // Memory grows with the trajectories (the statistics keep each one's runout and crossings):
    // running out of it, here or in a quarry's sections, is a count to lower, said as such.
    // (Once the results are in place, a failure is no longer "nothing written": it stays an
    // internal error, and a FAIL already decided is not hidden behind exit 2.)
    try {
      return simulate_and_report(loaded, layout, log_seconds);
    } catch (const std::bad_alloc&) {
      if (committed_) throw;
      throw RunOutOfMemory(out_of_memory_message(loaded, total_trajectories(loaded), std::nullopt, out_));
    }
  }

 private:
  // The run after its input was read and checked: simulate, compute, write, print.
  int simulate_and_report(io::LoadedScenario& loaded, const io::ReportTemplate& layout,
                          double log_seconds) {
    if (!loaded.quarries.empty()) {  // a quarry scenario: its sections, one after the other
      QuarryRunOptions q;
      q.out = out_;
      q.threads = threads_;
      q.flags = flags();
      q.quiet = quiet_;
      q.log_seconds = log_seconds;
      q.committed = &committed_;
      return run_quarries(loaded, layout, q);
    }
    sim::Scenario& sc = loaded.scenario;
    sim::RunOptions opt;
    opt.threads = threads_;
    opt.record_impacts = impacts_;
    opt.all_crossings = all_crossings_;
    const std::uint64_t total = sc.trajectory_count();
    const unsigned used = threads_used(threads_, (total + opt.chunk_size - 1) / opt.chunk_size);

    // 2. The output folder; a failure from here on leaves nothing behind. Ctrl-C is caught from
    // before the folder exists, so that it is always taken away again.
    const InterruptGuard interrupt;
    opt.stop = interrupt.flag();
    const std::unique_ptr<io::OutputFolder> folder = open_output_folder(out_, loaded.inputs);
    if (!folder) return kExitInput;
    io::ResultFiles files(folder->staging(), sc, impacts_, all_crossings_);
    // The report's data sheets: as many rows as its layout shows (the CSVs hold every row).
    FirstRows first(files, layout.trajectory_rows, layout.crossing_rows);
    ProgressBar bar(progress_mode(quiet_), log_seconds);
    const auto t0 = std::chrono::steady_clock::now();
    const sim::RunReport rep = sim::run_simulation(
        sc, opt, first, [&](std::uint64_t done, std::uint64_t n) { bar.update(done, n); });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    bar.finish();
    if (rep.out_of_memory)
      throw RunOutOfMemory(out_of_memory_message(loaded, total, rep.delivered, out_));
    if (rep.error) throw std::runtime_error("writing the results failed: " + *rep.error);
    if (rep.interrupted || interrupt.interrupted()) return report_interrupted(out_.c_str());
    bar.stage(loaded.barriers.empty() ? "statistics" : "statistics and the barriers' bootstraps");
    files.close();

    const design::RunStatistics stats = design::run_statistics(sc.lines, files.samples());
    const io::DesignResults design_results = compute_barriers(loaded, files.samples(), threads_);
    // The statistics and bootstraps of a large run take seconds: a Ctrl-C during them stops
    // here rather than after the report is written.
    if (interrupt.interrupted()) {
      bar.finish();
      return report_interrupted(out_.c_str());
    }
    bar.stage("writing summary.json and report.xlsx");
    const io::RunInfo info = run_info(loaded, total, sc.blocks.size(), sc.sources.size(), used,
                                      flags(), layout);
    io::write_summary_json(folder->staged(io::kSummaryJson), info, stats, design_results);
    write_run_report(folder->staged(io::kReportXlsx), layout, loaded, stats, files.samples(),
                     design_results, std::move(first));
    bar.finish();
    if (interrupt.interrupted()) return report_interrupted(out_.c_str());
    const auto written = commit_results(*folder);
    committed_ = true;
    if (quiet_) print_run_notes(stderr, stats);
    print_to_stdout([&] {
      if (!quiet_) print_results(stdout, stats, seconds, written);
      if (!quiet_ || check_) print_design(stdout, design_results, !quiet_);
      // Every barrier, designed or not, has check lines (the advisory ones at least).
      if (check_ && design_results.checks.empty())
        fmt::print("{}Nothing to check: the scenario has no [[barriers]] or [[quarries]] (exit 0).\n",
                   quiet_ ? "" : "\n");
    });
    return check_exit_code(flags(), design_results.checks);
  }

 private:
  RunFlags flags() const {
    return {.check = check_, .strict = strict_, .fail_on_warn = fail_on_warn_,
            .all_crossings = all_crossings_, .impacts = impacts_};
  }

  std::string scenario_, out_, rules_;
  std::int64_t seed_ = 0;  // signed, so that a negative seed is refused, not wrapped
  std::uint32_t throws_ = 1;
  unsigned threads_ = 0;
  bool check_ = false;
  bool quiet_ = false, impacts_ = false, all_crossings_ = false, strict_ = false;
  bool fail_on_warn_ = false;
  bool committed_ = false;  // the results are in place in DIR
  CLI::Option* seed_opt_ = nullptr;
  CLI::Option* throws_opt_ = nullptr;
};

}  // namespace

std::unique_ptr<Command> make_run_command() { return std::make_unique<RunCommand>(false); }
std::unique_ptr<Command> make_check_command() { return std::make_unique<RunCommand>(true); }

}  // namespace pierre::app
