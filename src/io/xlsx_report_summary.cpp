// The Summary sheet: the run, the barriers' design values, the observation lines, how the
// trajectories ended, the quarry rows
// (xlsx_report_quarry.cpp) and every check line.
#include "xlsx_report_writer.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "pierre/design/number_text.hpp"

namespace pierre::io::detail {
namespace {
// A note over the print area's width, A:J (16 + 20 + 34 + 2·12 + 10 + 26 + 10 + 44 + 12 = 196,
// the widths set below), wrapped: in one cell it ran off the printed page.
constexpr Col kNoteLast = 9;
constexpr double kNoteWidth = 196;
}  // namespace

void Report::summary(lxw_worksheet* ws) {
  page_setup(ws);
  width(ws, 0, 0, 16);
  width(ws, 1, 1, 20);
  width(ws, 2, 2, 34);
  width(ws, 3, 4, 12);
  width(ws, 5, 5, 10);
  width(ws, 6, 6, 26);
  width(ws, 7, 7, 10);
  width(ws, 8, 8, 44);
  width(ws, 9, 11, 12);

  text(ws, 0, 0, t_.get("titles", "summary"), title());
  check(worksheet_set_row(ws, 0, 24, nullptr), "worksheet_set_row");
  Row r = summary_run(ws, 2);
  r = summary_barriers(ws, r);
  r = summary_lines(ws, r);
  r = summary_stops(ws, r);
  // Quarry danger zones: Tables 6.2/6.3's rows and their average.
  if (d_.quarry) r = quarry_summary(ws, r);
  r = summary_basis(ws, r);
  summary_checks(ws, r);
}

// The run: project, scenario, date, version, seed, throws, rule sets and the runout.
Row Report::summary_run(lxw_worksheet* ws, Row r) {
  const LoadedScenario* sc = d_.scenario;
  text(ws, r++, 0, t_.get("titles", "run"), section());
  auto label = [&](std::string_view key) { text(ws, r, 0, t_.get("labels", key), bold()); };
  label("project");
  text(ws, r++, 2, sc ? sc->scenario.name : std::string());
  if (sc && !sc->description.empty()) {
    label("description");
    text(ws, r++, 2, sc->description);
  }
  if (sc)
    for (auto [key, value] : sc->document.fields())
      if (!value->empty()) {
        label(key);
        text(ws, r++, 2, *value);
      }
  if (sc) {
    label("scenario_file");
    text(ws, r++, 2, sc->file.string());
  }
  label("date");
  {
    const auto ymd = parse_date(d_.date);
    lxw_datetime dt{static_cast<int>(ymd.year()), static_cast<int>(unsigned(ymd.month())),
                    static_cast<int>(unsigned(ymd.day())), 0, 0, 0.0};
    lxw_format* f = number("date");
    format_set_align(f, LXW_ALIGN_LEFT);
    check(worksheet_write_datetime(ws, r++, 2, &dt, f), "worksheet_write_datetime");
  }
  label("version");
  text(ws, r++, 2, d_.pierre_version);
  label("seed");
  seed(ws, r++, 2, d_.seed, number("general", 2));
  label("throws");
  num(ws, r++, 2, d_.throws, number("count", 2));
  if (sc && !sc->overrides.empty()) {  // the echoed scenario text (Inputs) shows the file's
    label("overrides");
    for (const auto& o : sc->overrides) text(ws, r++, 2, o);
  }
  if (sc && !sc->notes.empty()) {  // likely mistakes the readers noted: the client sees them too
    // The label over A:B and each note over C to the print width, both wrapped (a note ran
    // off the printed page, the label was cut).
    const std::string head = t_.get("labels", "input_notes");
    merged(ws, r, 0, 1, head, bold_wrap());
    for (const auto& n : sc->notes) {
      const std::string m = n.message();
      merged(ws, r, 2, kNoteLast, m, wrapped_note());
      if (&n == &sc->notes.front())
        fit_row(ws, r, {{&head, 36}, {&m, kNoteWidth - 36}});
      else
        fit_row(ws, r, {{&m, kNoteWidth - 36}});
      ++r;
    }
  }
  label("trajectories");
  num(ws, r++, 2,
      static_cast<double>(d_.total_trajectories ? d_.total_trajectories
                                                : d_.statistics.trajectories),
      number("count", 2));
  label("rule_sets");
  if (d_.rule_sets.empty()) text(ws, r++, 2, t_.get("labels", "none"));
  for (const auto& rs : d_.rule_sets) text(ws, r++, 2, rs);
  if (d_.statistics.runout.count > 0) {
    const auto& ro = d_.statistics.runout;
    for (auto [key, v] : {std::pair{"runout_p50", ro.p50}, std::pair{"runout_p95", ro.p95},
                          std::pair{"runout_p99", ro.p99}, std::pair{"runout_max", ro.max}}) {
      label(key);
      // At or beyond a block still moving (off the profile, cut off): a lower bound, "≥ 85.00".
      num(ws, r++, 2, v, number(ro.is_lower_bound(v) ? "length_at_least" : "length", 2));
    }
    // What they are measured from; beside the quarry table's RD they read as a danger zone.
    text(ws, r++, 0,
         d_.quarry ? replace_all(t_.get("labels", "runout_quarry_note"), "{sections}",
                                 std::to_string(d_.quarry_sections.size()))
                   : t_.get("labels", "runout_note"),
         note());
  }
  return r;
}

// The barriers in two tables: the design values (the console's, with the free board), then
// what each must reach, the smallest energy class that does, the kit checked against it and
// the verdict of the barrier's check lines (every barrier, those without a design too); under
// them how each class was chosen.
Row Report::summary_barriers(lxw_worksheet* ws, Row r) {
  const std::vector<design::BarrierSpec> none;
  const auto& specs = d_.scenario ? d_.scenario->barriers : none;
  if (d_.barriers.empty() && specs.empty()) return r;
  if (!d_.barriers.empty()) r = summary_barrier_values(ws, r);

  r = table_title(ws, r, "barrier_classes");
  headings(ws, r++, 0, "barriers",
           {"name", "mel_req", "sel_req", "energy_class", "class_mel", "class_sel", "candidate",
            "verdict", "verdict_lines"},
           45);
  const Row first = r;
  auto verdict = [&](const std::string& name, const std::string& kit) {
    std::vector<design::CheckLine> own;
    for (const auto& l : d_.checks)
      if (l.subject == name) own.push_back(l);
    std::string fails, warns;
    for (const auto& l : own) {
      if (l.status == design::CheckStatus::fail) fails += (fails.empty() ? "" : ", ") + l.id;
      if (l.status == design::CheckStatus::warn) warns += (warns.empty() ? "" : ", ") + l.id;
    }
    // The worst of its lines; N/A only when none is anything else.
    using S = design::CheckStatus;
    const std::size_t judged = own.size() - design::count_status(own, S::not_applicable);
    std::string word;
    if (!own.empty())
      word = design::to_string(!fails.empty() ? S::fail
                               : !warns.empty() ? S::warn
                               : judged > 0     ? S::pass
                                                : S::not_applicable);
    std::string lines;
    if (!fails.empty()) lines = "FAIL " + fails;
    if (!warns.empty()) lines += (lines.empty() ? "WARN " : "; WARN ") + warns;
    text(ws, r, 6, kit, wrap());
    text(ws, r, 7, word, centred_bold());
    text(ws, r, 8, lines, wrap());
    fit_row(ws, r, {{&name, 16}, {&kit, 26}, {&lines, 44}});
  };
  for (const auto& b : d_.barriers) {
    text(ws, r, 0, b.spec.name, wrap());
    // A capacity the rule set does not design on is information, not a requirement: a class
    // whose SEL is below an SEL_req of a MEL design read as a failure.
    num(ws, r, 1, b.MEL_req_kJ, number(design::needs_mel(b.design_on) ? "energy" : "info_energy", 1));
    num(ws, r, 2, b.SEL_req_kJ, number(design::needs_sel(b.design_on) ? "energy" : "info_energy", 1));
    if (b.energy_class) {
      // An open-ended class ("> 4500 kJ") shows as such: its bounds are not its capacity, the
      // kit declares its own (the note below says what it must reach).
      const bool open = b.energy_class->open_ended;
      num(ws, r, 3, b.energy_class->number, number(open ? "open_class" : "count", 1));
      num(ws, r, 4, b.energy_class->mel_kJ, number(open ? "open_energy" : "energy", 1));
      num(ws, r, 5, b.energy_class->sel_kJ, number(open ? "open_energy" : "energy", 1));
    } else {
      text(ws, r, 3, t_.get("labels", "none"), centred());
    }
    verdict(b.spec.name, candidate_kit(b.spec, b.candidate_mel_kJ, b.candidate_sel_kJ));
    ++r;
  }
  // A barrier its line gave no design (no block reached it): its check lines say why.
  for (const auto& spec : specs) {
    if (std::any_of(d_.barriers.begin(), d_.barriers.end(),
                    [&](const design::BarrierDesign& b) { return b.spec.name == spec.name; }))
      continue;
    text(ws, r, 0, spec.name, wrap());
    merged(ws, r, 1, 5, t_.get("labels", "no_design"), centred());
    const auto& c = spec.candidate;
    verdict(spec.name, candidate_kit(spec, c && c->mel_kJ ? *c->mel_kJ : kNaN,
                                     c && c->sel_kJ ? *c->sel_kJ : kNaN));
    ++r;
  }
  status_colours(ws, first, r - 1, 7);
  // How each class was chosen: on which capacity, from which table (its source).
  // Over the print area's width (kNoteWidth).
  for (const auto& b : d_.barriers)
    if (const auto it = b.how.find("energy_class"); b.energy_class && it != b.how.end())
      paragraph(ws, r++, 0, kNoteLast, kNoteWidth, b.spec.name + ": class " + std::to_string(b.energy_class->number) +
                           (b.energy_class->open_ended ? "+" : "") + ", " + it->second +
                           (b.energy_class->open_ended
                                ? fmt::format("; the class is open-ended: the kit must declare MEL >= "
                                              "{} kJ and SEL >= {} kJ",
                                              design::number_text(b.MEL_req_kJ, 4),
                                              design::number_text(b.SEL_req_kJ, 4))
                                : std::string()),
           wrapped_note());
  return r;
}

// The design values of each designed barrier, as the console prints them, with the free board.
Row Report::summary_barrier_values(lxw_worksheet* ws, Row r) {
  r = table_title(ws, r, "barrier_values");
  headings(ws, r++, 0, "barriers",
           {"name", "line", "rules", "chainage", "v_k", "h_k", "v_d", "m_d", "e_d",
            "free_board", "interception_height"},
           60);  // h_i's heading takes four lines in a column 12 wide
  for (const auto& b : d_.barriers) {
    const std::string rules = b.rules_name.empty() ? b.spec.rules : b.rules_name;
    text(ws, r, 0, b.spec.name, wrap());
    text(ws, r, 1, b.spec.line, wrap());
    text(ws, r, 2, rules, wrap());
    num(ws, r, 3, b.chainage, number("coordinate", 1));
    num(ws, r, 4, b.v_k.value, number("speed", 1));
    num(ws, r, 5, b.h_k.value, number("length", 1));
    num(ws, r, 6, b.v_d, number("speed", 1));
    num(ws, r, 7, b.m_d, number("mass", 1));
    num(ws, r, 8, b.E_d_kJ, number("energy", 1));
    num(ws, r, 9, b.free_board, number("length", 1));
    num(ws, r, 10, b.h_i, number("length", 1));
    fit_row(ws, r, {{&b.spec.name, 16}, {&b.spec.line, 20}, {&rules, 34}});
    ++r;
  }
  return r;
}

// The kit a candidate declares ("class 6, MEL 3000 kJ, SEL 1000 kJ, height 6.00 m"; MEL and SEL
// as resolved, NaN when not known), or the layout's words for a design without one.
std::string Report::candidate_kit(const design::BarrierSpec& spec, double mel_kJ, double sel_kJ) {
  if (!spec.candidate) return t_.get("labels", "no_candidate");
  const design::CandidateBarrier& c = *spec.candidate;
  std::string kit;
  auto add = [&](const std::string& part) { kit += (kit.empty() ? "" : ", ") + part; };
  if (c.energy_class) add("class " + std::to_string(*c.energy_class));
  if (!std::isnan(mel_kJ)) add("MEL " + design::number_text(mel_kJ, 6) + " kJ");
  if (!std::isnan(sel_kJ)) add("SEL " + design::number_text(sel_kJ, 6) + " kJ");
  if (c.height) add(fmt::format("height {:.2f} m", *c.height));
  return kit;
}

// The statistics at the observation lines, as the console prints them: per line its
// crossings, and the mean, P50, P95 and maximum of the speed, the passing height and the
// translational energy, a row each. A line no trajectory crossed says so instead.
Row Report::summary_lines(lxw_worksheet* ws, Row r) {
  if (d_.statistics.lines.empty()) return r;
  r = table_title(ws, r, "lines");
  headings(ws, r++, 0, "lines",
           {"name", "chainage", "quantity", "mean", "p50", "p95", "max", "count", "not_reached"},
           30);
  for (const auto& l : d_.statistics.lines) {
    text(ws, r, 0, l.name, top());
    num(ws, r, 1, l.chainage, number("coordinate", 1));
    num(ws, r, 7, static_cast<double>(l.count), number("count", 1));
    num(ws, r, 8, static_cast<double>(l.not_reached), number("count", 1));
    if (l.count == 0) {
      text(ws, r++, 2, t_.get("labels", "line_not_crossed"), note());
      continue;
    }
    struct Quantity {
      std::string_view heading, format;
      const design::QuantityStatistics& q;
      double scale;
    };
    for (const Quantity& q : {Quantity{"speed", "speed", l.speed, 1.0},
                              Quantity{"height", "length", l.height, 1.0},
                              Quantity{"energy", "energy", l.translational_energy, 1e-3}}) {
      text(ws, r, 2, h("lines", q.heading));
      Col c = 3;
      for (double v : {q.q.mean, q.q.p50, q.q.p95, q.q.max}) num(ws, r, c++, v * q.scale, number(q.format, 1));
      ++r;
    }
  }
  if (d_.statistics.every_crossing) text(ws, r++, 0, t_.get("labels", "lines_every_crossing"), note());
  return r;
}

// How the trajectories ended: a row per stop reason (zeros too, so that a reader sees none was
// cut off), and what a count that is not zero means for the stop points and the runout.
Row Report::summary_stops(lxw_worksheet* ws, Row r) {
  const auto& stops = d_.statistics.stop_reasons;
  if (stops.empty()) return r;
  std::uint64_t total = 0;
  for (const auto& s : stops) total += s.count;
  r = table_title(ws, r, "stop_reasons");
  headings(ws, r++, 0, "stop_reasons", {"reason", "count", "share", "meaning"}, 30);  // two lines
  for (const auto& s : stops) {
    const std::string_view name = sim::to_string(s.reason);
    std::string key = "stop_" + std::string(name);
    std::replace(key.begin(), key.end(), '-', '_');
    text(ws, r, 0, std::string(name));
    num(ws, r, 1, static_cast<double>(s.count), number("count", 1));
    num(ws, r, 2, total ? static_cast<double>(s.count) / static_cast<double>(total) : kNaN,
        number("percent", 1));
    text(ws, r++, 3, t_.get("labels", key));
  }
  for (const auto& n : design::stop_reason_notes(d_.statistics))
    paragraph(ws, r++, 0, kNoteLast, kNoteWidth, n, wrapped_note());
  return r;
}

// What the numbers rest on: the model and what it leaves out, the statistics, and how the
// barriers and quarry zones are set; a paragraph each, from the template's [basis].
Row Report::summary_basis(lxw_worksheet* ws, Row r) {
  const bool barriers = !d_.barriers.empty() || (d_.scenario && !d_.scenario->barriers.empty());
  std::vector<std::string> paragraphs;
  for (const char* key : {"model", "not_modelled", "statistics", "barriers", "quarries"}) {
    if ((key == std::string_view("barriers") && !barriers) ||
        (key == std::string_view("quarries") && !d_.quarry))
      continue;
    std::string p = t_.get("basis", key);
    if (p.empty()) continue;  // a firm's layout that leaves it out
    const std::uint64_t n = d_.total_trajectories ? d_.total_trajectories : d_.statistics.trajectories;
    p = replace_all(replace_all(p, "{trajectories}", std::to_string(n)), "{seed}",
                    std::to_string(d_.seed));
    paragraphs.push_back(std::move(p));
  }
  if (paragraphs.empty()) return r;
  r = table_title(ws, r, "basis");
  for (const auto& p : paragraphs) paragraph(ws, r++, 0, kNoteLast, kNoteWidth, p, wrap());
  return r;
}

// Every check line, whatever its subject: the caller's, then the quarry design's that the
// caller did not pass (same subject and id).
void Report::summary_checks(lxw_worksheet* ws, Row r) {
  std::vector<design::CheckLine> lines = d_.checks;
  if (d_.quarry)
    for (const auto& l : d_.quarry->checks)
      if (std::none_of(d_.checks.begin(), d_.checks.end(), [&](const design::CheckLine& c) {
            return c.subject == l.subject && c.id == l.id;
          }))
        lines.push_back(l);
  r = table_title(ws, r, "checks");
  // The verdict first: how many lines FAIL, as `pierre check` counts them.
  using design::CheckStatus;
  std::string verdict = lines.empty() ? t_.get("labels", "no_checks") : t_.get("labels", "verdict");
  for (auto [key, v] : {std::pair{"{lines}", lines.size()},
                        {"{fail}", design::count_status(lines, CheckStatus::fail)},
                        {"{warn}", design::count_status(lines, CheckStatus::warn)},
                        {"{pass}", design::count_status(lines, CheckStatus::pass)},
                        {"{na}", design::count_status(lines, CheckStatus::not_applicable)}})
    verdict = replace_all(verdict, key, std::to_string(v));
  text(ws, r++, 0, verdict, bold());
  std::string failing;
  for (const auto& l : lines)
    if (l.status == design::CheckStatus::fail)
      failing += (failing.empty() ? "" : ", ") + l.subject + " " + l.id;
  if (!failing.empty())
    text(ws, r++, 0, replace_all(t_.get("labels", "failing"), "{lines}", failing), bold());
  const Row head = r;
  if (!lines.empty()) r = check_table(ws, r, lines, true);  // no headings over nothing
  if (std::any_of(lines.begin(), lines.end(), [](const design::CheckLine& l) {
        return l.rule.find("(verify)") != std::string::npos;
      }))
    paragraph(ws, r++, 0, kNoteLast, kNoteWidth, t_.get("labels", "verify_note"), wrapped_note());
  // A:J, and as far as the widest table reaches: the barriers' design values to K (h_i), the
  // quarry table to L.
  check(worksheet_print_area(ws, 0, 0, r > 0 ? r - 1 : 0, d_.quarry ? 11 : !d_.barriers.empty() ? 10 : 9),
        "worksheet_print_area");
  if (!lines.empty()) check(worksheet_repeat_rows(ws, head, head), "worksheet_repeat_rows");
}

}  // namespace pierre::io::detail
