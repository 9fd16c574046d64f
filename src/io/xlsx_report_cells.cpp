// The workbook's primitives: formats, cells, rows, page set-up, names, the check table.
#include "xlsx_report_writer.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <tuple>

namespace pierre::io::detail {
namespace {

// The first `n` UTF-8 code points of s.
std::string utf8_prefix(const std::string& s, std::size_t n) {
  std::size_t i = 0, count = 0;
  while (i < s.size() && count < n) {
    ++i;
    while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) ++i;
    ++count;
  }
  return s.substr(0, i);
}

}  // namespace

[[noreturn]] void fail(std::string_view what, lxw_error e) {
  throw std::runtime_error(
      fmt::format("report.xlsx: {}: {}", what, lxw_strerror(e)));
}
void check(lxw_error e, std::string_view what) {
  if (e != LXW_NO_ERROR) fail(what, e);
}

std::string replace_all(std::string s, std::string_view key, std::string_view value) {
  for (std::size_t p = s.find(key); p != std::string::npos; p = s.find(key, p + value.size()))
    s.replace(p, key.size(), value);
  return s;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// "Barrier {name}" with a barrier named "barrier 3" reads "Barrier 3", not "Barrier barrier 3":
// a name that starts with the words before {name} (ASCII case aside) gives up that start, and
// the template's words and case stand.
std::string with_name(const std::string& pattern, const std::string& name) {
  const std::size_t at = pattern.find("{name}");
  if (at == std::string::npos) return pattern;
  std::string before = pattern.substr(0, at);
  while (!before.empty() && before.back() == ' ') before.pop_back();
  const bool repeats = !before.empty() && name.size() >= before.size() &&
                       lower(name.substr(0, before.size())) == lower(before) &&
                       (name.size() == before.size() || name[before.size()] == ' ');
  if (!repeats) return replace_all(pattern, "{name}", name);
  std::string text = replace_all(pattern, "{name}", name.substr(std::min(name.size(), before.size() + 1)));
  while (!text.empty() && text.back() == ' ') text.pop_back();  // a name that is the word alone
  return text;
}

std::string format_number(double v) {
  if (!std::isfinite(v)) return "—";
  return fmt::format("{:.4g}", v);
}

// ---- formats ---------------------------------------------------------------------------

lxw_format* Report::number(std::string_view kind, int align) {
  return cached(fmt::format("num.{}.{}", kind, align), [&](lxw_format* f) {
    format_set_num_format(f, keep(t_.get("formats", kind)));
    if (align == 1) format_set_align(f, LXW_ALIGN_CENTER);
    if (align == 2) format_set_align(f, LXW_ALIGN_LEFT);
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);
  });
}

lxw_format* Report::check_number(const std::string& unit, double v, int align) {
  return number(design::format_key(design::check_number_kind(unit, v)), align);
}

lxw_format* Report::heading() {
  return cached("heading", [&](lxw_format* f) {
    format_set_bold(f);
    format_set_font_color(f, t_.colour("heading_font"));
    format_set_bg_color(f, t_.colour("heading_fill"));
    format_set_text_wrap(f);
    format_set_align(f, LXW_ALIGN_VERTICAL_CENTER);
    format_set_align(f, LXW_ALIGN_CENTER);
    format_set_border(f, LXW_BORDER_THIN);
    format_set_border_color(f, 0xBFBFBF);
  });
}

lxw_format* Report::title() {
  return cached("title", [&](lxw_format* f) {
    format_set_bold(f);
    format_set_font_size(f, 16);
    format_set_font_color(f, t_.colour("title_font"));
  });
}

lxw_format* Report::section() {
  return cached("section", [&](lxw_format* f) {
    format_set_bold(f);
    format_set_font_size(f, 12);
    format_set_font_color(f, t_.colour("title_font"));
  });
}

lxw_format* Report::note() {
  return cached("note", [&](lxw_format* f) {
    format_set_italic(f);
    format_set_font_color(f, t_.colour("note_font"));
  });
}

lxw_format* Report::wrapped_note() {
  return cached("wrapped_note", [&](lxw_format* f) {
    format_set_italic(f);
    format_set_font_color(f, t_.colour("note_font"));
    format_set_text_wrap(f);
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);
  });
}

lxw_format* Report::bold() {
  return cached("bold", [&](lxw_format* f) {
    format_set_bold(f);
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);  // with the values of a row made taller
  });
}

lxw_format* Report::wrap() {
  return cached("wrap", [&](lxw_format* f) {
    format_set_text_wrap(f);
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);
  });
}

