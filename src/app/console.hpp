// Console output of `pierre run`: the progress bar on stderr and the results table on stdout.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "pierre/design/run_statistics.hpp"
#include "pierre/io/input_error.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::app {

// A column as wide as its widest entry (in characters of UTF-8), at least `at_least`: a name
// longer than usual pushed every column after it out of line.
template <class Rows, class Text>
std::size_t column_width(const Rows& rows, std::size_t at_least, Text text) {
  std::size_t w = at_least;
  for (const auto& r : rows) {
    const std::string t = text(r);
    w = std::max(w, static_cast<std::size_t>(std::count_if(t.begin(), t.end(), [](char c) {
                   return (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // not a continuation byte
                 })));
  }
  return w;
}

// Runs `print`, which writes the results to stdout. A failed write there (fmt throws) is left
// for main to report from ferror(stdout), so that the command's exit code survives it: a FAIL's
// 1 must reach a pipeline even when the table could not be printed.
template <class Print>
void print_to_stdout(Print&& print) {
  try {
    print();
  } catch (const std::system_error&) {
    if (!std::ferror(stdout)) throw;
  }
}

// Progress of a run on stderr. On a terminal (bar): percentage, trajectories per second and ETA
// on one line, redrawn at most five times a second, erased at the end. Elsewhere (log: a CI job's
// log, a file): a line of the same once the run has lasted `log_seconds`, and again every
// `log_seconds`, so that a long run is not silent for hours (and a CI system that stops a job
// without output does not stop it); a short run logs nothing. Off: nothing.
class ProgressBar {
 public:
  enum class Mode { off, bar, log };
  explicit ProgressBar(Mode mode, double log_seconds = kDefaultLogSeconds);
  ~ProgressBar() { finish(); }  // an error's message then starts on a clean line
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  void update(std::uint64_t done, std::uint64_t total);  // from one thread at a time
  // Replaces the line with the step under way after the simulation (statistics, bootstraps,
  // the report): on a large run they take seconds, and the terminal should not fall silent.
  // (Logged as a line of its own when the run has logged its progress.)
  void stage(std::string_view what);
  void finish();  // erases the bar's line

  static constexpr double kDefaultLogSeconds = 60;

 private:
  using clock = std::chrono::steady_clock;
  Mode mode_;
  double log_seconds_;
  bool drawn_ = false;   // the bar is on the terminal's line
  bool logged_ = false;  // a log line was written
  clock::time_point start_, last_;
};

// The progress mode and log interval for a run: the bar on a terminal unless quiet, else the
// log (quiet too: a long CI job must not look hung), every $PIERRE_PROGRESS_SECONDS seconds
// (default 60). A value that is not a number of seconds > 0 is bad input (io::InputError).
ProgressBar::Mode progress_mode(bool quiet);
double progress_log_seconds();

// The reader's notes on the input (io::LoadedScenario::notes), one line each: "Note: <file>:<line>:
// <field>: <text>".
void print_input_notes(std::FILE* out, const std::vector<io::InputNote>& notes);

// Notes on how the trajectories ended that bear on the results (blocks cut off by a limit or
// gone off the profile, energy stops on steep ground or at the first impact). print_results
// prints them; a quiet run sends them to stderr, as it does the input notes.
void print_run_notes(std::FILE* out, const design::RunStatistics& stats);

// A run's wall time to three significant digits: "42.3 ms" below a second, else "1.25 s".
std::string duration_text(double seconds);

// quarry_sections: the sections of a quarry run (0 for another run), whose runouts from the
// release point are pooled: not the RD of the table that follows.
void print_results(std::FILE* out, const design::RunStatistics& stats, double seconds,
                   const std::vector<std::filesystem::path>& files,
                   std::size_t quarry_sections = 0);

// The barriers' design values, then every check line as a table (subject, id, value, limit,
// unit, status, rule), then the reason of each FAIL and WARN line, then of each N/A line.
// Blocks are separated by a blank line, and one leads only when `follows_output` (something
// was printed before: `check --quiet` starts with its first table, not an empty line).
void print_design(std::FILE* out, const io::DesignResults& results, bool follows_output = true);

}  // namespace pierre::app
