// The Profile sheet: the slope with a few trajectories, and the observation lines and barriers
// standing on it, drawn at one scale from a data block below the chart. A quarry's sections have
// profiles of their own, drawn on their rows' sheets.
#include "xlsx_report_writer.hpp"

#include "pierre/io/chart_scale.hpp"

#include <algorithm>
#include <cmath>

namespace pierre::io::detail {

// A vertical segment of the profile chart: from the ground at (x, z) up `height`, named at its
// top.
struct Report::Mark {
  double x, z, height;
  std::string name;
};

void Report::profile(lxw_worksheet* ws, const std::string& sheet) {
  page_setup(ws);
  width(ws, 0, 7, 12);
  // A quarry's sections are drawn on their rows' sheets: the title says so, not what a slope
  // scenario's chart would show.
  // The title names what the chart holds: barriers stand at lines, so lines without barriers
  // or neither.
  const bool lines = d_.scenario && !d_.scenario->scenario.lines.empty();
  const char* key = d_.quarry              ? "quarry_profile"
                    : !d_.barriers.empty() ? "profile"
                    : lines                ? "profile_lines"
                                           : "profile_plain";
  text(ws, 0, 0, t_.get("titles", key), title());
  if (d_.quarry) {
    text(ws, 2, 0, t_.get("labels", "quarry_profile"), note());
    return;
  }
  const Row chart_row = 2;
  const Bounds ext = d_.scenario ? bounds(d_.scenario->scenario.profile.vertices()) : Bounds{};
  // The chart is 1.6 of the layout's width, and as tall as the section needs to fill that width
  // at one scale: 1.0 to 2.6 of the layout's height (plot area 85 % by 68 %, as equal_scale).
  const double plot_w = 1.6 * t_.chart_width * 0.85, plot_h = t_.chart_height * 0.68;
  const double y_scale =
      valid_extent(ext.xmin, ext.xmax, ext.zmin, ext.zmax)
          ? fitting_height(ext.xmin, ext.xmax, ext.zmin, ext.zmax, plot_w, plot_h, 2.6 * plot_h) /
                plot_h
          : 1.6;
  // Rows of 20 px, and a little room under the chart.
  const Row rows_for_chart = static_cast<Row>(std::ceil((y_scale + 0.2) * t_.chart_height / 20.0)) + 2;
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
  lxw_chart_font title_font{};
  title_font.size = 12;  // the sheet's one large chart: a larger title, bold as Excel's default
  lxw_chart* chart = scatter_chart("profile", t_.get("chart.profile", "title"), title_font);
  // Paths first so that the profile is drawn over them.
  const Row pr = path_rows(ws, r0, d_.sample_paths, number("coordinate"));
  bool any = pr > r0;
  if (any)
    xy_series(chart, sheet, r0, pr - 2, 2, 3, h("profile", "paths"), t_.colour("paths"), 0.75f);
  if (d_.scenario) any = profile_ground(ws, sheet, chart, r0, ext) || any;
  if (any) {
    equal_scale(chart, ext.xmin, ext.xmax, ext.zmin, ext.zmax, 1.6, y_scale);
    insert_chart(ws, {chart_row, 0}, chart, 1.6, y_scale);
  }
}

// The slope, and on it the observation lines and the barriers; returns whether the slope had a
// vertex to draw.
bool Report::profile_ground(lxw_worksheet* ws, const std::string& sheet, lxw_chart* chart, Row r0,
                            const Bounds& ext) {
  const auto& prof = d_.scenario->scenario.profile;
  const auto& v = prof.vertices();
  lxw_format* xf = number("coordinate");
  Row vr = r0;
  for (const auto& p : v) {
    num(ws, vr, 0, p.x, xf);
    num(ws, vr++, 1, p.z, xf);
  }
  if (!v.empty())
    xy_series(chart, sheet, r0, vr - 1, 0, 1, h("profile", "profile"), t_.colour("profile"),
              2.25f);
  // Observation lines at least 6 % of the profile's height, so that they show on a tall slope.
  const double z_range = ext.zmax - ext.zmin;
  const double line_height =
      std::max(t_.profile_line_height, std::isfinite(z_range) ? 0.06 * z_range : 0.0);
  std::vector<Mark> lines;
  for (const auto& l : d_.scenario->scenario.lines)
    if (const auto g = prof.top_ground(l.x)) lines.push_back({l.x, g->z, line_height, l.name});
  vertical_marks(ws, sheet, chart, r0, 4, lines, "lines", 1.25f, LXW_CHART_LINE_DASH_DASH);
  // Barriers: the candidate's height when known, else h_i.
  std::vector<Mark> barriers;
  for (const auto& b : d_.barriers) {
    const auto g = prof.top_ground(b.chainage);
    if (!g) continue;
    const double hb = b.spec.candidate && b.spec.candidate->height ? *b.spec.candidate->height
                                                                   : b.h_i;
    if (std::isfinite(hb)) barriers.push_back({b.chainage, g->z, hb, b.spec.name});
  }
  // Markers at the foot and the top, so that a barrier shows beside a tall slope.
  if (lxw_chart_series* s = vertical_marks(ws, sheet, chart, r0, 6, barriers, "barriers", 3.5f))
    markers(s, LXW_CHART_MARKER_DIAMOND, 7, t_.colour("barriers"), true);
  return !v.empty();
}

lxw_chart_series* Report::vertical_marks(lxw_worksheet* ws, const std::string& sheet,
                                         lxw_chart* chart, Row r0, Col c,
                                         const std::vector<Mark>& marks, std::string_view key,
                                         float line_width, std::uint8_t dash) {
  if (marks.empty()) return nullptr;
  lxw_format* xf = number("coordinate");
  Row r = r0;
  std::vector<std::string> names;  // per point: the top of each segment is named
  for (const auto& m : marks) {
    num(ws, r, c, m.x, xf);
    num(ws, r++, c + 1, m.z, xf);
    num(ws, r, c, m.x, xf);
    num(ws, r++, c + 1, m.z + m.height, xf);
    ++r;
    names.insert(names.end(), {"", m.name, ""});
  }
  lxw_chart_series* s = xy_series(chart, sheet, r0, r - 2, c, c + 1, h("profile", key),
                                  t_.colour(key), line_width, dash);
  names.pop_back();  // the range ends before the last gap row
  point_labels(s, names);
  return s;
}

}  // namespace pierre::io::detail