lxw_format* Report::bold_wrap() {
  return cached("bold_wrap", [&](lxw_format* f) {
    format_set_bold(f);
    format_set_text_wrap(f);
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);
  });
}

lxw_format* Report::indented() {
  return cached("indented", [&](lxw_format* f) {
    format_set_indent(f, 1);
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);
  });
}

lxw_format* Report::top() {
  return cached("top", [&](lxw_format* f) {
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);
  });
}

lxw_format* Report::centred() {
  return cached("centred", [&](lxw_format* f) {
    format_set_align(f, LXW_ALIGN_CENTER);
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);
  });
}

lxw_format* Report::centred_bold() {
  return cached("centred_bold", [&](lxw_format* f) {
    format_set_bold(f);
    format_set_align(f, LXW_ALIGN_CENTER);
    format_set_align(f, LXW_ALIGN_VERTICAL_TOP);
  });
}

lxw_format* Report::status_format(std::string_view status) {
  return cached("status." + std::string(status), [&](lxw_format* f) {
    const std::string k = lower(std::string(status));
    format_set_bold(f);
    format_set_font_color(f, t_.colour(k + "_font"));
    format_set_bg_color(f, t_.colour(k + "_fill"));
  });
}

// ---- cells -----------------------------------------------------------------------------

void Report::text(lxw_worksheet* ws, Row r, Col c, const std::string& s, lxw_format* f) {
  if (s.empty()) {
    if (f) check(worksheet_write_blank(ws, r, c, f), "worksheet_write_blank");
    return;
  }
  if (!f) f = top();  // plain text sits at the top of a row made taller by wrapped neighbours
  constexpr std::size_t kMax = 32767;  // Excel's limit of a cell's text
  if (s.size() <= kMax) {
    check(worksheet_write_string(ws, r, c, s.c_str(), f), "worksheet_write_string");
    return;
  }
  std::size_t n = kMax;
  while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
  check(worksheet_write_string(ws, r, c, s.substr(0, n).c_str(), f), "worksheet_write_string");
}

void Report::num(lxw_worksheet* ws, Row r, Col c, double v, lxw_format* f) {
  if (!std::isfinite(v)) {  // an empty cell, never text in a number column
    if (f) check(worksheet_write_blank(ws, r, c, f), "worksheet_write_blank");
    return;
  }
  check(worksheet_write_number(ws, r, c, v, f), "worksheet_write_number");
}

void Report::seed(lxw_worksheet* ws, Row r, Col c, std::uint64_t v, lxw_format* f) {
  if (v <= (std::uint64_t{1} << 53))
    num(ws, r, c, static_cast<double>(v), f);
  else
    text(ws, r, c, std::to_string(v));
}

void Report::merged(lxw_worksheet* ws, Row r, Col c0, Col c1, const std::string& s,
                    lxw_format* f) {
  check(worksheet_merge_range(ws, r, c0, r, c1, s.c_str(), f), "worksheet_merge_range");
}

void Report::paragraph(lxw_worksheet* ws, Row r, Col c0, Col c1, double chars,
                       const std::string& s, lxw_format* f) {
  merged(ws, r, c0, c1, s, f);
  fit_row(ws, r, {{&s, chars}});
}

void Report::headings(lxw_worksheet* ws, Row r, Col c0, std::string_view table,
                      std::initializer_list<std::string_view> keys, double height) {
  Col c = c0;
  for (auto k : keys) text(ws, r, c++, h(table, k), heading());
  check(worksheet_set_row(ws, r, height, nullptr), "worksheet_set_row");
}

double wrapped_lines(const std::string& text, double width) {
  // An average character of text is narrower than Excel's width unit (the digit 0).
  const double room = width * 1.15;
  double n = 0;
  std::size_t p = 0;
  while (p <= text.size()) {  // each line of the text wraps on its own
    std::size_t e = text.find('\n', p);
    if (e == std::string::npos) e = text.size();
    // Word by word, as the spreadsheet wraps (at a space, or after a hyphen): a word that
    // does not fit on the line begins the next (counting characters alone left a rule's
    // "(catch-bench retention)" clipped).
    double used = 0, k = 1;
    std::size_t i = p;
    while (i < e) {
      std::size_t j = i;  // the word: up to a space (left out) or a hyphen (kept)
      double word = 0;
      while (j < e && text[j] != ' ') {
        if ((static_cast<unsigned char>(text[j]) & 0xC0) != 0x80) ++word;
        if (text[j++] == '-') break;
      }
      const bool spaced = used > 0 && i > p && text[i - 1] == ' ';
      if (used > 0 && used + (spaced ? 1 : 0) + word > room) {
        ++k;
        used = 0;
      }
      used += (used > 0 && spaced ? 1 : 0) + word;
      while (used > room) {  // a word longer than the line runs on over the next
        ++k;
        used -= room;
      }
      i = j < e && text[j] == ' ' ? j + 1 : j;
    }
    n += k;
    p = e + 1;
  }
  return n;
}

