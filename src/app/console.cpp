#include "console.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "pierre/design/number_kind.hpp"
#include "pierre/sim/trajectory.hpp"

namespace pierre::app {

ProgressBar::ProgressBar(Mode mode, double log_seconds)
    : mode_(mode), log_seconds_(log_seconds), start_(clock::now()), last_(start_) {}

void ProgressBar::update(std::uint64_t done, std::uint64_t total) {
  if (mode_ == Mode::off || total == 0) return;
  const auto now = clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (mode_ == Mode::bar && done < total && (since < 0.2 || elapsed < 0.3)) return;
  // The log: every log_seconds, and the end of a run that has logged.
  if (mode_ == Mode::log && !(since >= log_seconds_ || (done == total && logged_))) return;
  last_ = now;
  const double frac = static_cast<double>(done) / static_cast<double>(total);
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
  const double eta = rate > 0 ? static_cast<double>(total - done) / rate : 0.0;
  const auto eta_s = static_cast<long>(std::lround(eta));
  const std::string eta_text =
      fmt::format("ETA {}:{:02d}:{:02d}", eta_s / 3600, (eta_s / 60) % 60, eta_s % 60);
  // fputs, not fmt::print: a write to a terminal that has gone away fails (EIO), and fmt would
  // throw from a worker thread, which ends the program without cleaning up.
  if (mode_ == Mode::log) {
    std::fputs(fmt::format("pierre: {:.1f} % of {} trajectories, {:.0f} trajectories/s, {}\n",
                           100.0 * frac, total, rate, eta_text)
                   .c_str(),
               stderr);
    logged_ = true;
  } else {
    constexpr int width = 30;
    const int filled = static_cast<int>(frac * width);
    std::fputs(fmt::format("\r[{}{}] {:5.1f}%  {:.0f} trajectories/s  {} ",
                           std::string(static_cast<std::size_t>(filled), '#'),
                           std::string(static_cast<std::size_t>(width - filled), ' '), 100.0 * frac,
                           rate, eta_text)
                   .c_str(),
               stderr);
    drawn_ = true;
  }
  std::fflush(stderr);
}

void ProgressBar::stage(std::string_view what) {
  if (mode_ == Mode::log) {
    if (logged_) std::fputs(fmt::format("pierre: {} ...\n", what).c_str(), stderr);
    std::fflush(stderr);
    return;
  }
  if (mode_ != Mode::bar) return;
  std::string line = fmt::format("\r{} ...", what);
  if (line.size() < 80) line.resize(80, ' ');  // over the bar drawn before
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (!drawn_) return;
  std::fputs(("\r" + std::string(79, ' ') + "\r").c_str(), stderr);  // never throws
  std::fflush(stderr);
  drawn_ = false;
}

ProgressBar::Mode progress_mode(bool quiet) {
  if (::isatty(2)) return quiet ? ProgressBar::Mode::off : ProgressBar::Mode::bar;
  return ProgressBar::Mode::log;
}

double progress_log_seconds() {
  const char* v = std::getenv("PIERRE_PROGRESS_SECONDS");
  if (!v || !*v) return ProgressBar::kDefaultLogSeconds;
  double s = 0;
  const char* end = v + std::strlen(v);
  const auto [ptr, ec] = std::from_chars(v, end, s);
  if (ec != std::errc{} || ptr != end || !(s > 0) || !std::isfinite(s))
    throw io::InputError("environment", 0, "PIERRE_PROGRESS_SECONDS", fmt::format("\"{}\"", v),
                         "a number of seconds > 0 between progress lines of a run whose stderr "
                         "is not a terminal (default 60)");
  return s;
}

namespace {

// `text` after `lead`, broken between words before 100 columns, later lines indented as far.
void print_wrapped(std::FILE* out, std::string_view lead, std::string_view text) {
  constexpr std::size_t kWidth = 100;
  std::string line(lead);
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find(' ', at);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(at, end - at);
    if (line.size() > lead.size() && line.size() + 1 + word.size() > kWidth) {
      fmt::print(out, "{}\n", line);
      line.assign(lead.size(), ' ');
    } else if (line.size() > lead.size()) {
      line += ' ';
    }
    line += word;
    at = end + 1;
  }
  fmt::print(out, "{}\n", line);
}

}  // namespace

std::string duration_text(double seconds) {
  // Three significant digits, fixed-point (0.05 s is "50.0 ms", not "0.0 s"); the bounds are
  // where rounding to the next decade starts.
  auto three = [](double v) {
    int decimals = 2;
    for (double bound = 9.995; v >= bound && decimals > 0; bound *= 10) --decimals;
    for (double bound = 0.9995; v > 0 && v < bound && decimals < 9; bound /= 10) ++decimals;
    return fmt::format("{:.{}f}", v, decimals);
  };
  if (!(seconds >= 0)) seconds = 0;
  return seconds < 0.9995 ? three(1e3 * seconds) + " ms" : three(seconds) + " s";
}

