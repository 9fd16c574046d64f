#include "pierre/io/xlsx_report.hpp"

#include <unistd.h>
#include <xlsxwriter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "pierre/stats/empirical_cdf.hpp"
#include "pierre/stats/lognormal_fit.hpp"
#include "pierre/stats/percentile.hpp"
#include "pierre/stats/weibull_fit.hpp"

namespace pierre::io {
namespace {

namespace fs = std::filesystem;
using Row = lxw_row_t;
using Col = lxw_col_t;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A drawn trajectory keeps at most this many points: more cannot be seen in a chart, and a
// block that bounces in place until the impact or time limit records hundreds of thousands,
// which a few such paths would carry past a sheet's 1 048 576 rows.
constexpr std::size_t kMaxPathPoints = 2000;

// The points of `path` to draw: the first, then each one at least 1/10 000 of the path's extent
// from the last kept (a block bouncing in place adds nothing a chart can show, and would crowd
// out the flights before it), and the last; above kMaxPathPoints, evenly spaced ones of those.
std::vector<geometry::Vec2> drawn_points(const std::vector<geometry::Vec2>& path) {
  if (path.empty()) return {};
  double x0 = path[0].x, x1 = x0, z0 = path[0].z, z1 = z0;
  for (const auto& p : path) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
  }
  const double step = 1e-4 * std::hypot(x1 - x0, z1 - z0);
  std::vector<geometry::Vec2> kept{path.front()};
  for (const auto& p : path)
    if (std::hypot(p.x - kept.back().x, p.z - kept.back().z) > step) kept.push_back(p);
  if (path.back().x != kept.back().x || path.back().z != kept.back().z) kept.push_back(path.back());
  if (kept.size() <= kMaxPathPoints) return kept;
  std::vector<geometry::Vec2> out;
  out.reserve(kMaxPathPoints);
  const std::size_t last = kept.size() - 1;
  for (std::size_t k = 0; k < kMaxPathPoints; ++k) out.push_back(kept[k * last / (kMaxPathPoints - 1)]);
  return out;
}

[[noreturn]] void fail(std::string_view what, lxw_error e) {
  throw std::runtime_error(
      fmt::format("report.xlsx: {}: {}", what, lxw_strerror(e)));
}
void check(lxw_error e, std::string_view what) {
  if (e != LXW_NO_ERROR) fail(what, e);
}
template <class T>
T* check_ptr(T* p, std::string_view what) {
  if (!p) throw std::runtime_error(fmt::format("report.xlsx: {} failed", what));
  return p;
}

std::string replace_all(std::string s, std::string_view key, std::string_view value) {
  for (std::size_t p = s.find(key); p != std::string::npos; p = s.find(key, p + value.size()))
    s.replace(p, key.size(), value);
  return s;
}

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
std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// An ISO date "YYYY-MM-DD" (anything after the tenth character is ignored).
std::chrono::year_month_day parse_date(const std::string& s) {
  int y = 0;
  unsigned m = 0, d = 0;
  char dash1 = 0, dash2 = 0;
  if (s.size() >= 10 &&
      std::sscanf(s.substr(0, 10).c_str(), "%4d%c%2u%c%2u", &y, &dash1, &m, &dash2, &d) == 5 &&
      dash1 == '-' && dash2 == '-') {
    const std::chrono::year_month_day ymd{std::chrono::year{y}, std::chrono::month{m},
                                          std::chrono::day{d}};
    if (ymd.ok() && y >= 1900 && y <= 9999) return ymd;
  }
  throw std::runtime_error(fmt::format(
      "report.xlsx: the run's date \"{}\" is not an ISO date (YYYY-MM-DD); it fixes the "
      "workbook's creation time",
      s));
}

std::string format_number(double v) {
  if (!std::isfinite(v)) return "—";
  return fmt::format("{:.4g}", v);
}

// ---- the data behind the charts --------------------------------------------------------

struct Histogram {
  double lo = 0, width = 1;
  std::vector<std::uint64_t> counts;
  std::vector<double> density;
};

Histogram histogram(std::span<const double> x, int bins) {
  Histogram h;
  double mn = std::numeric_limits<double>::infinity(), mx = -mn;
  std::size_t n = 0;
  for (double v : x)
    if (std::isfinite(v)) {
      mn = std::min(mn, v);
      mx = std::max(mx, v);
      ++n;
    }
  if (n == 0) return h;
  // Non-negative quantities start at zero unless the data sit far from it.
  h.lo = (mn >= 0 && mn <= 0.25 * mx) ? 0.0 : mn;
  double hi = mx;
  if (!(hi > h.lo)) hi = h.lo + 1;
  h.width = (hi - h.lo) / bins;
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  for (double v : x) {
    if (!std::isfinite(v)) continue;
    auto b = static_cast<long>(std::floor((v - h.lo) / h.width));
    b = std::clamp(b, 0L, static_cast<long>(bins) - 1);
    ++h.counts[static_cast<std::size_t>(b)];
  }
  for (auto c : h.counts)
    h.density.push_back(static_cast<double>(c) / (static_cast<double>(n) * h.width));
  return h;
}

// ---- the workbook --------------------------------------------------------------------

struct Cell {
  Row row;
  Col col;
};

class Report {
 public:
  Report(lxw_workbook* wb, const ReportData& data, const ReportTemplate& tpl)
      : wb_(wb), d_(data), t_(tpl) {}

  void write();

 private:
  // -- formats
  lxw_format* add_format() { return check_ptr(workbook_add_format(wb_), "workbook_add_format"); }
  // A number format of the template, cached; `align`: 0 as Excel does (right), 1 centred,
  // 2 left.
  lxw_format* number(std::string_view kind, int align = 0);
  // The format of a check line's value: by unit, else by size (integers, tiny probabilities).
  lxw_format* check_number(const std::string& unit, double v, int align);
  lxw_format* heading();
  lxw_format* title();
  lxw_format* section();
  lxw_format* note();
  lxw_format* bold();
  lxw_format* wrap();
  lxw_format* centred();
  lxw_format* top();
  lxw_format* indented();
  lxw_format* centred_bold();
  lxw_format* status_format(std::string_view status);  // for the conditional formats

  // -- cells
  void text(lxw_worksheet* ws, Row r, Col c, const std::string& s, lxw_format* f = nullptr);
  void num(lxw_worksheet* ws, Row r, Col c, double v, lxw_format* f);
  void opt(lxw_worksheet* ws, Row r, Col c, const std::optional<double>& v, lxw_format* f) {
    if (v) num(ws, r, c, *v, f);
  }
  void count(lxw_worksheet* ws, Row r, Col c, std::uint64_t v) {
    num(ws, r, c, static_cast<double>(v), number("count"));
  }
  // A heading row: the template's headings of `table` for `keys`, from column `c0`.
  void headings(lxw_worksheet* ws, Row r, Col c0, std::string_view table,
                std::initializer_list<std::string_view> keys, double height = 30);
  void width(lxw_worksheet* ws, Col c0, Col c1, double w) {
    check(worksheet_set_column(ws, c0, c1, w, nullptr), "worksheet_set_column");
  }
  // Columns c0 … c1 at `base`, some of them wider: one <col> entry per run of equal width.
  // (Overlapping entries, a range set and then one column in it again, are what libxlsxwriter
  // writes as it is told; LibreOffice then ignores the wider one and Excel may repair.)
  void widths(lxw_worksheet* ws, Col c0, Col c1, double base,
              std::initializer_list<std::pair<Col, double>> wider) {
    auto at = [&](Col c) {
      for (const auto& [col, w] : wider)
        if (col == c) return w;
      return base;
    };
    for (Col a = c0; a <= c1;) {
      Col b = a;
      while (b < c1 && at(b + 1) == at(a)) ++b;
      width(ws, a, b, at(a));
      a = b + 1;
    }
  }
  const std::string& h(std::string_view table, std::string_view key) const {
    return t_.get("headings." + std::string(table), key);
  }
  const char* keep(std::string s) { return strings_.emplace_back(std::move(s)).c_str(); }
  // One row of a data sheet (Trajectories, Crossings). In a quarry run its first cell names the
  // row's section and the others move one column right; names come from that section.
  struct DataRow {
    Report& rep;
    lxw_worksheet* ws;
    Row r;
    Col c0;
    const sim::Scenario* scenario;
    void num(Col c, double v, lxw_format* f) const { rep.num(ws, r, c + c0, v, f); }
    void text(Col c, const std::string& v, lxw_format* f = nullptr) const {
      rep.text(ws, r, c + c0, v, f);
    }
  };
  DataRow data_row(lxw_worksheet* ws, Row r, const std::vector<std::uint32_t>& sections,
                   std::size_t i) {
    DataRow row{*this, ws, r, sections.empty() ? Col{0} : Col{1},
                d_.scenario ? &d_.scenario->scenario : nullptr};
    if (d_.scenario && i < sections.size() && sections[i] < d_.scenario->quarries.size()) {
      const auto& q = d_.scenario->quarries[sections[i]];
      text(ws, r, 0, q.spec.name);
      row.scenario = &q.scenario;
    }
    return row;
  }
  // Sets row r's height to show every wrapped text: (text, width of its cells in characters).
  void fit_row(lxw_worksheet* ws, Row r,
               std::initializer_list<std::pair<const std::string*, double>> cells);
  void page_setup(lxw_worksheet* ws);
  void status_colours(lxw_worksheet* ws, Row r0, Row r1, Col c);

  // -- charts
  lxw_chart* scatter_chart(std::string_view chart_key, const std::string& name);
  lxw_chart_series* xy_series(lxw_chart* chart, const std::string& sheet, Row r0, Row r1, Col xc, Col yc,
                 const std::string& name, std::uint32_t colour, float line_width,
                 std::uint8_t dash = LXW_CHART_LINE_DASH_SOLID);
  // Filled markers of one colour on a series; with `line_too` false the points stand alone.
  void markers(lxw_chart_series* s, std::uint8_t type, std::uint8_t size, lxw_color_t colour,
               bool line_too);
  void insert_chart(lxw_worksheet* ws, Cell at, lxw_chart* chart, double x_scale = 1,
                    double y_scale = 1);
  // Axis bounds that draw a section at one scale in x and z (a 32° slope looks 32°): the
  // longer extent for its axis fixes metres per pixel of the plot area, the other axis gets
  // as many metres as its pixels hold. The plot area is taken as its usual share of the chart.
  void equal_scale(lxw_chart* chart, double xmin, double xmax, double zmin, double zmax,
                   double x_scale, double y_scale);
  // The drawing data of the quarry section of that name (nullptr when none was passed).
  const ReportData::QuarrySectionView* section_view(const std::string& name) const {
    for (const auto& v : d_.quarry_sections)
      if (v.name == name) return &v;
    return nullptr;
  }
  // A label per point of a series, by name; an empty name hides that point's label.
  void point_labels(lxw_chart_series* s, const std::vector<std::string>& names);
  // Writes the drawn points of `paths` in columns 2 (x) and 3 (z) from row r0, an empty row
  // after each path; returns the row after the last one written.
  Row path_rows(lxw_worksheet* ws, Row r0, const std::vector<std::vector<geometry::Vec2>>& paths,
                lxw_format* xf);

  // -- sheets
  // The sheet of a barrier or a quarry row: the template's sheets.<key> with {name} replaced.
  std::string item_sheet_name(std::string_view key, const std::string& item,
                              std::vector<std::string>& used);
  void summary(lxw_worksheet* ws);
  Row check_table(lxw_worksheet* ws, Row r, const std::vector<design::CheckLine>& lines,
                  bool subject);
  void inputs(lxw_worksheet* ws);
  void barrier(lxw_worksheet* ws, const std::string& sheet, const design::BarrierDesign& b);
  void profile(lxw_worksheet* ws, const std::string& sheet);
  // Quarry danger zones (xlsx_report.cpp, "a quarry row").
  Row quarry_summary(lxw_worksheet* ws, Row r);
  void quarry(lxw_worksheet* ws, const std::string& sheet, std::size_t row);
  // A distance (m or /H): a number, or "beyond the profile" for +infinity.
  void distance(lxw_worksheet* ws, Row r, Col c, double v, lxw_format* f);
  // The histogram, CDF and fitted curves of one distance of a row (data block at `data_row`,
  // charts at `at` and beside it); returns the next free data row.
  Row quarry_distance_charts(lxw_worksheet* ws, const std::string& sheet, Row data_row, Cell at,
                             Col cdf_col, std::string_view which, const design::QuarryRow& row);
  Row quarry_section_chart(lxw_worksheet* ws, const std::string& sheet, Row data_row, Cell at,
                           const design::QuarrySectionResult& s);
  void trajectories(lxw_worksheet* ws);
  void crossings(lxw_worksheet* ws);
  Row cap_note(lxw_worksheet* ws, Row r, std::size_t shown, std::uint64_t total,
               const char* csv);

  std::string line_name(std::uint32_t i) const;
  double line_chainage(std::uint32_t i) const;
  std::optional<std::uint32_t> line_index(const std::string& name) const;