void Report::fit_row(lxw_worksheet* ws, Row r,
                     std::initializer_list<std::pair<const std::string*, double>> cells) {
  double lines = 1;
  for (const auto& [text, w] : cells) lines = std::max(lines, wrapped_lines(*text, w));
  if (lines > 1)
    check(worksheet_set_row(ws, r, 15.0 * lines, nullptr), "worksheet_set_row");
}

void Report::page_setup(lxw_worksheet* ws) {
  if (t_.landscape) worksheet_set_landscape(ws);
  worksheet_set_paper(ws, static_cast<std::uint8_t>(t_.paper));
  worksheet_fit_to_pages(ws, 1, 0);
  worksheet_set_margins(ws, 0.5, 0.5, 0.6, 0.6);
  check(worksheet_set_footer(ws, t_.get("page", "footer").c_str()), "worksheet_set_footer");
  check(worksheet_set_header(ws, page_header().c_str()), "worksheet_set_header");
}

// The template's header with the project and the document control put in: the date always,
// the project, reference and revision cut (by characters) where they would take the header
// past Excel's 255 characters, an & of theirs doubled (a single one is a code to Excel).
std::string Report::page_header() const {
  auto cut = [](const std::string& s, std::size_t most) {  // at most `most` characters
    std::string p = utf8_prefix(s, most);
    return p.size() < s.size() ? p + "…" : p;
  };
  const LoadedScenario* sc = d_.scenario;
  const std::string project = sc ? sc->scenario.name : std::string();
  const std::string reference = sc ? sc->document.reference : std::string();
  const std::string revision = sc ? sc->document.revision : std::string();
  auto build = [&](std::size_t most) {
    std::string doc;
    auto add = [&](const std::string& part) { doc += (doc.empty() ? "" : "  ·  ") + part; };
    if (!reference.empty()) add(replace_all(cut(reference, most), "&", "&&"));
    if (!revision.empty())
      add(replace_all(replace_all(t_.get("labels", "revision_in_header"), "{revision}",
                                  cut(revision, most)),
                      "&", "&&"));
    add(d_.date);
    return replace_all(replace_all(t_.get("page", "header"), "{project}",
                                   replace_all(cut(project, most), "&", "&&")),
                       "{document}", doc);
  };
  std::size_t most = 80;  // the inputs' own limit: whole, unless the header outgrows Excel's
  std::string h = build(most);
  while (h.size() > 255 && most > 8) h = build(most -= 8);
  return h;
}

void Report::status_colours(lxw_worksheet* ws, Row r0, Row r1, Col c) {
  if (r1 < r0) return;
  for (const char* s : {"PASS", "FAIL", "WARN"}) {
    lxw_conditional_format cf{};
    cf.type = LXW_CONDITIONAL_TYPE_TEXT;
    cf.criteria = LXW_CONDITIONAL_CRITERIA_TEXT_CONTAINING;
    cf.value_string = const_cast<char*>(s);
    cf.format = status_format(s);
    check(worksheet_conditional_format_range(ws, r0, c, r1, c, &cf),
          "worksheet_conditional_format_range");
  }
}

// ---- names -----------------------------------------------------------------------------

std::string Report::line_name(std::uint32_t i) const {
  if (d_.scenario && i < d_.scenario->scenario.lines.size())
    return d_.scenario->scenario.lines[i].name;
  if (i < d_.statistics.lines.size()) return d_.statistics.lines[i].name;
  return fmt::format("line {}", i + 1);
}

double Report::line_chainage(std::uint32_t i) const {
  if (d_.scenario && i < d_.scenario->scenario.lines.size())
    return d_.scenario->scenario.lines[i].x;
  if (i < d_.statistics.lines.size()) return d_.statistics.lines[i].chainage;
  return kNaN;
}

