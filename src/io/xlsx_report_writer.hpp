// The writer of report.xlsx (pierre/io/xlsx_report.hpp), internal to the io layer: the class
// Report that lays a ReportData out on a libxlsxwriter workbook as the template says, and the
// small helpers its files share. One file per purpose:
//   xlsx_report.cpp              write_report, and Report::write: properties, sheets in tab order
//   xlsx_report_cells.cpp        formats, cells, rows and columns, names, the check table
//   xlsx_report_charts.cpp       chart helpers: scatter charts, series, axes, drawn paths
//   xlsx_report_summary.cpp      Summary
//   xlsx_report_inputs.cpp       Inputs
//   xlsx_report_barrier.cpp      a barrier's sheet
//   xlsx_report_profile.cpp      Profile
//   xlsx_report_quarry.cpp       a quarry row's sheet, and the rows' table on Summary
//   xlsx_report_quarry_charts.cpp  a quarry row's charts
//   xlsx_report_data_sheets.cpp  Trajectories and Crossings
// A member that writes a table takes the row it starts at and returns the row after it.
#pragma once

#include <xlsxwriter.h>

#include <chrono>
#include <cstdint>
#include <deque>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "pierre/design/number_kind.hpp"
#include "pierre/io/report_data.hpp"
#include "pierre/io/report_template.hpp"

namespace pierre::io::detail {

using Row = lxw_row_t;
using Col = lxw_col_t;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Every libxlsxwriter return code is checked: a failure is a std::runtime_error saying what.
[[noreturn]] void fail(std::string_view what, lxw_error e);
void check(lxw_error e, std::string_view what);
template <class T>
T* check_ptr(T* p, std::string_view what) {
  if (!p) throw std::runtime_error(fmt::format("report.xlsx: {} failed", what));
  return p;
}

std::string replace_all(std::string s, std::string_view key, std::string_view value);
std::string lower(std::string s);
std::string with_name(const std::string& pattern, const std::string& name);
// The lines `text` takes wrapped in cells `width` characters wide, word by word as the
// spreadsheet wraps (Report::fit_row sets a row's height from it).
double wrapped_lines(const std::string& text, double width);
// An ISO date "YYYY-MM-DD" (anything after the tenth character is ignored).
std::chrono::year_month_day parse_date(const std::string& s);
// Four significant digits, "—" for a NaN or an infinity (numbers inside a text).
std::string format_number(double v);
// `n` points evenly spaced from lo to hi, where the fitted curves are drawn.
std::vector<double> even_grid(double lo, double hi, int n);
// The empirical CDF of `x` at `grid`, NaN (an empty cell) everywhere without a sample.
std::vector<double> sample_cdf(const std::vector<double>& x, const std::vector<double>& grid);
// The extent of a drawing's points (the infinities of an empty one for none).
struct Bounds {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  double xmin = kInf, xmax = -kInf, zmin = kInf, zmax = -kInf;
};
Bounds bounds(const std::vector<geometry::Vec2>& points);

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
  void properties();

  // -- formats (xlsx_report_cells.cpp)
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
  lxw_format* wrapped_note();  // note(), wrapped in its cell, at the top
  lxw_format* bold();
  lxw_format* wrap();
  lxw_format* bold_wrap();  // bold(), wrapped in its cell, at the top
  lxw_format* centred();
  lxw_format* top();
  lxw_format* indented();
  lxw_format* centred_bold();
  lxw_format* status_format(std::string_view status);  // for the conditional formats