  lxw_workbook* wb_;
  const ReportData& d_;
  const ReportTemplate& t_;
  // The workbook's formats, made on first use and shared by name: libxlsxwriter keeps every
  // format it is given, so one per cell would bloat the file. `setup` styles a new one.
  template <class Setup>
  lxw_format* cached(std::string_view key, Setup&& setup) {
    if (auto it = formats_.find(key); it != formats_.end()) return it->second;
    lxw_format* f = add_format();
    setup(f);
    return formats_.emplace(std::string(key), f).first->second;
  }
  std::map<std::string, lxw_format*, std::less<>> formats_;
  std::deque<std::string> strings_;
  std::deque<std::vector<lxw_row_t>> breaks_;  // kept alive until the workbook is written
};

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
  if (unit == "kJ") return number("energy", align);
  if (unit == "m") return number("length", align);
  if (unit == "m/s") return number("speed", align);
  if (unit == "%") return number("length", align);  // two decimals
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15) return number("count", align);
  if (std::isfinite(v) && v != 0 && std::abs(v) < 1e-3) return number("scientific", align);
  return number("parameter", align);
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

void Report::headings(lxw_worksheet* ws, Row r, Col c0, std::string_view table,
                      std::initializer_list<std::string_view> keys, double height) {
  Col c = c0;
  for (auto k : keys) text(ws, r, c++, h(table, k), heading());
  check(worksheet_set_row(ws, r, height, nullptr), "worksheet_set_row");
}

void Report::fit_row(lxw_worksheet* ws, Row r,
                     std::initializer_list<std::pair<const std::string*, double>> cells) {
  double lines = 1;
  for (const auto& [text, w] : cells) {
    double n = 0;
    std::size_t p = 0;
    while (p <= text->size()) {  // each line of the text wraps on its own
      std::size_t e = text->find('\n', p);
      if (e == std::string::npos) e = text->size();
      std::size_t chars = 0;
      for (std::size_t i = p; i < e; ++i)
        if ((static_cast<unsigned char>((*text)[i]) & 0xC0) != 0x80) ++chars;
      // An average character of text is narrower than Excel's width unit (the digit 0).
      n += std::max(1.0, std::ceil(static_cast<double>(chars) / (w * 1.15)));
      p = e + 1;
    }
    lines = std::max(lines, n);
  }
  if (lines > 1)
    check(worksheet_set_row(ws, r, 15.0 * lines, nullptr), "worksheet_set_row");
}

void Report::page_setup(lxw_worksheet* ws) {
  if (t_.landscape) worksheet_set_landscape(ws);
  worksheet_set_paper(ws, static_cast<std::uint8_t>(t_.paper));
  worksheet_fit_to_pages(ws, 1, 0);
  worksheet_set_margins(ws, 0.5, 0.5, 0.6, 0.6);
  check(worksheet_set_footer(ws, t_.get("page", "footer").c_str()), "worksheet_set_footer");
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

// ---- charts ----------------------------------------------------------------------------

lxw_chart* Report::scatter_chart(std::string_view chart_key, const std::string& name) {
  lxw_chart* chart =
      check_ptr(workbook_add_chart(wb_, LXW_CHART_SCATTER_STRAIGHT), "workbook_add_chart");
  const std::string section = "chart." + std::string(chart_key);
  chart_title_set_name(chart, keep(replace_all(t_.get(section, "title"), "{name}", name)));
  lxw_chart_font title_font{};
  title_font.size = 11;
  title_font.bold = LXW_EXPLICIT_FALSE;
  chart_title_set_name_font(chart, &title_font);
  chart_axis_set_name(chart->x_axis, keep(t_.get(section, "x_axis")));
  chart_axis_set_name(chart->y_axis, keep(t_.get(section, "y_axis")));
  chart_axis_major_gridlines_set_visible(chart->x_axis, LXW_TRUE);
  lxw_chart_line grid{};
  grid.color = 0xD9D9D9;
  grid.width = 0.5f;
  chart_axis_major_gridlines_set_line(chart->x_axis, &grid);
  chart_axis_major_gridlines_set_line(chart->y_axis, &grid);
  chart_axis_set_label_position(chart->x_axis, LXW_CHART_AXIS_LABEL_POSITION_LOW);
  chart_axis_set_label_position(chart->y_axis, LXW_CHART_AXIS_LABEL_POSITION_LOW);
  chart_legend_set_position(chart, LXW_CHART_LEGEND_BOTTOM);
  chart_show_blanks_as(chart, LXW_CHART_BLANKS_AS_GAP);
  return chart;
}

lxw_chart_series* Report::xy_series(lxw_chart* chart, const std::string& sheet, Row r0, Row r1, Col xc,
                       Col yc, const std::string& name, std::uint32_t colour, float line_width,
                       std::uint8_t dash) {
  lxw_chart_series* s = check_ptr(chart_add_series(chart, nullptr, nullptr), "chart_add_series");
  // A scatter series needs categories (x) AND values (y), or libxlsxwriter drops the chart.
  chart_series_set_categories(s, keep(sheet), r0, xc, r1, xc);
  chart_series_set_values(s, keep(sheet), r0, yc, r1, yc);
  chart_series_set_name(s, keep(name));
  lxw_chart_line line{};
  line.color = colour;
  line.width = line_width;
  line.dash_type = dash;
  chart_series_set_line(s, &line);
  chart_series_set_marker_type(s, LXW_CHART_MARKER_NONE);
  return s;
}

void Report::markers(lxw_chart_series* s, std::uint8_t type, std::uint8_t size,
                     lxw_color_t colour, bool line_too) {
  if (!line_too) {
    lxw_chart_line none{};
    none.none = LXW_TRUE;
    chart_series_set_line(s, &none);
  }
  chart_series_set_marker_type(s, type);
  chart_series_set_marker_size(s, size);
  lxw_chart_fill fill{};
  fill.color = colour;
  chart_series_set_marker_fill(s, &fill);
  lxw_chart_line edge{};
  edge.color = colour;
  chart_series_set_marker_line(s, &edge);
}

void Report::equal_scale(lxw_chart* chart, double xmin, double xmax, double zmin, double zmax,
                         double x_scale, double y_scale) {
  if (!(xmax > xmin) || !(zmax >= zmin)) return;
  const double w = t_.chart_width * x_scale * 0.85, h = t_.chart_height * y_scale * 0.68;
  const double margin = 0.05 * std::max(zmax - zmin, 1e-9);
  const double per_px = std::max((xmax - xmin) / w, (zmax - zmin + 2 * margin) / h);
  // Bounds on round numbers (Excel labels the ticks from them), widening only.
  auto round_step = [](double range) { return std::pow(10.0, std::floor(std::log10(range))) / 2; };
  const double xs = round_step(per_px * w), zs = round_step(per_px * h);
  const double x0 = std::floor(xmin / xs) * xs, z0 = std::floor((zmin - margin) / zs) * zs;
  chart_axis_set_min(chart->x_axis, x0);
  chart_axis_set_max(chart->x_axis, std::ceil((x0 + per_px * w) / xs) * xs);
  chart_axis_set_min(chart->y_axis, z0);
  chart_axis_set_max(chart->y_axis, std::ceil((z0 + per_px * h) / zs) * zs);
}

void Report::point_labels(lxw_chart_series* s, const std::vector<std::string>& names) {
  std::vector<lxw_chart_data_label> labels(names.size());
  std::vector<lxw_chart_data_label*> list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty())
      labels[i].hide = LXW_TRUE;
    else
      labels[i].value = const_cast<char*>(keep(names[i]));
    list.push_back(&labels[i]);
  }
  list.push_back(nullptr);
  chart_series_set_labels(s);
  chart_series_set_labels_position(s, LXW_CHART_LABEL_POSITION_RIGHT);
  check(chart_series_set_labels_custom(s, list.data()), "chart_series_set_labels_custom");
}

void Report::insert_chart(lxw_worksheet* ws, Cell at, lxw_chart* chart, double x_scale,
                          double y_scale) {
  lxw_chart_options o{};
  o.x_scale = x_scale * t_.chart_width / 480.0;  // libxlsxwriter's default chart: 480 × 288 px
  o.y_scale = y_scale * t_.chart_height / 288.0;
  o.x_offset = 4;
  o.y_offset = 4;
  check(worksheet_insert_chart_opt(ws, at.row, at.col, chart, &o), "worksheet_insert_chart");
}

Row Report::path_rows(lxw_worksheet* ws, Row r0,
                     const std::vector<std::vector<geometry::Vec2>>& paths, lxw_format* xf) {
  Row r = r0;
  for (const auto& path : paths) {
    if (path.empty()) continue;
    for (const auto& p : drawn_points(path)) {
      num(ws, r, 2, p.x, xf);
      num(ws, r++, 3, p.z, xf);
    }
    ++r;  // an empty row: a gap between paths
  }
  return r;
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
  std::string base = replace_all(t_.get("sheets", key), "{name}", item);
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

// ---- Summary ---------------------------------------------------------------------------

Row Report::check_table(lxw_worksheet* ws, Row r, const std::vector<design::CheckLine>& lines,
                        bool subject) {
  if (subject) {  // Summary: one column per field
    headings(ws, r, 0, "checks",
             {"subject", "id", "what", "value", "limit", "unit", "rule", "status", "reason"});
  } else {  // a barrier sheet (columns of 14): id, value, limit, unit, status, then merged text
    headings(ws, r, 0, "checks", {"id", "value", "limit", "unit", "status"});
    for (auto [c0, c1, key] : {std::tuple{5, 7, "what"}, std::tuple{8, 9, "rule"},
                               std::tuple{10, 12, "reason"}})
      check(worksheet_merge_range(ws, r, static_cast<Col>(c0), r, static_cast<Col>(c1),
                                  h("checks", key).c_str(), heading()),
            "worksheet_merge_range");
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
        check(worksheet_merge_range(ws, r, static_cast<Col>(c0), r, static_cast<Col>(c1),
                                    t->c_str(), wrap()),
              "worksheet_merge_range");
      fit_row(ws, r, {{&l.what, 42}, {&l.rule, 28}, {&l.reason, 42}});
    }
    ++r;
  }
  // The status column, coloured by conditional formats (the words decide, not static colours).
  status_colours(ws, first, r - 1, static_cast<Col>(subject ? 7 : 4));
  return r;
}

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

  const LoadedScenario* sc = d_.scenario;
  text(ws, 0, 0, t_.get("titles", "summary"), title());
  check(worksheet_set_row(ws, 0, 24, nullptr), "worksheet_set_row");
  Row r = 2;
  text(ws, r++, 0, t_.get("titles", "run"), section());
  auto label = [&](std::string_view key) { text(ws, r, 0, t_.get("labels", key), bold()); };
  label("project");
  text(ws, r++, 2, sc ? sc->scenario.name : std::string());
  if (sc && !sc->description.empty()) {
    label("description");
    text(ws, r++, 2, sc->description);
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
  if (d_.seed <= (std::uint64_t{1} << 53)) {  // exact as a double
    num(ws, r++, 2, static_cast<double>(d_.seed), number("general", 2));
  } else {
    text(ws, r++, 2, std::to_string(d_.seed));  // a double would round it
  }
  label("throws");
  num(ws, r++, 2, d_.throws, number("count", 2));
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
      num(ws, r++, 2, v, number("length", 2));
    }
  }

  // Recommended barriers.
  if (!d_.barriers.empty()) {
    ++r;
    text(ws, r++, 0, t_.get("titles", "barriers"), section());
    headings(ws, r++, 0, "barriers",
             {"name", "line", "rules", "chainage", "energy_class", "class_mel", "class_sel",
              "mel_req", "sel_req", "interception_height"},
             45);
    for (const auto& b : d_.barriers) {
      text(ws, r, 0, b.spec.name);
      text(ws, r, 1, b.spec.line);
      text(ws, r, 2, b.rules_name.empty() ? b.spec.rules : b.rules_name, wrap());
      num(ws, r, 3, b.chainage, number("coordinate", 1));
      if (b.energy_class) {
        num(ws, r, 4, b.energy_class->number, number("count", 1));
        num(ws, r, 5, b.energy_class->mel_kJ, number("energy", 1));
        num(ws, r, 6, b.energy_class->sel_kJ, number("energy", 1));
      } else {
        text(ws, r, 4, t_.get("labels", "none"), centred());
      }
      num(ws, r, 7, b.MEL_req_kJ, number("energy", 1));
      num(ws, r, 8, b.SEL_req_kJ, number("energy", 1));
      num(ws, r, 9, b.h_i, number("length", 1));
      const std::string rules = b.rules_name.empty() ? b.spec.rules : b.rules_name;
      fit_row(ws, r, {{&b.spec.name, 16}, {&b.spec.line, 20}, {&rules, 34}});
      ++r;
    }
    // How each class was chosen: on which capacity, from which table (its source).
    for (const auto& b : d_.barriers)
      if (const auto it = b.how.find("energy_class"); b.energy_class && it != b.how.end())
        text(ws, r++, 0, b.spec.name + ": class " + std::to_string(b.energy_class->number) + ", " +
                             it->second, note());
  }

  // Observation lines.
  if (!d_.statistics.lines.empty()) {
    ++r;
    text(ws, r++, 0, t_.get("titles", "lines"), section());
    headings(ws, r++, 0, "lines",
             {"name", "chainage", "count", "not_reached", "speed_mean", "speed_p95",
              "height_p95", "energy_p95", "energy_max"},
             45);
    for (const auto& l : d_.statistics.lines) {
      text(ws, r, 0, l.name);
      num(ws, r, 1, l.chainage, number("coordinate", 1));
      num(ws, r, 2, static_cast<double>(l.count), number("count", 1));
      num(ws, r, 3, static_cast<double>(l.not_reached), number("count", 1));
      num(ws, r, 4, l.count ? l.speed.mean : kNaN, number("speed", 1));
      num(ws, r, 5, l.count ? l.speed.p95 : kNaN, number("speed", 1));
      num(ws, r, 6, l.count ? l.height.p95 : kNaN, number("length", 1));
      num(ws, r, 7, l.count ? l.translational_energy.p95 / 1000 : kNaN, number("energy", 1));
      num(ws, r, 8, l.count ? l.translational_energy.max / 1000 : kNaN, number("energy", 1));
      ++r;
    }
  }

  // Quarry danger zones: Tables 6.2/6.3's rows and their average.
  if (d_.quarry) r = quarry_summary(ws, r);

  // Every check line, whatever its subject: the caller's, then the quarry design's that the
  // caller did not pass (same subject and id).
  std::vector<design::CheckLine> lines = d_.checks;
  if (d_.quarry)
    for (const auto& l : d_.quarry->checks)
      if (std::none_of(d_.checks.begin(), d_.checks.end(), [&](const design::CheckLine& c) {
            return c.subject == l.subject && c.id == l.id;
          }))
        lines.push_back(l);
  ++r;
  text(ws, r++, 0, t_.get("titles", "checks"), section());
  // The verdict first: how many lines FAIL, as `pierre check` counts them.
  std::size_t n[4] = {0, 0, 0, 0};  // pass, fail, warn, N/A
  for (const auto& l : lines) ++n[static_cast<int>(l.status)];
  std::string verdict = lines.empty() ? t_.get("labels", "no_checks") : t_.get("labels", "verdict");
  for (auto [key, v] : {std::pair{"{lines}", lines.size()}, {"{fail}", n[1]}, {"{warn}", n[2]},
                        {"{pass}", n[0]}, {"{na}", n[3]}})
    verdict = replace_all(verdict, key, std::to_string(v));
  text(ws, r++, 0, verdict, bold());
  const Row head = r;
  r = check_table(ws, r, lines, true);
  check(worksheet_print_area(ws, 0, 0, r > 0 ? r - 1 : 0, d_.quarry ? 11 : 9),
        "worksheet_print_area");
  check(worksheet_repeat_rows(ws, head, head), "worksheet_repeat_rows");
}