std::optional<std::uint32_t> Report::line_index(const std::string& name) const {
  if (d_.scenario) {
    const auto& ls = d_.scenario->scenario.lines;
    for (std::size_t i = 0; i < ls.size(); ++i)
      if (ls[i].name == name) return static_cast<std::uint32_t>(i);
  }
  for (std::size_t i = 0; i < d_.statistics.lines.size(); ++i)
    if (d_.statistics.lines[i].name == name) return static_cast<std::uint32_t>(i);
  return std::nullopt;
}

// Excel's rules: at most 31 characters, none of []:*?/\, not starting or ending with ', unique
// regardless of case, not "History". Apostrophes are replaced too, so that chart ranges never
// need escaping, and a name a formula reads as a cell reference gets a word in front.
std::string Report::item_sheet_name(std::string_view key, const std::string& item,
                                    std::vector<std::string>& used) {
  const std::string fallback = key == "quarry" ? "Quarry" : "Barrier";
  std::string base = with_name(t_.get("sheets", key), item);
  for (char& c : base)
    if (std::string_view("[]:*?/\\'").find(c) != std::string_view::npos) c = '_';
  if (base.empty()) base = fallback;
  auto trimmed = [&fallback](std::string t) {
    while (!t.empty() && t.back() == ' ') t.pop_back();
    return t.empty() ? fallback : t;
  };
  base = trimmed(utf8_prefix(base, 31));
  // A barrier called "B1" would make a sheet formulas read as cell B1: "Barrier B1" instead.
  if (sheet_name_reads_as_reference(base)) base = trimmed(utf8_prefix(fallback + " " + base, 31));
  std::string name = base;
  for (int k = 2; std::find(used.begin(), used.end(), lower(name)) != used.end(); ++k) {
    const std::string suffix = fmt::format(" ({})", k);
    name = trimmed(utf8_prefix(base, 31 - suffix.size())) + suffix;
  }
  used.push_back(lower(name));
  return name;
}

// ---- the check table (Summary, a barrier, a quarry row) ------------------------------

Row Report::check_table(lxw_worksheet* ws, Row r, const std::vector<design::CheckLine>& lines,
                        bool subject) {
  if (subject) {  // Summary: one column per field
    headings(ws, r, 0, "checks",
             {"subject", "id", "what", "value", "limit", "unit", "rule", "status", "reason"});
  } else {  // a barrier sheet (columns of 14): id, value, limit, unit, status, then merged text
    headings(ws, r, 0, "checks", {"id", "value", "limit", "unit", "status"});
    for (auto [c0, c1, key] : {std::tuple{5, 7, "what"}, std::tuple{8, 9, "rule"},
                               std::tuple{10, 12, "reason"}})
      merged(ws, r, static_cast<Col>(c0), static_cast<Col>(c1), h("checks", key), heading());
  }
  const Row first = ++r;
  for (const auto& l : lines) {
    const std::string status(design::to_string(l.status));
    if (subject) {
      text(ws, r, 0, l.subject, wrap());
      text(ws, r, 1, l.id, wrap());
      text(ws, r, 2, l.what, wrap());
      num(ws, r, 3, l.value, check_number(l.unit, l.value, 1));
      num(ws, r, 4, l.limit, check_number(l.unit, l.limit, 1));
      text(ws, r, 5, l.unit, centred());
      text(ws, r, 6, l.rule, wrap());
      text(ws, r, 7, status, centred_bold());
      text(ws, r, 8, l.reason, wrap());
      fit_row(ws, r, {{&l.subject, 16}, {&l.id, 20}, {&l.what, 34}, {&l.rule, 26},
                      {&l.reason, 44}});
    } else {
      text(ws, r, 0, l.id, wrap());
      num(ws, r, 1, l.value, check_number(l.unit, l.value, 1));
      num(ws, r, 2, l.limit, check_number(l.unit, l.limit, 1));
      text(ws, r, 3, l.unit, centred());
      text(ws, r, 4, status, centred_bold());
      for (auto [c0, c1, t] : {std::tuple{5, 7, &l.what}, std::tuple{8, 9, &l.rule},
                               std::tuple{10, 12, &l.reason}})
        merged(ws, r, static_cast<Col>(c0), static_cast<Col>(c1), *t, wrap());
      fit_row(ws, r, {{&l.what, 42}, {&l.rule, 28}, {&l.reason, 42}});
    }
    ++r;
  }
  // The status column, coloured by conditional formats (the words decide, not static colours).
  status_colours(ws, first, r - 1, static_cast<Col>(subject ? 7 : 4));
  return r;
}

}  // namespace pierre::io::detail