  // -- cells, rows and columns (xlsx_report_cells.cpp)
  void text(lxw_worksheet* ws, Row r, Col c, const std::string& s, lxw_format* f = nullptr);
  void num(lxw_worksheet* ws, Row r, Col c, double v, lxw_format* f);
  void opt(lxw_worksheet* ws, Row r, Col c, const std::optional<double>& v, lxw_format* f) {
    if (v) num(ws, r, c, *v, f);
  }
  void count(lxw_worksheet* ws, Row r, Col c, std::uint64_t v) {
    num(ws, r, c, static_cast<double>(v), number("count"));
  }
  // A seed: a number where a double holds it exactly (up to 2^53), else text (a double would
  // round it).
  void seed(lxw_worksheet* ws, Row r, Col c, std::uint64_t v, lxw_format* f);
  // Text across the columns c0 … c1 of row r (a merged range).
  void merged(lxw_worksheet* ws, Row r, Col c0, Col c1, const std::string& s, lxw_format* f);
  // A text longer than its cell, kept inside the print area: merged over columns c0..c1
  // (`chars` wide in all, Excel's width units), wrapped (f must wrap), the row as high as it
  // needs. A long note in one cell ran off the printed page.
  void paragraph(lxw_worksheet* ws, Row r, Col c0, Col c1, double chars, const std::string& s,
                 lxw_format* f);
  // A table's title after a blank row: the template's titles.<key>; returns the row below it.
  Row table_title(lxw_worksheet* ws, Row r, std::string_view key) {
    text(ws, r + 1, 0, t_.get("titles", key), section());
    return r + 2;
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
    const design::QuarryGeometry* geometry = nullptr;  // a quarry row's section
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
    // The section's crest and toe, as its design results have them (in section order).
    if (d_.quarry && i < sections.size() && sections[i] < d_.quarry->sections.size()) {
      row.geometry = &d_.quarry->sections[sections[i]].geometry;
    }
    return row;
  }
  // Sets row r's height to show every wrapped text: (text, width of its cells in characters).
  void fit_row(lxw_worksheet* ws, Row r,
               std::initializer_list<std::pair<const std::string*, double>> cells);
  void page_setup(lxw_worksheet* ws);
  std::string page_header() const;
  void status_colours(lxw_worksheet* ws, Row r0, Row r1, Col c);

  // -- charts (xlsx_report_charts.cpp)
  // A scatter chart of the template's chart.<key>: its title with {name} replaced (11 pt, not
  // bold), its axis names, light gridlines, the legend below and blanks drawn as gaps.
  lxw_chart* scatter_chart(std::string_view chart_key, const std::string& name);
  // The same with the title as given, in `title_font`.
  lxw_chart* scatter_chart(std::string_view chart_key, const std::string& title,
                           lxw_chart_font title_font);
  lxw_chart_series* xy_series(lxw_chart* chart, const std::string& sheet, Row r0, Row r1, Col xc,
                              Col yc, const std::string& name, std::uint32_t colour,
                              float line_width, std::uint8_t dash = LXW_CHART_LINE_DASH_SOLID);
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
  // The axes of a histogram or a CDF chart: x from lo to hi in the general format, y from 0.
  void curve_axes(lxw_chart* c, double lo, double hi);
  // The outline of histogram columns `width` wide from `lo`, of heights `density`: (e_i, 0),
  // (e_i, d_i), (e_i+1, d_i), (e_i+1, 0), … in columns xc (x) and xc + 1 (y) from row r0;
  // returns the row after the last point.
  Row outline_rows(lxw_worksheet* ws, Row r0, Col xc, double lo, double width,
                   const std::vector<double>& density, lxw_format* xf, lxw_format* yf);

  // -- names (xlsx_report_cells.cpp)
  // The sheet of a barrier or a quarry row: the template's sheets.<key> with {name} replaced.
  // "read from <file>": under a rule set or class table, the file it was read from.
  std::string read_from(const std::string& file) const {
    return replace_all(t_.get("labels", "read_from"), "{file}", file);
  }
  std::string item_sheet_name(std::string_view key, const std::string& item,
                              std::vector<std::string>& used);
  std::string line_name(std::uint32_t i) const;
  double line_chainage(std::uint32_t i) const;
  std::optional<std::uint32_t> line_index(const std::string& name) const;

  // -- check lines (xlsx_report_cells.cpp): with `subject`, Summary's table of every field;
  // without, a barrier's or a quarry row's, its text in merged columns
  Row check_table(lxw_worksheet* ws, Row r, const std::vector<design::CheckLine>& lines,
                  bool subject);