// ---- Inputs ----------------------------------------------------------------------------

void Report::inputs(lxw_worksheet* ws) {
  page_setup(ws);
  width(ws, 0, 0, 30);
  width(ws, 1, 8, 16);
  text(ws, 0, 0, t_.get("titles", "inputs"), title());
  Row r = 2;
  const LoadedScenario* sc = d_.scenario;
  if (sc) {
    const auto& s = sc->scenario;
    text(ws, r++, 0, t_.get("titles", "simulation"), section());
    headings(ws, r++, 0, "simulation",
             {"seed", "throws", "gravity", "max_time", "max_impacts", "stop_head_factor",
              "max_sliding_speed"});
    if (s.settings.seed <= (std::uint64_t{1} << 53))
      num(ws, r, 0, static_cast<double>(s.settings.seed), number("general", 1));
    else
      text(ws, r, 0, std::to_string(s.settings.seed));
    count(ws, r, 1, s.settings.throws);
    num(ws, r, 2, s.settings.gravity, number("material"));
    num(ws, r, 3, s.settings.max_time, number("time"));
    num(ws, r, 4, static_cast<double>(s.settings.max_impacts), number("count"));
    num(ws, r, 5, s.settings.stop_head_factor, number("factor"));
    num(ws, r++, 6, s.settings.max_sliding_speed, number("speed"));

    ++r;
    text(ws, r++, 0, t_.get("titles", "materials"), section());
    if (!sc->materials_file.empty()) {
      text(ws, r, 0, t_.get("labels", "materials_file"), bold());
      text(ws, r++, 1, sc->materials_file.string());
    }
    headings(ws, r++, 0, "materials",
             {"name", "source", "normal_energy", "normal_energy_k", "tangential_energy",
              "tangential_energy_k", "roughness", "friction_angle"});
    for (const auto& m : s.materials) {
      text(ws, r, 0, m.name);
      text(ws, r, 1, m.source, wrap());
      num(ws, r, 2, m.normal_energy, number("material"));
      num(ws, r, 3, m.normal_energy_k, number("material"));
      num(ws, r, 4, m.tangential_energy, number("material"));
      num(ws, r, 5, m.tangential_energy_k, number("material"));
      num(ws, r, 6, m.roughness, number("material"));
      num(ws, r, 7, m.friction_angle_deg, number("angle"));
      fit_row(ws, r++, {{&m.source, 16}});
    }

    ++r;
    text(ws, r++, 0, t_.get("titles", "blocks"), section());
    headings(ws, r++, 0, "blocks",
             {"id", "mass", "volume", "density", "shape_min", "shape_max", "count"});
    // A quarry scenario's blocks and sources are its sections': each under its name.
    auto each_section = [&](auto&& write) {
      if (sc->quarries.empty()) return write(sc->block_groups, s.sources);
      for (const auto& q : sc->quarries) {
        text(ws, r++, 0, q.spec.name, bold());
        write(q.block_groups, q.scenario.sources);
      }
    };
    each_section([&](const auto& groups, const auto&) {
      for (const auto& b : groups) {
        text(ws, r, 0, b.id);
        num(ws, r, 1, b.mass, number("mass"));
        num(ws, r, 2, b.volume, number("volume"));
        num(ws, r, 3, b.density, number("density"));
        num(ws, r, 4, b.shape_min, number("factor"));
        num(ws, r, 5, b.shape_max, number("factor"));
        count(ws, r++, 6, b.count);
      }
    });

    ++r;
    text(ws, r++, 0, t_.get("titles", "sources"), section());
    headings(ws, r++, 0, "sources", {"name", "x", "z", "vx", "vz", "omega"});
    each_section([&](const auto&, const auto& sources) {
      for (const auto& so : sources) {
        text(ws, r, 0, so.name);
        num(ws, r, 1, so.position.x, number("coordinate"));
        num(ws, r, 2, so.position.z, number("coordinate"));
        num(ws, r, 3, so.velocity.x, number("speed"));
        num(ws, r, 4, so.velocity.z, number("speed"));
        num(ws, r++, 5, so.omega, number("speed"));
      }
    });

    // The section as read: every vertex with the material of the segment that starts there
    // (the last vertex ends the profile).
    ++r;
    text(ws, r++, 0, t_.get("titles", "profile_vertices"), section());
    headings(ws, r++, 0, "profile_vertices", {"x", "z", "material"});
    auto vertices = [&](const sim::Scenario& sec) {
      const auto& segs = sec.profile.segments();
      for (std::size_t k = 0; k < segs.size(); ++k) {
        num(ws, r, 0, segs[k].a.x, number("coordinate"));
        num(ws, r, 1, segs[k].a.z, number("coordinate"));
        const auto m = static_cast<std::size_t>(segs[k].material);
        if (m < sec.materials.size()) text(ws, r, 2, sec.materials[m].name);
        ++r;
      }
      if (!segs.empty()) {
        num(ws, r, 0, segs.back().b.x, number("coordinate"));
        num(ws, r++, 1, segs.back().b.z, number("coordinate"));
      }
    };
    if (sc->quarries.empty()) {
      vertices(s);
    } else {
      for (const auto& q : sc->quarries) {
        text(ws, r++, 0, q.spec.name, bold());
        vertices(q.scenario);
      }
    }

    ++r;
    text(ws, r++, 0, t_.get("titles", "observation_lines"), section());
    headings(ws, r++, 0, "observation_lines", {"name", "x"});
    for (const auto& l : s.lines) {
      text(ws, r, 0, l.name);
      num(ws, r++, 1, l.x, number("coordinate"));
    }
  }

  // Barriers: one column per barrier, one row per input.
  if (!d_.barriers.empty()) {
    ++r;
    text(ws, r++, 0, t_.get("titles", "barrier_inputs"), section());
    text(ws, r, 0, h("barrier_inputs", "field"), heading());
    for (std::size_t i = 0; i < d_.barriers.size() && i < 200; ++i)
      text(ws, r, static_cast<Col>(1 + i), d_.barriers[i].spec.name, heading());
    ++r;
    const Row top = r;
    auto row = [&](std::string_view key) {
      text(ws, r, 0, h("barrier_inputs", key), bold());
      return r++;
    };
    const Row line = row("line"), rules = row("rules"), block = row("design_block"),
              volume = row("volume"), density = row("density"), pct = row("percentile"),
              df = row("free_board_diameter"), dq = row("data_quality"),
              cls = row("energy_class"), mel = row("mel"), sel = row("sel"),
              height = row("height"), el_mel = row("elongation_mel"),
              el_sel = row("elongation_sel"), dist = row("distance_to_object"),
              resid = row("residual_height"), acc_e = row("acceptable_energy"),
              acc_h = row("acceptable_height"), obs = row("observed_file");
    (void)top;
    for (std::size_t i = 0; i < d_.barriers.size() && i < 200; ++i) {
      const auto& s = d_.barriers[i].spec;
      const Col c = static_cast<Col>(1 + i);
      text(ws, line, c, s.line);
      text(ws, rules, c, s.rules);
      using K = design::DesignBlock::Kind;
      const auto& db = s.design_block;
      text(ws, block, c,
           db.kind == K::given     ? "given"
           : db.kind == K::largest ? "largest"
                                   : "percentile");
      if (db.kind == K::given) num(ws, volume, c, db.volume, number("volume"));
      if (db.density > 0) num(ws, density, c, db.density, number("density"));
      if (db.kind == K::percentile) num(ws, pct, c, db.percentile, number("general"));
      opt(ws, df, c, s.free_board_diameter, number("length"));
      std::string q;
      for (const auto& [k, v] : s.data_quality) q += (q.empty() ? "" : "; ") + k + " = " + v;
      text(ws, dq, c, keep(q), wrap());
      fit_row(ws, dq, {{&strings_.back(), 16}});
      if (s.candidate) {
        const auto& cb = *s.candidate;
        if (cb.energy_class) num(ws, cls, c, *cb.energy_class, number("count"));
        opt(ws, mel, c, cb.mel_kJ, number("energy"));
        opt(ws, sel, c, cb.sel_kJ, number("energy"));
        opt(ws, height, c, cb.height, number("length"));
        opt(ws, el_mel, c, cb.elongation_mel, number("length"));
        opt(ws, el_sel, c, cb.elongation_sel, number("length"));
        opt(ws, dist, c, cb.distance_to_object, number("length"));
        opt(ws, resid, c, cb.residual_height, number("length"));
      }
      opt(ws, acc_e, c, s.acceptable_energy_exceedance, number("probability"));
      opt(ws, acc_h, c, s.acceptable_height_exceedance, number("probability"));
      text(ws, obs, c, s.observed_file);
    }
  }

  // The scenario file as read, one line per row.
  if (sc) {
    ++r;
    text(ws, r++, 0, t_.get("titles", "scenario_text"), section());
    text(ws, r++, 0, sc->file.string(), note());
    std::size_t line_no = 1, p = 0;
    const std::string& s = sc->text;
    while (p < s.size()) {
      std::size_t e = s.find('\n', p);
      if (e == std::string::npos) e = s.size();
      std::string l = s.substr(p, e - p);
      if (!l.empty() && l.back() == '\r') l.pop_back();
      num(ws, r, 0, static_cast<double>(line_no++), number("count", 2));
      text(ws, r++, 1, l);
      p = e + 1;
    }
  }
}

// ---- a barrier -------------------------------------------------------------------------