void print_results(std::FILE* out, const design::RunStatistics& s, double seconds,
                   const std::vector<std::filesystem::path>& files, std::size_t quarry_sections) {
  fmt::print(out, "{} trajectories in {}\n\n", s.trajectories, duration_text(seconds));
  if (!s.lines.empty()) {
    std::fputs(s.every_crossing
                        ? "Observation lines (every crossing, in both directions: --all-crossings; "
                          "not reached: trajectories without a crossing in the main direction)\n"
                        : "Observation lines (first crossing of each trajectory in the main "
                          "direction)\n",
               out);
    const std::size_t wl = column_width(s.lines, 16, [](const auto& l) { return l.name; });
    fmt::print(out, "{:<{}} {:>9} {:>8} {:>11}  {:<26} {:>10} {:>10} {:>10} {:>10}\n", "line", wl,
               "x (m)", "count", "not reached", "quantity", "mean", "P50", "P95", "max");
    for (const auto& l : s.lines) {
      struct Row {
        const char* label;
        const design::QuantityStatistics* q;
        double scale;
        design::NumberKind kind;
      };
      const Row rows[] = {{"speed (m/s)", &l.speed, 1.0, design::NumberKind::speed},
                          {"passing height (m)", &l.height, 1.0, design::NumberKind::length},
                          {"transl. energy (kJ)", &l.translational_energy, 1e-3, design::NumberKind::energy}};
      bool first = true;
      for (const Row& r : rows) {
        if (first)
          fmt::print(out, "{:<{}} {:>9.2f} {:>8} {:>11}  ", l.name, wl, l.chainage, l.count,
                     l.not_reached);
        else
          fmt::print(out, "{:<{}} {:>9} {:>8} {:>11}  ", "", wl, "", "", "");
        first = false;
        auto cell = [&](double v) { return design::number_cell(v * r.scale, r.kind, 10); };
        fmt::print(out, "{:<26} {} {} {} {}\n", r.label, cell(r.q->mean), cell(r.q->p50),
                   cell(r.q->p95), cell(r.q->max));
      }
    }
    fmt::print(out, "\n");
  }
  // In a quarry run these pool every section's travel from its release point: the distances
  // from the toe that set the zones (RD) are the quarry table's.
  const std::string pooled =
      quarry_sections > 1 ? fmt::format(", {} sections pooled; RD from the toe below", quarry_sections)
      : quarry_sections == 1 ? "; RD from the toe below"
                             : "";
  // A percentile that reaches the runouts of blocks still moving (off the profile, cut off) is a
  // lower bound: "≥" before it (the note below says why).
  auto metres = [&](double v) {
    return (s.runout.is_lower_bound(v) ? "≥ " : "") + design::number_cell(v, design::NumberKind::length);
  };
  fmt::print(out, "Horizontal runout from the release point (m{}):   P50 {}   P95 {}   P99 {}   max {}\n",
             pooled, metres(s.runout.p50), metres(s.runout.p95), metres(s.runout.p99),
             metres(s.runout.max));
  fmt::print(out, "Stop reasons:");
  for (const auto& r : s.stop_reasons) fmt::print(out, "  {} {}", sim::to_string(r.reason), r.count);
  fmt::print(out, "\n");
  print_run_notes(out, s);
  fmt::print(out, "\nWritten:\n");
  for (const auto& f : files) fmt::print(out, "  {}\n", f.string());
}

void print_run_notes(std::FILE* out, const design::RunStatistics& s) {
  // Blocks cut off by a limit or gone off the profile: what their stop points and runouts mean.
  for (const auto& note : design::stop_reason_notes(s)) print_wrapped(out, "Note: ", note);
}

void print_input_notes(std::FILE* out, const std::vector<io::InputNote>& notes) {
  for (const auto& n : notes) fmt::print(out, "Note: {}\n", n.message());
}