  // -- Summary (xlsx_report_summary.cpp); its quarry rows' table is quarry_summary below
  void summary(lxw_worksheet* ws);
  Row summary_run(lxw_worksheet* ws, Row r);
  Row summary_barriers(lxw_worksheet* ws, Row r);
  Row summary_barrier_values(lxw_worksheet* ws, Row r);
  std::string candidate_kit(const design::BarrierSpec& spec, double mel_kJ, double sel_kJ);
  Row summary_lines(lxw_worksheet* ws, Row r);
  Row summary_stops(lxw_worksheet* ws, Row r);
  Row summary_basis(lxw_worksheet* ws, Row r);
  void summary_checks(lxw_worksheet* ws, Row r);

  // -- Inputs (xlsx_report_inputs.cpp)
  void inputs(lxw_worksheet* ws);
  void blocks(lxw_worksheet* ws);  // the block groups, on a sheet of their own (xlsx_report_inputs.cpp)
  template <class Write>
  void each_section(lxw_worksheet* ws, Row& r, const LoadedScenario& sc, Write&& write);
  Row inputs_simulation(lxw_worksheet* ws, Row r, const LoadedScenario& sc);
  Row inputs_materials(lxw_worksheet* ws, Row r, const LoadedScenario& sc);
  Row inputs_blocks(lxw_worksheet* ws, Row r, const LoadedScenario& sc);
  Row inputs_sources(lxw_worksheet* ws, Row r, const LoadedScenario& sc);
  Row inputs_vertices(lxw_worksheet* ws, Row r, const LoadedScenario& sc);
  Row inputs_lines(lxw_worksheet* ws, Row r, const LoadedScenario& sc);
  Row inputs_quarries(lxw_worksheet* ws, Row r);
  Row inputs_barriers(lxw_worksheet* ws, Row r);
  void inputs_scenario_text(lxw_worksheet* ws, Row r, const LoadedScenario& sc);

  // -- a barrier's sheet (xlsx_report_barrier.cpp, which defines the types it passes): its
  // tables, then its charts on a page of their own
  void barrier(lxw_worksheet* ws, const std::string& sheet, const design::BarrierDesign& b);
  struct BarrierSample;
  struct StatisticsColumn;
  struct BarrierPlot;
  struct BarrierChartData;
  Row barrier_overview(lxw_worksheet* ws, Row r, const design::BarrierDesign& b);
  BarrierSample barrier_sample(const design::BarrierDesign& b) const;
  Row barrier_statistics(lxw_worksheet* ws, Row r, const design::BarrierDesign& b,
                         const BarrierSample& sample);
  void statistic(lxw_worksheet* ws, Row r, Col c, std::string_view s, const StatisticsColumn& q);
  Row barrier_bootstrap(lxw_worksheet* ws, Row r, const design::BarrierDesign& b);
  Row barrier_design_values(lxw_worksheet* ws, Row r, const design::BarrierDesign& b);
  Row barrier_factors(lxw_worksheet* ws, Row r, const design::BarrierDesign& b);
  Row barrier_exceedance(lxw_worksheet* ws, Row r, const design::BarrierDesign& b);
  Row barrier_checks(lxw_worksheet* ws, Row r, const design::BarrierDesign& b);
  void barrier_charts(lxw_worksheet* ws, const std::string& sheet, Row r,
                      const design::BarrierDesign& b, const BarrierSample& sample);
  BarrierChartData barrier_chart_data(lxw_worksheet* ws, Row data_row, const BarrierPlot& pl);
  void barrier_histogram_chart(lxw_worksheet* ws, const std::string& sheet, Cell at,
                               const BarrierPlot& pl, const BarrierChartData& cd,
                               const std::string& name);
  void barrier_cdf_chart(lxw_worksheet* ws, const std::string& sheet, Cell at,
                         const BarrierPlot& pl, const BarrierChartData& cd,
                         const std::string& name);