void Report::barrier(lxw_worksheet* ws, const std::string& sheet, const design::BarrierDesign& b) {
  page_setup(ws);
  width(ws, 0, 0, 34);
  width(ws, 1, 12, 14);
  text(ws, 0, 0, replace_all(t_.get("titles", "barrier"), "{name}", b.spec.name), title());
  check(worksheet_set_row(ws, 0, 24, nullptr), "worksheet_set_row");
  Row r = 2;
  auto kv_text = [&](std::string_view label, const std::string& v) {
    text(ws, r, 0, std::string(label), bold());
    text(ws, r++, 1, v);
  };
  kv_text(h("barriers", "line"), fmt::format("{} ({} m)", b.spec.line, format_number(b.chainage)));
  kv_text(t_.get("labels", "rules"),
          fmt::format("{} — {}", b.rules_name.empty() ? b.spec.rules : b.rules_name,
                      b.rules_title));
  if (!b.rules_source.empty()) {
    text(ws, r++, 1, b.rules_source, note());
  }
  text(ws, r, 0, t_.get("labels", "crossings"), bold());
  count(ws, r++, 1, b.crossings);
  text(ws, r, 0, t_.get("labels", "not_reached"), bold());
  count(ws, r++, 1, b.not_reached);
  text(ws, r, 0, t_.get("labels", "bootstrap_seed"), bold());
  if (b.bootstrap_seed <= (std::uint64_t{1} << 53))
    num(ws, r++, 1, static_cast<double>(b.bootstrap_seed), number("count"));
  else
    text(ws, r++, 1, std::to_string(b.bootstrap_seed));

  // The sample at the line, from the report's crossings (first crossing in the main direction).
  std::vector<double> speed, height, energy, rotational;
  const auto li = line_index(b.spec.line);
  const int dir = d_.scenario ? d_.scenario->scenario.profile.main_direction() : 1;
  if (li && d_.samples && *li < d_.samples->lines().size()) {
    // The whole sample the design used (first crossings in the main direction).
    const design::LineSamples& ls = d_.samples->lines()[*li];
    speed = ls.speed;
    height = ls.height;
    for (double e : ls.translational_energy) energy.push_back(e / 1000);
    for (double e : ls.rotational_energy) rotational.push_back(e / 1000);
  } else if (li) {
    std::uint64_t last = std::numeric_limits<std::uint64_t>::max();
    for (const auto& c : d_.crossings) {
      if (c.line != *li || c.direction != dir || c.trajectory == last) continue;
      last = c.trajectory;
      speed.push_back(c.speed);
      height.push_back(c.height);
      energy.push_back(c.translational_energy / 1000);
      rotational.push_back(c.rotational_energy / 1000);
    }
  }

  // Statistics: one row per statistic, one column per quantity.
  ++r;
  text(ws, r++, 0, t_.get("titles", "statistics"), section());
  struct Q {
    const design::QuantityFit* fit;
    const stats::SampleSummary* summary;
    std::string_view key, fmt;
    const std::vector<double>* sample;  // for the empirical percentiles (may be empty)
  };
  std::vector<Q> qs = {{&b.speed, &b.speed.summary, "speed", "speed", &speed},
                       {&b.height, &b.height.summary, "height", "length", &height},
                       {&b.energy, &b.energy.summary, "energy", "energy", &energy},
                       {nullptr, &b.rotational_energy, "rotational_energy", "energy", &rotational}};
  const std::vector<double> none;
  if (b.observed_speed) qs.push_back({&*b.observed_speed, &b.observed_speed->summary,
                                      "observed_speed", "speed", &none});
  if (b.observed_height) qs.push_back({&*b.observed_height, &b.observed_height->summary,
                                       "observed_height", "length", &none});
  if (b.observed_energy) qs.push_back({&*b.observed_energy, &b.observed_energy->summary,
                                       "observed_energy", "energy", &none});
  text(ws, r, 0, h("statistics", "statistic"), heading());
  for (std::size_t i = 0; i < qs.size(); ++i)
    text(ws, r, static_cast<Col>(1 + i), h("statistics", qs[i].key), heading());
  check(worksheet_set_row(ws, r++, 30, nullptr), "worksheet_set_row");
  // P50 / P95 (empirical, type 7) of the sample drawn from the report's crossings.
  const char* rows[] = {"count", "mean", "sd", "min", "max", "p50", "p95", "weibull_k",
                        "weibull_lambda", "weibull_ks_d", "weibull_ks_p", "lognormal_mu",
                        "lognormal_sigma", "lognormal_ks_d", "lognormal_ks_p"};
  for (const char* stat : rows) {
    const std::string_view s = stat;
    text(ws, r, 0, h("statistics", s), bold());
    for (std::size_t i = 0; i < qs.size(); ++i) {
      const Q& q = qs[i];
      const Col c = static_cast<Col>(1 + i);
      lxw_format* qf = number(q.fmt);
      const auto& sm = *q.summary;
      if (s == "count") count(ws, r, c, sm.count);
      else if (s == "mean") num(ws, r, c, sm.count ? sm.mean : kNaN, qf);
      else if (s == "sd") num(ws, r, c, sm.count > 1 ? sm.standard_deviation : kNaN, qf);
      else if (s == "min") num(ws, r, c, sm.count ? sm.min : kNaN, qf);
      else if (s == "max") num(ws, r, c, sm.count ? sm.max : kNaN, qf);
      else if (s == "p50" || s == "p95") {
        if (!q.sample->empty()) num(ws, r, c, stats::percentile(*q.sample, s == "p50" ? 50 : 95), qf);
      } else if (!q.fit) {
        continue;
      } else if (s == "weibull_k" && q.fit->weibull) num(ws, r, c, q.fit->weibull->shape, number("parameter"));
      else if (s == "weibull_lambda" && q.fit->weibull) num(ws, r, c, q.fit->weibull->scale, qf);
      else if (s == "weibull_ks_d" && q.fit->weibull_ks) num(ws, r, c, q.fit->weibull_ks->statistic, number("parameter"));
      else if (s == "weibull_ks_p" && q.fit->weibull_ks) num(ws, r, c, q.fit->weibull_ks->p_value_stephens, number("p_value"));
      else if (s == "lognormal_mu" && q.fit->lognormal) num(ws, r, c, q.fit->lognormal->mu, number("parameter"));
      else if (s == "lognormal_sigma" && q.fit->lognormal) num(ws, r, c, q.fit->lognormal->sigma, number("parameter"));
      else if (s == "lognormal_ks_d" && q.fit->lognormal_ks) num(ws, r, c, q.fit->lognormal_ks->statistic, number("parameter"));
      else if (s == "lognormal_ks_p" && q.fit->lognormal_ks) num(ws, r, c, q.fit->lognormal_ks->p_value_stephens, number("p_value"));
    }
    ++r;
  }
  for (const auto& q : qs)
    if (q.fit && !q.fit->error.empty())
      text(ws, r++, 0, fmt::format("{}: {}", h("statistics", q.key), q.fit->error), note());

  // Bootstrap intervals.
  ++r;
  text(ws, r++, 0, t_.get("titles", "bootstrap"), section());
  headings(ws, r++, 0, "bootstrap",
           {"quantity", "estimate", "lower", "upper", "half_width", "confidence", "resamples"});
  struct BI {
    std::string_view key, fmt;
    const std::optional<stats::BootstrapInterval>* iv;
  };
  for (const BI& bi : {BI{"v_k", "speed", &b.v_k.interval}, BI{"h_k", "length", &b.h_k.interval},
                       BI{"E_d", "energy", &b.E_d_interval}, BI{"h_i", "length", &b.h_i_interval}}) {
    text(ws, r, 0, h("bootstrap", bi.key), bold());
    if (*bi.iv) {
      const auto& iv = **bi.iv;
      num(ws, r, 1, iv.estimate, number(bi.fmt));
      num(ws, r, 2, iv.lower, number(bi.fmt));
      num(ws, r, 3, iv.upper, number(bi.fmt));
      num(ws, r, 4, iv.estimate != 0 ? iv.half_width() / std::abs(iv.estimate) : kNaN,
          number("percent"));
      num(ws, r, 5, iv.confidence, number("percent"));
      count(ws, r, 6, iv.resamples);
    } else {
      text(ws, r, 1, t_.get("labels", "none"), note());
    }
    ++r;
  }

  // Design table (Table 4.1's columns).
  ++r;
  text(ws, r++, 0, t_.get("titles", "design"), section());
  headings(ws, r++, 1, "design", {"v_d", "m_d", "E_d", "sel_req", "mel_req", "h_i", "energy_class"},
           45);
  text(ws, r, 0, b.spec.name, bold());
  num(ws, r, 1, b.v_d, number("speed"));
  num(ws, r, 2, b.m_d, number("mass"));
  num(ws, r, 3, b.E_d_kJ, number("energy"));
  num(ws, r, 4, b.SEL_req_kJ, number("energy"));
  num(ws, r, 5, b.MEL_req_kJ, number("energy"));
  num(ws, r, 6, b.h_i, number("length"));
  if (b.energy_class)
    num(ws, r, 7, b.energy_class->number, number("count"));
  else
    text(ws, r, 7, t_.get("labels", "none"));
  r += 2;

  // The factors and design quantities, with how each was obtained.
  text(ws, r++, 0, t_.get("titles", "factors"), section());
  headings(ws, r, 0, "factors", {"quantity", "value", "unit"});
  check(worksheet_merge_range(ws, r, 3, r, 8, h("factors", "how").c_str(), heading()),
        "worksheet_merge_range");
  ++r;
  // How each was obtained: the design's own words (BarrierDesign::how), else the formula.
  auto fr = [&](std::string_view key, double v, std::string_view kind, std::string_view unit,
                const std::string& formula = {}) {
    text(ws, r, 0, h("factors", key), bold());
    num(ws, r, 1, v, number(kind));
    text(ws, r, 2, std::string(unit));
    const auto it = b.how.find(std::string(key));
    text(ws, r, 3, it != b.how.end() ? it->second : formula);
    ++r;
  };
  fr("v_k_weibull", b.v_k.weibull, "speed", "m/s");
  fr("v_k_empirical", b.v_k.empirical, "speed", "m/s");
  fr("v_k", b.v_k.value, "speed", "m/s");
  fr("gamma_F", b.gamma_F.value, "factor", "", b.gamma_F.how);
  fr("v_d", b.v_d, "speed", "m/s", "v_k · γF");
  fr("density", b.design_density, "density", "kg/m³");
  fr("volume", b.design_volume, "volume", "m³");
  fr("gamma_M", b.gamma_M.value, "factor", "", b.gamma_M.how);
  fr("m_d", b.m_d, "mass", "kg", "ρ · Vol · γM");
  fr("E_d", b.E_d_kJ, "energy", "kJ", "½ m_d v_d²");
  fr("gamma_E_SEL", b.gamma_E_SEL, "factor", "");
  fr("sel_req", b.SEL_req_kJ, "energy", "kJ", "γE,SEL · E_d");
  fr("gamma_E_MEL", b.gamma_E_MEL, "factor", "");
  fr("mel_req", b.MEL_req_kJ, "energy", "kJ", "γE,MEL · E_d");
  fr("h_k_weibull", b.h_k.weibull, "length", "m");
  fr("h_k_empirical", b.h_k.empirical, "length", "m");
  fr("h_k", b.h_k.value, "length", "m");
  fr("gamma_h", b.gamma_h.value, "factor", "", b.gamma_h.how);
  fr("h_d", b.h_d, "length", "m");
  fr("free_board_diameter", b.free_board_diameter, "length", "m");
  fr("free_board", b.free_board, "length", "m");
  fr("h_i", b.h_i, "length", "m");
  fr("h_max_sim", b.h_max_sim, "length", "m");
  if (std::isfinite(b.candidate_mel_kJ)) fr("candidate_mel", b.candidate_mel_kJ, "energy", "kJ", "");
  if (std::isfinite(b.candidate_sel_kJ)) fr("candidate_sel", b.candidate_sel_kJ, "energy", "kJ", "");
  if (!b.residual_height_category.empty()) {
    text(ws, r, 0, h("factors", "residual_height_category"), bold());
    text(ws, r++, 1, b.residual_height_category);
  }

  // Exceedance (Table 4.2's columns).
  ++r;
  text(ws, r++, 0, t_.get("titles", "exceedance"), section());
  headings(ws, r++, 0, "exceedance",
           {"what", "threshold", "unit", "simulated_weibull", "simulated_empirical",
            "observed_weibull"});
  for (const auto& e : b.exceedance) {
    text(ws, r, 0, e.what, bold());
    num(ws, r, 1, e.threshold, number(e.unit == "kJ" ? "energy" : "length"));
    text(ws, r, 2, e.unit);
    num(ws, r, 3, e.simulated_weibull, number("probability"));
    num(ws, r, 4, e.simulated_empirical, number("probability"));
    if (e.observed_weibull) num(ws, r, 5, *e.observed_weibull, number("probability"));
    ++r;
  }

  // This barrier's check lines.
  if (!b.checks.empty()) {
    ++r;
    text(ws, r++, 0, t_.get("titles", "barrier_checks"), section());
    // id in A (wide), what in B.. would be cut: keep Summary's columns minus the subject.
    r = check_table(ws, r, b.checks, false);
  }
  if (!b.notes.empty()) {
    ++r;
    text(ws, r++, 0, t_.get("titles", "notes"), section());
    for (const auto& n : b.notes) text(ws, r++, 0, n, note());
  }

  // ---- charts and their data ----
  ++r;
  const Row chart_row = r;
  const Row rows_per_chart = static_cast<Row>(std::ceil(t_.chart_height / 20.0)) + 1;
  Row data_row = chart_row + 3 * rows_per_chart + 1;

  text(ws, data_row++, 0, t_.get("titles", "chart_data"), section());
  text(ws, data_row++, 0,
       replace_all(replace_all(replace_all(h("histogram", "source"), "{n}",
                                           std::to_string(speed.size())),
                               "{line}", b.spec.line),
                   "{total}", std::to_string(b.crossings)),
       note());
  // Print the tables, then the charts on a page of their own; the data block stays on the
  // sheet, out of the print area.
  check(worksheet_print_area(ws, 0, 0, data_row - 3, 12), "worksheet_print_area");
  auto& breaks = breaks_.emplace_back(std::vector<lxw_row_t>{chart_row, 0});
  check(worksheet_set_h_pagebreaks(ws, breaks.data()), "worksheet_set_h_pagebreaks");

  struct Plot {
    std::string_view key, fmt;
    const std::vector<double>* sample;
    const design::QuantityFit* fit;
  };
  const Plot plots[] = {{"speed", "speed", &speed, &b.speed},
                        {"height", "length", &height, &b.height},
                        {"energy", "energy", &energy, &b.energy}};
  for (std::size_t p = 0; p < 3; ++p) {
    const Plot& pl = plots[p];
    const auto& x = *pl.sample;
    const auto& fit = *pl.fit;
    ++data_row;
    text(ws, data_row++, 0, h("statistics", pl.key), section());
    const Row top = data_row;
    headings(ws, data_row++, 0, "histogram",
             {"bin_lower", "bin_upper", "count", "density", "outline_x", "outline_y", "curve_x",
              "weibull_pdf", "lognormal_pdf", "empirical_cdf", "weibull_cdf", "lognormal_cdf"});
    const Row r0 = data_row;
    // Curve range: the histogram's, or the fit's central 99.9 % when there is no sample.
    const Histogram hg = histogram(x, t_.histogram_bins);
    double lo = hg.lo, hi = hg.lo + hg.width * static_cast<double>(hg.counts.size());
    if (x.empty()) {
      lo = 0;
      hi = fit.weibull ? stats::quantile(*fit.weibull, 0.999)
                       : (fit.summary.count ? fit.summary.max : 1.0);
      if (!(hi > lo)) hi = lo + 1;
    }
    lxw_format* qf = number(pl.fmt);
    // Bins.
    for (std::size_t i = 0; i < hg.counts.size(); ++i) {
      const double a = hg.lo + hg.width * static_cast<double>(i);
      num(ws, r0 + static_cast<Row>(i), 0, a, qf);
      num(ws, r0 + static_cast<Row>(i), 1, a + hg.width, qf);
      count(ws, r0 + static_cast<Row>(i), 2, hg.counts[i]);
      num(ws, r0 + static_cast<Row>(i), 3, hg.density[i], number("parameter"));
    }
    // The outline of the columns: (e_i, 0), (e_i, d_i), (e_i+1, d_i), (e_i+1, 0), ...
    Row o = r0;
    for (std::size_t i = 0; i < hg.counts.size(); ++i) {
      const double a = hg.lo + hg.width * static_cast<double>(i), e = a + hg.width;
      for (auto [px, py] : {std::pair{a, 0.0}, std::pair{a, hg.density[i]},
                            std::pair{e, hg.density[i]}, std::pair{e, 0.0}}) {
        num(ws, o, 4, px, qf);
        num(ws, o++, 5, py, number("parameter"));
      }
    }
    // Curves on an even grid.
    const int n = t_.curve_points;
    std::vector<double> grid(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) grid[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (n - 1);
    const std::vector<double> ecdf =
        x.empty() ? std::vector<double>(grid.size(), kNaN) : stats::empirical_cdf(x, grid);
    for (int i = 0; i < n; ++i) {
      const Row rr = r0 + static_cast<Row>(i);
      const double g = grid[static_cast<std::size_t>(i)];
      num(ws, rr, 6, g, qf);
      if (fit.weibull) {
        num(ws, rr, 7, stats::pdf(*fit.weibull, g), number("parameter"));
        num(ws, rr, 10, stats::cdf(*fit.weibull, g), number("parameter"));
      }
      if (fit.lognormal) {
        num(ws, rr, 8, stats::pdf(*fit.lognormal, g), number("parameter"));
        num(ws, rr, 11, stats::cdf(*fit.lognormal, g), number("parameter"));
      }
      num(ws, rr, 9, ecdf[static_cast<std::size_t>(i)], number("parameter"));
    }
    data_row = std::max<Row>(o, r0 + static_cast<Row>(n)) + 1;
    (void)top;

    // The histogram chart: columns' outline, Weibull and log-normal densities.
    const std::string key(pl.key);
    lxw_chart* hc = nullptr;
    const Row rn = r0 + static_cast<Row>(n) - 1;
    if (!hg.counts.empty() || fit.weibull || fit.lognormal) {
      hc = scatter_chart(key + "_histogram", b.spec.name);
      if (!hg.counts.empty())
        xy_series(hc, sheet, r0, o - 1, 4, 5, h("histogram", "histogram"), t_.colour("histogram"),
                  1.25f);
      if (fit.weibull)
        xy_series(hc, sheet, r0, rn, 6, 7, h("histogram", "weibull_pdf"), t_.colour("weibull"),
                  2.0f);
      if (fit.lognormal)
        xy_series(hc, sheet, r0, rn, 6, 8, h("histogram", "lognormal_pdf"),
                  t_.colour("lognormal"), 1.5f, LXW_CHART_LINE_DASH_DASH);
      chart_axis_set_min(hc->x_axis, lo);
      chart_axis_set_max(hc->x_axis, hi);
      chart_axis_set_min(hc->y_axis, 0);
      chart_axis_set_num_format(hc->x_axis, keep(t_.get("formats", "general")));
      insert_chart(ws, {chart_row + static_cast<Row>(p) * rows_per_chart, 0}, hc);
    }
    // The CDF chart: empirical against fitted.
    if (!x.empty() || fit.weibull || fit.lognormal) {
      lxw_chart* cc = scatter_chart(key + "_cdf", b.spec.name);
      if (!x.empty())
        xy_series(cc, sheet, r0, rn, 6, 9, h("histogram", "empirical_cdf"),
                  t_.colour("empirical"), 2.0f);
      if (fit.weibull)
        xy_series(cc, sheet, r0, rn, 6, 10, h("histogram", "weibull_cdf"), t_.colour("weibull"),
                  1.5f);
      if (fit.lognormal)
        xy_series(cc, sheet, r0, rn, 6, 11, h("histogram", "lognormal_cdf"),
                  t_.colour("lognormal"), 1.5f, LXW_CHART_LINE_DASH_DASH);
      chart_axis_set_min(cc->x_axis, lo);
      chart_axis_set_max(cc->x_axis, hi);
      chart_axis_set_min(cc->y_axis, 0);
      chart_axis_set_max(cc->y_axis, 1);
      chart_axis_set_num_format(cc->x_axis, keep(t_.get("formats", "general")));
      // Right of the histogram: column A (34) + 3 columns of 14 ≈ 620 px at 7 px/char + padding.
      insert_chart(ws, {chart_row + static_cast<Row>(p) * rows_per_chart, 5}, cc);
    }
  }
}

// ---- Profile ---------------------------------------------------------------------------

void Report::profile(lxw_worksheet* ws, const std::string& sheet) {
  page_setup(ws);
  width(ws, 0, 7, 12);
  text(ws, 0, 0, t_.get("titles", "profile"), title());
  if (d_.quarry) {  // sections have profiles of their own, drawn on their rows' sheets
    text(ws, 2, 0, t_.get("labels", "quarry_profile"), note());
    return;
  }
  const Row chart_row = 2;
  const Row rows_for_chart = static_cast<Row>(std::ceil(1.8 * t_.chart_height / 20.0)) + 2;
  Row r = chart_row + rows_for_chart;
  text(ws, r++, 0, t_.get("titles", "chart_data"), section());
  check(worksheet_print_area(ws, 0, 0, r - 2, 12), "worksheet_print_area");
  const Row head = r;
  text(ws, head, 0, h("profile", "profile"), heading());
  text(ws, head, 2, h("profile", "paths"), heading());
  text(ws, head, 4, h("profile", "lines"), heading());
  text(ws, head, 6, h("profile", "barriers"), heading());
  for (Col c = 0; c < 8; c += 2) {
    text(ws, head + 1, c, h("profile", "x"), heading());
    text(ws, head + 1, c + 1, h("profile", "z"), heading());
  }
  const Row r0 = head + 2;
  lxw_format* xf = number("coordinate");

  lxw_chart* chart = check_ptr(workbook_add_chart(wb_, LXW_CHART_SCATTER_STRAIGHT),
                               "workbook_add_chart");
  chart_title_set_name(chart, keep(t_.get("chart.profile", "title")));
  lxw_chart_font title_font{};
  title_font.size = 12;
  chart_title_set_name_font(chart, &title_font);
  chart_axis_set_name(chart->x_axis, keep(t_.get("chart.profile", "x_axis")));
  chart_axis_set_name(chart->y_axis, keep(t_.get("chart.profile", "y_axis")));
  chart_legend_set_position(chart, LXW_CHART_LEGEND_BOTTOM);
  chart_show_blanks_as(chart, LXW_CHART_BLANKS_AS_GAP);
  lxw_chart_line grid{};
  grid.color = 0xD9D9D9;
  grid.width = 0.5f;
  chart_axis_major_gridlines_set_visible(chart->x_axis, LXW_TRUE);
  chart_axis_major_gridlines_set_line(chart->x_axis, &grid);
  chart_axis_major_gridlines_set_line(chart->y_axis, &grid);
  chart_axis_set_label_position(chart->x_axis, LXW_CHART_AXIS_LABEL_POSITION_LOW);
  chart_axis_set_label_position(chart->y_axis, LXW_CHART_AXIS_LABEL_POSITION_LOW);
  bool any = false;
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;

  // Paths first so that the profile is drawn over them.
  const Row pr = path_rows(ws, r0, d_.sample_paths, xf);
  if (pr > r0) {
    xy_series(chart, sheet, r0, pr - 2, 2, 3, h("profile", "paths"), t_.colour("paths"), 0.75f);
    any = true;
  }
  if (d_.scenario) {
    const auto& prof = d_.scenario->scenario.profile;
    const auto& v = prof.vertices();
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (const auto& p : v) {
      zmin = std::min(zmin, p.z);
      zmax = std::max(zmax, p.z);
    }
    // Lines drawn at least 6 % of the profile's height, so that they show on a tall slope.
    const double line_height =
        std::max(t_.profile_line_height, std::isfinite(zmax - zmin) ? 0.06 * (zmax - zmin) : 0.0);
    Row vr = r0;
    for (const auto& p : v) {
      num(ws, vr, 0, p.x, xf);
      num(ws, vr++, 1, p.z, xf);
      xmin = std::min(xmin, p.x);
      xmax = std::max(xmax, p.x);
    }
    if (!v.empty()) {
      xy_series(chart, sheet, r0, vr - 1, 0, 1, h("profile", "profile"), t_.colour("profile"),
                2.25f);
      any = true;
    }
    // Observation lines: vertical segments from the ground up.
    Row lr = r0;
    std::vector<std::string> line_names;  // per point: the top of each line is named
    for (const auto& l : d_.scenario->scenario.lines) {
      const auto g = prof.top_ground(l.x);
      if (!g) continue;
      num(ws, lr, 4, l.x, xf);
      num(ws, lr++, 5, g->z, xf);
      num(ws, lr, 4, l.x, xf);
      num(ws, lr++, 5, g->z + line_height, xf);
      ++lr;
      line_names.insert(line_names.end(), {"", l.name, ""});
    }
    if (lr > r0) {
      lxw_chart_series* ls = xy_series(chart, sheet, r0, lr - 2, 4, 5, h("profile", "lines"),
                                       t_.colour("lines"), 1.25f, LXW_CHART_LINE_DASH_DASH);
      line_names.pop_back();  // the range ends before the last gap row
      point_labels(ls, line_names);
    }
    // Barriers: the candidate's height when known, else h_i.
    Row br = r0;
    std::vector<std::string> barrier_names;
    for (const auto& b : d_.barriers) {
      const auto g = prof.top_ground(b.chainage);
      if (!g) continue;
      const double hb = b.spec.candidate && b.spec.candidate->height ? *b.spec.candidate->height
                                                                     : b.h_i;
      if (!std::isfinite(hb)) continue;
      num(ws, br, 6, b.chainage, xf);
      num(ws, br++, 7, g->z, xf);
      num(ws, br, 6, b.chainage, xf);
      num(ws, br++, 7, g->z + hb, xf);
      ++br;
      barrier_names.insert(barrier_names.end(), {"", b.spec.name, ""});
    }
    if (br > r0) {
      lxw_chart_series* s = xy_series(chart, sheet, r0, br - 2, 6, 7, h("profile", "barriers"),
                                      t_.colour("barriers"), 3.5f);
      // Markers at the foot and the top, so that a barrier shows beside a tall slope.
      markers(s, LXW_CHART_MARKER_DIAMOND, 7, t_.colour("barriers"), true);
      barrier_names.pop_back();
      point_labels(s, barrier_names);
    }
  }
  if (any) {
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    if (d_.scenario)
      for (const auto& p : d_.scenario->scenario.profile.vertices()) {
        zmin = std::min(zmin, p.z);
        zmax = std::max(zmax, p.z);
      }
    equal_scale(chart, xmin, xmax, zmin, zmax, 1.6, 1.6);
    insert_chart(ws, {chart_row, 0}, chart, 1.6, 1.6);
  }
}

// ---- a quarry row (design-checks.md §2) ------------------------------------------------

void Report::distance(lxw_worksheet* ws, Row r, Col c, double v, lxw_format* f) {
  if (std::isinf(v) && v > 0) {
    lxw_format* f2 = cached("centred_wrap", [](lxw_format* g) {
      format_set_align(g, LXW_ALIGN_CENTER);
      format_set_align(g, LXW_ALIGN_VERTICAL_TOP);
      format_set_shrink(g);  // words in a number column: fit the column, never spill over
    });
    text(ws, r, c, t_.get("labels", "beyond_profile"), f2);
  } else
    num(ws, r, c, v, f);
}

Row Report::quarry_summary(lxw_worksheet* ws, Row r) {
  const design::QuarryDesign& q = *d_.quarry;
  ++r;
  text(ws, r++, 0, t_.get("titles", "quarry_summary"), section());
  headings(ws, r++, 0, "quarry_summary",
           {"row", "source", "height", "thrown", "rd_gov", "id_gov", "rd50_h", "rd95_h",
            "rdmax_h", "id50_h", "id95_h", "idmax_h"},
           45);
  lxw_format *lf = number("length", 1), *hf = number("factor", 1);
  for (const auto& row : q.rows) {
    text(ws, r, 0, row.name, wrap());
    text(ws, r, 1, t_.get("labels", "calculated"), centred());
    num(ws, r, 2, row.height, lf);
    num(ws, r, 3, static_cast<double>(row.thrown), number("count", 1));
    distance(ws, r, 4, row.rd_gov.value_h * row.height, lf);
    distance(ws, r, 5, row.id_gov.value_h * row.height, lf);
    distance(ws, r, 6, row.rd.p50_h, hf);
    distance(ws, r, 7, row.rd.p95_h, hf);
    distance(ws, r, 8, row.rd.max_h, hf);
    distance(ws, r, 9, row.id.p50_h, hf);
    distance(ws, r, 10, row.id.p95_h, hf);
    distance(ws, r, 11, row.id.max_h, hf);
    ++r;
    if (row.observed_rd || row.observed_id) {
      text(ws, r, 0, row.name, wrap());
      text(ws, r, 1, t_.get("labels", "observed"), centred());
      if (row.observed_rd) {
        num(ws, r, 6, row.observed_rd->p50_h, hf);
        num(ws, r, 7, row.observed_rd->p95_h, hf);
        num(ws, r, 8, row.observed_rd->max_h, hf);
      }
      if (row.observed_id) {
        num(ws, r, 9, row.observed_id->p50_h, hf);
        num(ws, r, 10, row.observed_id->p95_h, hf);
        num(ws, r, 11, row.observed_id->max_h, hf);
      }
      ++r;
    }
  }
  // The thesis's last rows: means over the rows of the per-row ratios.
  const auto& a = q.average;
  auto avg = [&](const std::string& source, double rd50, double rd95, double rdmax, double id50,
                 double id95, double idmax) {
    const std::string& label = t_.get("titles", "quarry_average");
    lxw_format* f = cached("bold_wrap", [](lxw_format* g) {
      format_set_bold(g);
      format_set_text_wrap(g);
      format_set_align(g, LXW_ALIGN_VERTICAL_TOP);
    });
    text(ws, r, 0, label, f);
    fit_row(ws, r, {{&label, 16}});
    text(ws, r, 1, source, centred_bold());
    distance(ws, r, 6, rd50, hf);
    distance(ws, r, 7, rd95, hf);
    distance(ws, r, 8, rdmax, hf);
    distance(ws, r, 9, id50, hf);
    distance(ws, r, 10, id95, hf);
    distance(ws, r, 11, idmax, hf);
    ++r;
  };
  if (a.rows > 0)
    avg(t_.get("labels", "calculated"), a.rd50_h, a.rd95_h, a.rdmax_h, a.id50_h, a.id95_h,
        a.idmax_h);
  if (a.observed_rows > 0)
    avg(t_.get("labels", "observed"), a.obs_rd50_h, a.obs_rd95_h, a.obs_rdmax_h, a.obs_id50_h,
        a.obs_id95_h, a.obs_idmax_h);
  return r;
}

void Report::quarry(lxw_worksheet* ws, const std::string& sheet, std::size_t ri) {
  const design::QuarryDesign& q = *d_.quarry;
  const design::QuarryRow& row = q.rows[ri];
  std::vector<const design::QuarrySectionResult*> secs;
  for (std::size_t i : row.sections)
    if (i < q.sections.size()) secs.push_back(&q.sections[i]);
  page_setup(ws);
  width(ws, 0, 0, 30);
  width(ws, 1, 13, 14);  // as a barrier sheet: the check table's merged columns fit its text
  text(ws, 0, 0, replace_all(t_.get("titles", "quarry"), "{name}", row.name), title());
  check(worksheet_set_row(ws, 0, 24, nullptr), "worksheet_set_row");
  Row r = 2;
  auto label = [&](const std::string& l) { text(ws, r, 0, l, bold()); };
  label(t_.get("labels", "rules"));
  text(ws, r++, 1,
       secs.empty() || secs[0]->rules_title.empty()
           ? row.rules
           : fmt::format("{} — {}", row.rules, secs[0]->rules_title));
  if (!secs.empty() && !secs[0]->rules_source.empty()) text(ws, r++, 1, secs[0]->rules_source, note());
  if (row.pooled) {
    std::string names;
    for (const auto* s : secs) names += (names.empty() ? "" : ", ") + s->spec.name;
    label(t_.get("labels", "pooled"));
    text(ws, r++, 1, names);
  }
  for (const auto* s : secs)
    if (!s->spec.observed_source.empty()) {
      label(t_.get("labels", "observed_source"));
      text(ws, r++, 1, row.pooled ? fmt::format("{}: {}", s->spec.name, s->spec.observed_source)
                                  : s->spec.observed_source);
    }
  lxw_format *xf = number("coordinate"), *lf = number("length"), *hf = number("factor"),
             *pf = number("parameter"), *af = number("angle");

  // Geometry: crest, toe, H (given or found).
  ++r;
  text(ws, r++, 0, t_.get("titles", "quarry_geometry"), section());
  headings(ws, r++, 0, "quarry_geometry",
           {"section", "crest_x", "crest_z", "crest_origin", "toe_x", "toe_z", "toe_origin",
            "height", "height_derived", "height_origin", "floor_angle", "floor_length", "seed"},
           45);
  for (const auto* s : secs) {
    const auto& g = s->geometry;
    if (const auto* v = section_view(s->spec.name)) count(ws, r, 12, v->seed);
    text(ws, r, 0, s->spec.name, wrap());
    num(ws, r, 1, g.crest.x, xf);
    num(ws, r, 2, g.crest.z, xf);
    text(ws, r, 3, std::string(design::to_string(g.crest_origin)), centred());
    num(ws, r, 4, g.toe.x, xf);
    num(ws, r, 5, g.toe.z, xf);
    text(ws, r, 6, std::string(design::to_string(g.toe_origin)), centred());
    num(ws, r, 7, g.height, lf);
    num(ws, r, 8, g.height_derived, lf);
    text(ws, r, 9, std::string(design::to_string(g.height_origin)), centred());
    num(ws, r, 10, g.floor_angle_deg, af);
    num(ws, r++, 11, g.floor_length, lf);
  }

  // Counts.
  ++r;
  text(ws, r++, 0, t_.get("titles", "quarry_counts"), section());
  headings(ws, r++, 0, "quarry_counts",
           {"section", "thrown", "reached_floor", "not_reached_floor", "above_toe",
            "left_profile", "left_upslope", "abnormal"},
           45);
  auto counts = [&](const std::string& name, std::uint64_t thrown, std::uint64_t reached,
                    std::uint64_t not_reached, std::uint64_t above, std::uint64_t left,
                    std::uint64_t upslope, std::uint64_t abnormal, bool total) {
    text(ws, r, 0, name, total ? bold() : wrap());
    Col c = 1;
    for (std::uint64_t v : {thrown, reached, not_reached, above, left, upslope, abnormal})
      count(ws, r, c++, v);
    ++r;
  };
  for (const auto* s : secs) {
    const auto& d = s->distances;
    counts(s->spec.name, d.thrown, d.reached_floor, d.not_reached_floor, d.above_toe,
           d.left_profile, d.left_upslope, d.abnormal, false);
  }
  if (secs.size() > 1)
    counts(t_.get("labels", "total"), row.thrown, row.reached_floor, row.not_reached_floor,
           row.above_toe, row.left_profile, row.left_upslope, row.abnormal, true);

  // Tables 6.2 / 6.3: calculated beside observed.
  ++r;
  text(ws, r++, 0, t_.get("titles", "quarry_statistics"), section());
  headings(ws, r++, 0, "quarry_statistics",
           {"distance", "source", "count", "zeros", "censored", "p50", "p95", "p99", "max",
            "p50_h", "p95_h", "p99_h", "max_h"},
           30);
  struct Dist {
    std::string_view key;
    const design::DistanceStatistics* st;
    const std::optional<design::ObservedComparison>* obs;
  };
  const Dist dists[] = {{"rd", &row.rd, &row.observed_rd}, {"id", &row.id, &row.observed_id}};
  auto calculated = [&](std::string_view key, const std::string& source,
                        const design::DistanceStatistics& st) {
    text(ws, r, 0, t_.get("labels", key), bold());
    text(ws, r, 1, source, centred());
    count(ws, r, 2, st.count);
    count(ws, r, 3, st.zeros);
    count(ws, r, 4, st.censored);
    Col c = 5;
    for (double v : {st.p50, st.p95, st.p99, st.max}) distance(ws, r, c++, v, lf);
    for (double v : {st.p50_h, st.p95_h, st.p99_h, st.max_h}) distance(ws, r, c++, v, hf);
    ++r;
  };
  for (const auto& dd : dists) {
    calculated(dd.key, t_.get("labels", "calculated"), *dd.st);
    if (*dd.obs) {
      const auto& o = **dd.obs;
      text(ws, r, 0, t_.get("labels", dd.key), bold());
      text(ws, r, 1, t_.get("labels", "observed"), centred());
      if (o.count > 0) count(ws, r, 2, o.count);
      num(ws, r, 5, o.p50, lf);
      num(ws, r, 6, o.p95, lf);
      num(ws, r, 8, o.max, lf);
      num(ws, r, 9, o.p50_h, hf);
      num(ws, r, 10, o.p95_h, hf);
      num(ws, r, 12, o.max_h, hf);
      ++r;
    }
    // A group's sections on their own (design-checks.md §2: per section and pooled), the
    // section's name in the source column.
    if (secs.size() > 1)
      for (const design::QuarrySectionResult* sec : secs)
        calculated(dd.key, sec->spec.name, dd.key == "rd" ? sec->rd : sec->id);
  }

  // The log-normal mixture fits and the comparison with the observed values.
  ++r;
  text(ws, r++, 0, t_.get("titles", "quarry_fits"), section());
  headings(ws, r++, 0, "quarry_fits",
           {"distance", "zero_share", "mu", "sigma", "observed", "censored", "ks_d", "ks_p",
            "ks_below", "cdf_rmse", "observed_ks_d", "observed_ks_p", "fit_error"},
           45);
  for (const auto& dd : dists) {
    const auto& st = *dd.st;
    text(ws, r, 0, t_.get("labels", dd.key), bold());
    if (st.fit) {
      num(ws, r, 1, st.fit->zero_share, number("percent"));
      num(ws, r, 2, st.fit->positive.mu, pf);
      num(ws, r, 3, st.fit->positive.sigma, pf);
      count(ws, r, 4, st.fit->observed);
      count(ws, r, 5, st.fit->censored);
    }
    if (st.ks) {
      num(ws, r, 6, st.ks->statistic, pf);
      num(ws, r, 7, st.ks->p_value, number("p_value"));
      num(ws, r, 8, st.ks->below, hf);
    }
    if (*dd.obs) {
      const auto& o = **dd.obs;
      if (o.cdf_rmse) num(ws, r, 9, *o.cdf_rmse, pf);
      if (o.ks) {
        num(ws, r, 10, o.ks->statistic, pf);
        num(ws, r, 11, o.ks->p_value, number("p_value"));
      }
    }
    text(ws, r, 12, st.fit_error, wrap());
    ++r;
  }

  // Distances at the asked probabilities of exceedance.
  if (!row.exceedance.empty()) {
    ++r;
    text(ws, r++, 0, t_.get("titles", "quarry_exceedance"), section());
    headings(ws, r++, 0, "quarry_exceedance",
             {"probability", "rd_fit_h", "rd_empirical_h", "rd_fit", "rd_empirical", "id_fit_h",
              "id_empirical_h", "id_fit", "id_empirical"},
             30);
    for (const auto& e : row.exceedance) {
      num(ws, r, 0, e.probability, number("probability", 1));
      distance(ws, r, 1, e.rd_fit_h, hf);
      distance(ws, r, 2, e.rd_empirical_h, hf);
      distance(ws, r, 3, e.rd_fit, lf);
      distance(ws, r, 4, e.rd_empirical, lf);
      distance(ws, r, 5, e.id_fit_h, hf);
      distance(ws, r, 6, e.id_empirical_h, hf);
      distance(ws, r, 7, e.id_fit, lf);
      distance(ws, r, 8, e.id_empirical, lf);
      ++r;
    }
    // Say when the fitted columns should not be read as distances: a fit the KS doubts (its
    // fit.* line WARNs), or a distance past the end of the floor that was simulated.
    for (const auto& [what, id, st] : {std::tuple{"RD", "fit.RD", &row.rd}, std::tuple{"ID", "fit.ID", &row.id}}) {
      const bool doubtful = std::any_of(d_.quarry->checks.begin(), d_.quarry->checks.end(),
                                        [&](const design::CheckLine& l) {
                                          return l.subject == row.name && l.id == id &&
                                                 l.status == design::CheckStatus::warn;
                                        });
      if (doubtful && st->ks)
        text(ws, r++, 0,
             replace_all(replace_all(t_.get("labels", "fit_doubtful"), "{what}", what), "{p}",
                         fmt::format("{:.3g}", st->ks->p_value)),
             note());
    }
    double floor_end = 0;
    for (const auto* sec : secs) floor_end = std::max(floor_end, sec->geometry.floor_length);
    if (std::any_of(row.exceedance.begin(), row.exceedance.end(), [&](const auto& e) {
          return e.rd_fit > floor_end || e.id_fit > floor_end;
        }))
      text(ws, r++, 0,
           replace_all(t_.get("labels", "fit_past_floor"), "{floor}", fmt::format("{:.1f}", floor_end)),
           note());
  }

  // Governing distances.
  ++r;
  text(ws, r++, 0, t_.get("titles", "quarry_governing"), section());
  headings(ws, r, 0, "quarry_governing", {"quantity", "value_h", "value"});
  check(worksheet_merge_range(ws, r, 3, r, 9, h("quarry_governing", "how").c_str(), heading()),
        "worksheet_merge_range");
  ++r;
  auto gov = [&](std::string_view key, double vh, const std::string& how) {
    text(ws, r, 0, h("quarry_governing", key), bold());
    distance(ws, r, 1, vh, hf);
    distance(ws, r, 2, vh * row.height, lf);
    text(ws, r++, 3, how, indented());
  };
  gov("rd_gov", row.rd_gov.value_h, row.rd_gov.how);
  gov("id_gov", row.id_gov.value_h, row.id_gov.how);
  if (row.rd_interval) {
    const auto& iv = *row.rd_interval;
    const std::string how = fmt::format("{:.0f} % bootstrap interval, {} resamples (estimate {:.3f} H)",
                                        100 * iv.confidence, iv.resamples, iv.estimate);
    gov("rd_lower", iv.lower, how);
    gov("rd_upper", iv.upper, how);
  }

  // Zones per section.
  ++r;
  text(ws, r++, 0, t_.get("titles", "quarry_zones"), section());
  headings(ws, r, 0, "quarry_zones",
           {"section", "danger_zone", "first_impact_zone", "bench_width", "retention",
            "ritchie_width"},
           60);
  check(worksheet_merge_range(ws, r, 6, r, 9, h("quarry_zones", "work_areas").c_str(), heading()),
        "worksheet_merge_range");
  ++r;
  for (const auto* s : secs) {
    text(ws, r, 0, s->spec.name, wrap());
    distance(ws, r, 1, s->danger_zone, lf);
    distance(ws, r, 2, s->first_impact_zone, lf);
    opt(ws, r, 3, s->spec.bench_width, lf);
    opt(ws, r, 4, s->bench_retention, number("percent"));
    opt(ws, r, 5, s->ritchie_width, lf);
    std::string areas;
    for (const auto& w : s->spec.work_areas)
      areas += fmt::format("{}{} {} m", areas.empty() ? "" : "; ", w.name, format_number(w.distance));
    text(ws, r, 6, keep(areas), wrap());
    check(worksheet_merge_range(ws, r, 6, r, 9, areas.c_str(), wrap()), "worksheet_merge_range");
    fit_row(ws, r, {{&strings_.back(), 52}, {&s->spec.name, 30}});
    ++r;
  }

  // This row's check lines.
  std::vector<design::CheckLine> lines;
  for (const auto& l : q.checks) {
    bool mine = l.subject == row.name;
    for (const auto* s : secs) mine = mine || l.subject == s->spec.name;
    if (mine) lines.push_back(l);
  }
  if (!lines.empty()) {
    ++r;
    text(ws, r++, 0, t_.get("titles", "barrier_checks"), section());
    r = check_table(ws, r, lines, false);
  }

  // ---- charts and their data: the sections first, then RD and ID ----
  ++r;
  const Row chart_row = r;
  const Row rows_per_chart = static_cast<Row>(std::ceil(t_.chart_height / 20.0)) + 1;
  const Row rows_per_section = static_cast<Row>(std::ceil(1.4 * t_.chart_height / 20.0)) + 1;
  const Row n_sections = static_cast<Row>(secs.size());
  Row data_row = chart_row + n_sections * rows_per_section + 2 * rows_per_chart + 1;
  text(ws, data_row++, 0, t_.get("titles", "chart_data"), section());
  check(worksheet_print_area(ws, 0, 0, data_row - 3, 13), "worksheet_print_area");
  auto& breaks = breaks_.emplace_back(std::vector<lxw_row_t>{chart_row, 0});
  check(worksheet_set_h_pagebreaks(ws, breaks.data()), "worksheet_set_h_pagebreaks");

  Row at = chart_row;
  for (const auto* s : secs) {
    data_row = quarry_section_chart(ws, sheet, data_row, {at, 0}, *s);
    at += rows_per_section;
  }
  data_row = quarry_distance_charts(ws, sheet, data_row, {at, 0}, 6, "rd", row);
  at += rows_per_chart;
  quarry_distance_charts(ws, sheet, data_row, {at, 0}, 6, "id", row);
}

Row Report::quarry_distance_charts(lxw_worksheet* ws, const std::string& sheet, Row data_row,
                                   Cell at, Col cdf_col, std::string_view which,
                                   const design::QuarryRow& row) {
  const bool rd = which == "rd";
  const design::DistanceSample& sample = rd ? row.rd_sample : row.id_sample;
  const design::DistanceStatistics& st = rd ? row.rd : row.id;
  const auto& obs = rd ? row.observed_rd : row.observed_id;
  const std::vector<double>& x = sample.normalized;
  const std::string key(which);

  ++data_row;
  text(ws, data_row++, 0, t_.get("labels", which), section());
  text(ws, data_row++, 0,
       replace_all(replace_all(replace_all(h("quarry_chart", "source"), "{n}",
                                           std::to_string(x.size())),
                               "{zeros}", std::to_string(st.zeros)),
                   "{censored}", std::to_string(st.censored)),
       note());
  headings(ws, data_row++, 0, "quarry_chart",
           {"outline_x", "outline_y", "curve_x", "fitted_pdf", "empirical_cdf", "fitted_cdf",
            "observed_x", "observed_cdf"});
  const Row r0 = data_row;
  lxw_format *hf = number("factor"), *pf = number("parameter");

  // The columns: the positive finite values, density over every value (zeros and censored
  // count in n), so that they compare with (1 − p0) f_logn.
  double hi = 0;
  std::size_t positive = 0;
  for (double v : x)
    if (std::isfinite(v) && v > 0) {
      hi = std::max(hi, v);
      ++positive;
    }
  if (obs)
    for (double b : obs->breaks_h)
      if (std::isfinite(b)) hi = std::max(hi, b);
  if (!(hi > 0)) hi = 1;
  const int bins = t_.histogram_bins;
  const double w = hi / bins;
  std::vector<double> density(static_cast<std::size_t>(bins), 0.0);
  for (double v : x)
    if (std::isfinite(v) && v > 0) {
      const auto b = std::clamp(static_cast<long>(std::floor(v / w)), 0L, static_cast<long>(bins) - 1);
      density[static_cast<std::size_t>(b)] += 1;
    }
  double dmax = 0;
  for (double& d : density) {
    d /= static_cast<double>(x.size()) * w;
    dmax = std::max(dmax, d);
  }
  Row o = r0;
  if (positive > 0)
    for (int i = 0; i < bins; ++i) {
      const double a = w * i, e = a + w, d = density[static_cast<std::size_t>(i)];
      for (auto [px, py] : {std::pair{a, 0.0}, std::pair{a, d}, std::pair{e, d}, std::pair{e, 0.0}}) {
        num(ws, o, 0, px, hf);
        num(ws, o++, 1, py, pf);
      }
    }
  // Curves on an even grid from 0.
  const int n = t_.curve_points;
  std::vector<double> grid(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) grid[static_cast<std::size_t>(i)] = hi * i / (n - 1);
  const std::vector<double> ecdf =
      x.empty() ? std::vector<double>(grid.size(), kNaN) : stats::empirical_cdf(x, grid);
  double cmax = 0;
  for (int i = 0; i < n; ++i) {
    const Row rr = r0 + static_cast<Row>(i);
    const double g = grid[static_cast<std::size_t>(i)];
    num(ws, rr, 2, g, hf);
    if (st.fit) {
      const double f = (1 - st.fit->zero_share) * stats::pdf(st.fit->positive, g);
      num(ws, rr, 3, f, pf);
      if (std::isfinite(f)) cmax = std::max(cmax, f);
      num(ws, rr, 5, 1 - stats::exceedance_probability(*st.fit, g), pf);
    }
    num(ws, rr, 4, ecdf[static_cast<std::size_t>(i)], pf);
  }
  const Row rn = r0 + static_cast<Row>(n) - 1;
  // Observed points: the break points of Eq 4.1 and the observed CDF there.
  Row ob = r0;
  if (obs)
    for (std::size_t i = 0; i < obs->breaks_h.size() && i < obs->observed_cdf.size(); ++i) {
      if (!std::isfinite(obs->breaks_h[i])) continue;
      num(ws, ob, 6, obs->breaks_h[i], hf);
      num(ws, ob++, 7, obs->observed_cdf[i], pf);
    }
  data_row = std::max({o, rn + 1, ob}) + 1;

  auto axes = [&](lxw_chart* c) {
    chart_axis_set_min(c->x_axis, 0);
    chart_axis_set_max(c->x_axis, hi);
    chart_axis_set_min(c->y_axis, 0);
    chart_axis_set_num_format(c->x_axis, keep(t_.get("formats", "general")));
  };
  // Histogram with the fitted density.
  if (positive > 0 || st.fit) {
    lxw_chart* hc = scatter_chart(key + "_histogram", row.name);
    if (positive > 0)
      xy_series(hc, sheet, r0, o - 1, 0, 1, h("quarry_chart", "histogram"), t_.colour("histogram"),
                1.25f);
    if (st.fit)
      xy_series(hc, sheet, r0, rn, 2, 3, h("quarry_chart", "fitted_pdf"), t_.colour("lognormal"),
                2.0f);
    axes(hc);
    // A density spike at 0 must not flatten the columns.
    if (dmax > 0 && cmax > 2.5 * dmax) chart_axis_set_max(hc->y_axis, 1.5 * dmax);
    insert_chart(ws, at, hc);
  }
  // Empirical against fitted CDF, with the observed points.
  if (!x.empty() || st.fit) {
    lxw_chart* cc = scatter_chart(key + "_cdf", row.name);
    if (!x.empty())
      xy_series(cc, sheet, r0, rn, 2, 4, h("quarry_chart", "empirical_cdf"),
                t_.colour("empirical"), 2.0f);
    if (st.fit)
      xy_series(cc, sheet, r0, rn, 2, 5, h("quarry_chart", "fitted_cdf"), t_.colour("lognormal"),
                1.5f, LXW_CHART_LINE_DASH_DASH);
    if (ob > r0) {
      lxw_chart_series* s = xy_series(cc, sheet, r0, ob - 1, 6, 7, h("quarry_chart", "observed_cdf"),
                                      t_.colour("observed"), 1.0f);
      markers(s, LXW_CHART_MARKER_CIRCLE, 5, t_.colour("observed"), false);
    }
    axes(cc);
    chart_axis_set_max(cc->y_axis, 1);
    insert_chart(ws, {at.row, cdf_col}, cc);
  }
  return data_row;
}

Row Report::quarry_section_chart(lxw_worksheet* ws, const std::string& sheet, Row data_row,
                                 Cell at, const design::QuarrySectionResult& s) {
  const ReportData::QuarrySectionView* view = section_view(s.spec.name);
  if (!view || !view->profile || view->profile->vertices().empty()) return data_row;
  const geometry::Profile& prof = *view->profile;
  const auto& g = s.geometry;

  ++data_row;
  text(ws, data_row++, 0, s.spec.name, section());
  const Row head = data_row;
  std::size_t k = 0;
  for (const char* key : {"profile", "paths", "toe", "danger_zone", "first_impact_zone", "work_areas"}) {
    text(ws, head, static_cast<Col>(2 * k), h("quarry_chart", key), heading());
    text(ws, head + 1, static_cast<Col>(2 * k), h("quarry_chart", "x"), heading());
    text(ws, head + 1, static_cast<Col>(2 * k + 1), h("quarry_chart", "z"), heading());
    ++k;
  }
  const Row r0 = head + 2;
  lxw_format* xf = number("coordinate");

  lxw_chart* chart = scatter_chart("quarry_section", s.spec.name);
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin, xmin = zmin, xmax = -zmin;
  for (const auto& p : prof.vertices()) {
    zmin = std::min(zmin, p.z);
    zmax = std::max(zmax, p.z);
    xmin = std::min(xmin, p.x);
    xmax = std::max(xmax, p.x);
  }
  Row last = r0;
  // Paths first, under the profile.
  const Row pr = path_rows(ws, r0, view->paths, xf);
  if (pr > r0)
    xy_series(chart, sheet, r0, pr - 2, 2, 3, h("quarry_chart", "paths"), t_.colour("paths"), 0.75f);
  Row vr = r0;
  for (const auto& p : prof.vertices()) {
    num(ws, vr, 0, p.x, xf);
    num(ws, vr++, 1, p.z, xf);
  }
  xy_series(chart, sheet, r0, vr - 1, 0, 1, h("quarry_chart", "profile"), t_.colour("profile"), 2.25f);
  last = std::max({last, pr, vr});

  // Vertical marks on the ground: the toe, ID_gov and RD_gov.
  const double lh = std::max(t_.profile_line_height, 0.25 * g.height);
  auto ground = [&](double x) {
    const auto gp = prof.top_ground(x);
    return gp ? gp->z : g.toe.z;
  };
  auto mark = [&](Col c, double x, std::string_view key, std::uint32_t colour, float width,
                  std::uint8_t dash) {
    if (!std::isfinite(x)) return;
    const double z = ground(x);
    num(ws, r0, c, x, xf);
    num(ws, r0, c + 1, z, xf);
    num(ws, r0 + 1, c, x, xf);
    num(ws, r0 + 1, c + 1, z + lh, xf);
    xy_series(chart, sheet, r0, r0 + 1, c, c + 1, h("quarry_chart", key), colour, width, dash);
    last = std::max(last, r0 + 2);
  };
  mark(4, g.toe.x, "toe", t_.colour("toe"), 1.25f, LXW_CHART_LINE_DASH_DASH);
  mark(6, g.toe.x + g.direction * s.danger_zone, "danger_zone", t_.colour("danger_zone"), 2.5f,
       LXW_CHART_LINE_DASH_SOLID);
  mark(8, g.toe.x + g.direction * s.first_impact_zone, "first_impact_zone",
       t_.colour("first_impact_zone"), 2.0f, LXW_CHART_LINE_DASH_SOLID);
  // Work areas: points on the floor.
  Row wr = r0;
  for (const auto& w : s.spec.work_areas) {
    const double x = g.toe.x + g.direction * w.distance;
    num(ws, wr, 10, x, xf);
    num(ws, wr++, 11, ground(x), xf);
  }
  if (wr > r0) {
    lxw_chart_series* sr = xy_series(chart, sheet, r0, wr - 1, 10, 11, h("quarry_chart", "work_areas"),
                                     t_.colour("work_areas"), 1.0f);
    markers(sr, LXW_CHART_MARKER_TRIANGLE, 9, t_.colour("work_areas"), false);
    std::vector<std::string> names;
    for (const auto& w : s.spec.work_areas) names.push_back(w.name);
    point_labels(sr, names);  // two work areas are two like triangles otherwise
    last = std::max(last, wr);
  }
  equal_scale(chart, xmin, xmax, zmin, zmax, 2.0, 1.4);
  chart_axis_set_num_format(chart->x_axis, keep(t_.get("formats", "general")));
  insert_chart(ws, at, chart, 2.0, 1.4);
  return last + 1;
}

// ---- data sheets -----------------------------------------------------------------------

Row Report::cap_note(lxw_worksheet* ws, Row r, std::size_t shown, std::uint64_t total,
                     const char* csv) {
  const std::string key = shown < total ? "capped" : "complete";
  std::string s = replace_all(t_.get("titles", key), "{shown}", std::to_string(shown));
  s = replace_all(replace_all(s, "{total}", std::to_string(total)), "{file}", csv);
  s = replace_all(s, "{printed}", std::to_string(std::min<std::size_t>(shown, t_.print_rows)));
  text(ws, r++, 0, s, note());
  return r;
}

void Report::trajectories(lxw_worksheet* ws) {
  page_setup(ws);
  // A quarry run leads with the section of each row; its names come from that section.
  const bool by_section = !d_.trajectory_sections.empty();
  const Col c0 = by_section ? 1 : 0;
  widths(ws, 0, 17 + c0, 11,
         {{0, by_section ? 16 : 11}, {1 + c0, 20}, {2 + c0, 12}, {10 + c0, 14}});
  text(ws, 0, 0, t_.get("titles", "trajectories"), title());
  const std::size_t shown = std::min(d_.trajectories.size(), t_.trajectory_rows);
  const std::uint64_t total = std::max<std::uint64_t>(d_.total_trajectories, d_.trajectories.size());
  Row r = cap_note(ws, 1, shown, total, "trajectories.csv");
  const Row head = r;
  if (by_section) headings(ws, r, 0, "trajectories", {"section"}, 45);
  headings(ws, r++, c0, "trajectories",
           {"trajectory", "source", "block", "throw", "mass", "start_x", "start_z", "stop_x",
            "stop_z", "runout", "stop_reason", "duration", "impacts", "first_impact_x",
            "first_impact_z", "max_jump_height", "max_speed", "max_energy"},
           45);
  worksheet_freeze_panes(ws, r, 1 + c0);
  check(worksheet_repeat_rows(ws, head, head), "worksheet_repeat_rows");
  lxw_format *cf = number("count"), *xf = number("coordinate"), *mf = number("mass"),
             *lf = number("length"), *tf = number("time"), *sf = number("speed"),
             *ef = number("energy");
  for (std::size_t i = 0; i < shown; ++i, ++r) {
    const auto& t = d_.trajectories[i];
    const DataRow row = data_row(ws, r, d_.trajectory_sections, i);
    const sim::Scenario* s = row.scenario;
    row.num(0, static_cast<double>(t.trajectory), cf);
    if (s && t.source < s->sources.size()) row.text(1, s->sources[t.source].name);
    else row.num(1, t.source, cf);
    if (s && t.block < s->blocks.size()) row.text(2, s->blocks[t.block].id);
    else row.num(2, t.block, cf);
    row.num(3, t.throw_index, cf);
    row.num(4, t.mass, mf);
    row.num(5, t.start.x, xf);
    row.num(6, t.start.z, xf);
    row.num(7, t.stop.x, xf);
    row.num(8, t.stop.z, xf);
    row.num(9, t.runout(), lf);
    row.text(10, std::string(sim::to_string(t.stop_reason)), centred());
    row.num(11, t.duration, tf);
    row.num(12, t.impacts, cf);
    if (t.has_first_impact) {
      row.num(13, t.first_impact.x, xf);
      row.num(14, t.first_impact.z, xf);
    }
    row.num(15, t.max_jump_height, lf);
    row.num(16, t.max_speed, sf);
    row.num(17, t.max_energy / 1000, ef);
  }
  const Row last = static_cast<Row>(std::min<std::size_t>(head + t_.print_rows, r > 0 ? r - 1 : 0));
  check(worksheet_print_area(ws, 0, 0, std::max(last, head), 17 + c0), "worksheet_print_area");
}

void Report::crossings(lxw_worksheet* ws) {
  page_setup(ws);
  const bool by_section = !d_.crossing_sections.empty();
  const Col c0 = by_section ? 1 : 0;
  widths(ws, 0, 14 + c0, 11, {{0, by_section ? 16 : 11}, {1 + c0, 16}, {3 + c0, 14}});
  text(ws, 0, 0, t_.get("titles", "crossings"), title());
  const std::size_t shown = std::min(d_.crossings.size(), t_.crossing_rows);
  const std::uint64_t total = std::max<std::uint64_t>(d_.total_crossings, d_.crossings.size());
  Row r = cap_note(ws, 1, shown, total, "crossings.csv");
  const Row head = r;
  if (by_section) headings(ws, r, 0, "crossings", {"section"}, 45);
  headings(ws, r++, c0, "crossings",
           {"trajectory", "line", "chainage", "block", "mass", "time", "direction", "vx", "vz",
            "speed", "omega", "translational_energy", "rotational_energy", "passing_height",
            "sliding"},
           45);
  worksheet_freeze_panes(ws, r, 1 + c0);
  check(worksheet_repeat_rows(ws, head, head), "worksheet_repeat_rows");
  lxw_format *cf = number("count"), *xf = number("coordinate"), *mf = number("mass"),
             *lf = number("length"), *tf = number("time"), *sf = number("speed"),
             *ef = number("energy"), *gf = number("general");
  for (std::size_t i = 0; i < shown; ++i, ++r) {
    const auto& c = d_.crossings[i];
    const DataRow row = data_row(ws, r, d_.crossing_sections, i);
    const sim::Scenario* s = row.scenario;
    row.num(0, static_cast<double>(c.trajectory), cf);
    row.text(1, line_name(c.line));
    row.num(2, line_chainage(c.line), xf);
    if (s && c.block < s->blocks.size()) row.text(3, s->blocks[c.block].id);
    else row.num(3, c.block, cf);
    row.num(4, c.mass, mf);
    row.num(5, c.time, tf);
    row.num(6, c.direction, gf);
    row.num(7, c.velocity.x, sf);
    row.num(8, c.velocity.z, sf);
    row.num(9, c.speed, sf);
    row.num(10, c.omega, sf);
    row.num(11, c.translational_energy / 1000, ef);
    row.num(12, c.rotational_energy / 1000, ef);
    row.num(13, c.height, lf);
    row.num(14, c.sliding ? 1 : 0, cf);
  }
  const Row last = static_cast<Row>(std::min<std::size_t>(head + t_.print_rows, r > 0 ? r - 1 : 0));
  check(worksheet_print_area(ws, 0, 0, std::max(last, head), 14 + c0), "worksheet_print_area");
}

// ---- the whole workbook ----------------------------------------------------------------

void Report::write() {
  // Properties: a fixed creation time (the run's date at 00:00 UTC) for reproducible bytes.
  const auto ymd = parse_date(d_.date);
  const auto created = std::chrono::sys_days(ymd).time_since_epoch();
  lxw_doc_properties props{};
  const std::string title = d_.scenario ? d_.scenario->scenario.name : std::string("pierre");
  const std::string comments =
      fmt::format("pierre {}, seed {}", d_.pierre_version, d_.seed);
  props.title = const_cast<char*>(title.c_str());
  props.subject = const_cast<char*>(t_.get("titles", "summary").c_str());
  props.author = const_cast<char*>("pierre");
  props.comments = const_cast<char*>(comments.c_str());
  props.created =
      static_cast<time_t>(std::chrono::duration_cast<std::chrono::seconds>(created).count());
  check(workbook_set_properties(wb_, &props), "workbook_set_properties");

  // Create the sheets in the template's order (the tab order), then fill them.
  std::vector<std::string> used;
  auto add = [&](const std::string& name) {
    const lxw_error e = workbook_validate_sheet_name(wb_, name.c_str());
    if (e != LXW_NO_ERROR) fail(fmt::format("sheet name \"{}\"", name), e);
    used.push_back(lower(name));
    return check_ptr(workbook_add_worksheet(wb_, name.c_str()), "workbook_add_worksheet");
  };
  for (const char* k : {"summary", "inputs", "profile", "trajectories", "crossings"})
    used.push_back(lower(t_.get("sheets", k)));
  used.push_back("history");  // reserved by Excel, which refuses a workbook with such a sheet
  std::vector<std::string> barrier_names, quarry_names;
  for (const auto& b : d_.barriers)
    barrier_names.push_back(item_sheet_name("barrier", b.spec.name, used));
  if (d_.quarry)
    for (const auto& row : d_.quarry->rows)
      quarry_names.push_back(item_sheet_name("quarry", row.name, used));
  used.clear();
  std::map<std::string, lxw_worksheet*> sheets;
  std::vector<lxw_worksheet*> barrier_sheets, quarry_sheets;
  for (const auto& key : t_.order) {
    if (key == "barriers") {
      for (const auto& n : barrier_names) barrier_sheets.push_back(add(n));
    } else if (key == "quarries") {
      for (const auto& n : quarry_names) quarry_sheets.push_back(add(n));
    } else {
      sheets[key] = add(t_.get("sheets", key));
    }
  }
  summary(sheets.at("summary"));
  for (std::size_t i = 0; i < d_.barriers.size(); ++i)
    barrier(barrier_sheets[i], barrier_names[i], d_.barriers[i]);
  for (std::size_t i = 0; i < quarry_sheets.size(); ++i)
    quarry(quarry_sheets[i], quarry_names[i], i);
  profile(sheets.at("profile"), t_.get("sheets", "profile"));
  inputs(sheets.at("inputs"));
  trajectories(sheets.at("trajectories"));
  crossings(sheets.at("crossings"));
  worksheet_activate(sheets.at("summary"));
}

}  // namespace