void print_design(std::FILE* out, const io::DesignResults& r, bool follows_output) {
  if (r.barriers.empty() && r.checks.empty()) return;
  // A blank line between blocks, not before the first thing printed (`check --quiet`).
  bool printed = follows_output;
  auto blank = [&] {
    if (printed) fmt::print(out, "\n");
    printed = true;
  };
  if (!r.barriers.empty() || !r.barriers_without_design.empty()) {
    blank();
    fmt::print(out, "Barriers (ETAG 027, docs/barriers.md; characteristic values at the rule set's percentile)\n");
    // The class the requirement needs, not a candidate's (the report's "smallest energy class
    // required"): "class" alone read as the candidate's own.
    const auto& none = r.barriers_without_design;
    const std::size_t wb =
        std::max(column_width(r.barriers, 18, [](const auto& d) { return d.spec.name; }),
                 column_width(none, 18, [](const auto& d) { return d.name; }));
    const std::size_t wn =
        std::max(column_width(r.barriers, 12, [](const auto& d) { return d.spec.line; }),
                 column_width(none, 12, [](const auto& d) { return d.line; }));
    const std::size_t wr =
        std::max(column_width(r.barriers, 18, [](const auto& d) { return d.rules_name; }),
                 column_width(none, 18, [](const auto& d) { return d.rules_name; }));
    fmt::print(out, "{:<{}} {:<{}} {:<{}} {:>10} {:>10} {:>8} {:>9} {:>10} {:>10} {:>9} {:>7}\n",
               "barrier", wb, "line", wn, "rules", wr, "v_k m/s", "h_k m", "v_d m/s", "E_d kJ",
               "MEL_req kJ", "SEL_req kJ", "req class", "h_i m");
    // Which of the two a characteristic value is: a Weibull v_k below the P95 of the line table
    // above is the fit's, not a slip.
    auto k = [](const design::Characteristic& c, design::NumberKind kind) {
      const char* from = std::isnan(c.value)           ? " "
                         : c.value == c.weibull       ? "W"
                         : c.value == c.empirical     ? "E"
                                                      : " ";
      return design::number_cell(c.value, kind, 8) + " " + from;
    };
    constexpr auto speed = design::NumberKind::speed, length = design::NumberKind::length,
                   energy = design::NumberKind::energy;
    for (const auto& d : r.barriers)
      fmt::print(out, "{:<{}} {:<{}} {:<{}} {} {} {} {} {} {} {:>9} {}\n", d.spec.name, wb,
                 d.spec.line, wn, d.rules_name, wr, k(d.v_k, speed), k(d.h_k, length), design::number_cell(d.v_d, speed, 8),
                 design::number_cell(d.E_d_kJ, energy, 9), design::number_cell(d.MEL_req_kJ, energy, 10),
                 design::number_cell(d.SEL_req_kJ, energy, 10),
                 d.energy_class ? std::to_string(d.energy_class->number) +
                                      (d.energy_class->open_ended ? "+" : "")
                                : std::string("-"),
                 design::number_cell(d.h_i, length, 7));
    // A barrier its line gave no design: in the table all the same, with why (its check line
    // below says it too), so that a reader of the table misses none.
    for (const auto& d : none)
      fmt::print(out, "{:<{}} {:<{}} {:<{}} no design: {}\n", d.name, wb, d.line, wn, d.rules_name,
                 wr, d.reason);
    if (!r.barriers.empty())
      fmt::print(out, "v_k, h_k: W the Weibull quantile, E the empirical percentile (the rule "
                      "set's `governing`)\n");
    // What an engineer should know of a design (fits from few values, zero heights left out of
    // the Weibull, ...): the report and summary.json keep them too.
    for (const auto& d : r.barriers)
      for (const auto& note : d.notes) print_wrapped(out, "Note: " + d.spec.name + ": ", note);
  }
  blank();
  const std::size_t ws = column_width(r.checks, 18, [](const auto& c) { return c.subject; });
  const std::size_t wi = column_width(r.checks, 20, [](const auto& c) { return c.id; });
  fmt::print(out, "Checks\n{:<{}} {:<{}} {:>10} {:>10} {:<4} {:<6} {}\n", "subject", ws, "id", wi,
             "value", "limit", "unit", "status", "rule");
  for (const auto& c : r.checks)
    fmt::print(out, "{:<{}} {:<{}} {} {} {:<4} {:<6} {}\n", c.subject, ws, c.id, wi,
               design::number_cell(c.value, design::check_number_kind(c.unit, c.value), 10),
               design::number_cell(c.limit, design::check_number_kind(c.unit, c.limit), 10), c.unit,
               design::to_string(c.status), c.rule);
  // The reasons: FAIL and WARN first, then why a line does not apply (an N/A line still shows a
  // value and a limit, e.g. a candidate's SEL below SEL_req when the rule set designs on MEL).
  bool header = false;
  for (const bool judged : {true, false})
    for (const auto& c : r.checks) {
      const bool is_judged =
          c.status == design::CheckStatus::fail || c.status == design::CheckStatus::warn;
      if (is_judged != judged || c.status == design::CheckStatus::pass || c.reason.empty())
        continue;
      if (!header) blank();
      header = true;
      fmt::print(out, "{} {} {}: {}\n", design::to_string(c.status), c.subject, c.id, c.reason);
    }
  // Every status counted, as the report's verdict counts them (a WARN is read, not only a FAIL).
  auto count = [&](design::CheckStatus st) { return design::count_status(r.checks, st); };
  blank();
  fmt::print(out, "{} check line{}: {} FAIL, {} WARN, {} PASS, {} N/A\n", r.checks.size(),
             r.checks.size() == 1 ? "" : "s", count(design::CheckStatus::fail),
             count(design::CheckStatus::warn), count(design::CheckStatus::pass),
             count(design::CheckStatus::not_applicable));
}

}  // namespace pierre::app