  // -- Profile (xlsx_report_profile.cpp)
  void profile(lxw_worksheet* ws, const std::string& sheet);
  bool profile_ground(lxw_worksheet* ws, const std::string& sheet, lxw_chart* chart, Row r0,
                      const Bounds& ext);
  struct Mark;
  // Vertical segments in columns c (x) and c + 1 (z) from row r0, a gap row after each, drawn as
  // one series of the profile's `key` named at their tops; nullptr when there are none.
  lxw_chart_series* vertical_marks(lxw_worksheet* ws, const std::string& sheet, lxw_chart* chart,
                                   Row r0, Col c, const std::vector<Mark>& marks,
                                   std::string_view key, float line_width,
                                   std::uint8_t dash = LXW_CHART_LINE_DASH_SOLID);

  // -- quarry danger zones (design-checks.md §2): the rows' table on Summary and a row's sheet
  // (xlsx_report_quarry.cpp), the row's charts (xlsx_report_quarry_charts.cpp)
  Row quarry_summary(lxw_worksheet* ws, Row r);
  Row quarry_averages(lxw_worksheet* ws, Row r);
  // A distance (m or /H): a number, or "beyond the profile" for +infinity.
  void distance(lxw_worksheet* ws, Row r, Col c, double v, lxw_format* f);
  void quarry(lxw_worksheet* ws, const std::string& sheet, std::size_t row);
  using QuarrySections = std::vector<const design::QuarrySectionResult*>;  // a row's sections
  Row quarry_overview(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                      const QuarrySections& secs);
  Row quarry_geometry(lxw_worksheet* ws, Row r, const QuarrySections& secs);
  Row quarry_counts(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                    const QuarrySections& secs);
  Row quarry_statistics(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                        const QuarrySections& secs);
  Row quarry_fits(lxw_worksheet* ws, Row r, const design::QuarryRow& row);
  Row quarry_exceedance(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                        const QuarrySections& secs);
  Row quarry_governing(lxw_worksheet* ws, Row r, const design::QuarryRow& row);
  Row quarry_zones(lxw_worksheet* ws, Row r, const QuarrySections& secs);
  Row quarry_checks(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                    const QuarrySections& secs);
  void quarry_charts(lxw_worksheet* ws, const std::string& sheet, Row r,
                     const design::QuarryRow& row, const QuarrySections& secs);
  Row quarry_section_chart(lxw_worksheet* ws, const std::string& sheet, Row data_row, Cell at,
                           const design::QuarrySectionResult& s);
  Row quarry_section_marks(lxw_worksheet* ws, const std::string& sheet, lxw_chart* chart, Row r0,
                           const design::QuarrySectionResult& s, const geometry::Profile& prof);
  // The histogram, CDF and fitted curves of one distance of a row (data block at `data_row`,
  // charts at `at` and beside it); returns the next free data row.
  Row quarry_distance_charts(lxw_worksheet* ws, const std::string& sheet, Row data_row, Cell at,
                             Col cdf_col, std::string_view which, const design::QuarryRow& row);
  struct QuarryDistance;
  struct DistanceChartData;
  DistanceChartData quarry_distance_data(lxw_worksheet* ws, Row data_row, const QuarryDistance& d);
  void quarry_histogram_chart(lxw_worksheet* ws, const std::string& sheet, Cell at,
                              const QuarryDistance& d, const DistanceChartData& cd,
                              const std::string& name);
  void quarry_cdf_chart(lxw_worksheet* ws, const std::string& sheet, Cell at,
                        const QuarryDistance& d, const DistanceChartData& cd,
                        const std::string& name);

  // -- data sheets (xlsx_report_data_sheets.cpp)
  void trajectories(lxw_worksheet* ws);
  void crossings(lxw_worksheet* ws);
  Row cap_note(lxw_worksheet* ws, Row r, std::size_t shown, std::uint64_t total,
               const char* csv);
  Row data_sheet_head(lxw_worksheet* ws, std::string_view key, Col c0, std::size_t shown,
                      std::uint64_t total, const char* csv,
                      std::initializer_list<std::string_view> keys);
  void data_sheet_print_area(lxw_worksheet* ws, Row head, Row r, Col last_col);

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

}  // namespace pierre::io::detail