void write_report(const std::filesystem::path& file, const ReportData& data,
                  const ReportTemplate& tpl) {
  parse_date(data.date);  // before anything is written
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  const fs::path tmp =
      dir / fmt::format(".{}.partial-{}", file.filename().string(), static_cast<long>(::getpid()));
  std::error_code ec;
  fs::remove(tmp, ec);

  lxw_workbook_options options{};
  options.constant_memory = LXW_FALSE;  // charts need the cells to fill their caches
  options.tmpdir = nullptr;
  options.use_zip64 = LXW_FALSE;
  const std::string tmp_name = tmp.string();
  lxw_workbook* wb = workbook_new_opt(tmp_name.c_str(), &options);
  if (!wb) throw std::runtime_error("report.xlsx: workbook_new failed (out of memory)");
  try {
    Report(wb, data, tpl).write();
  } catch (...) {
    lxw_workbook_free(wb);
    fs::remove(tmp, ec);
    throw;
  }
  const lxw_error e = workbook_close(wb);  // writes the file and frees the workbook
  if (e != LXW_NO_ERROR) {
    fs::remove(tmp, ec);
    throw std::runtime_error(fmt::format("report.xlsx: cannot write {}: {}", file.string(),
                                         lxw_strerror(e)));
  }
  fs::rename(tmp, file, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(tmp, ec);
    throw std::runtime_error(fmt::format("report.xlsx: cannot move the report into place as {}: {}",
                                         file.string(), why));
  }
}

}  // namespace pierre::io
