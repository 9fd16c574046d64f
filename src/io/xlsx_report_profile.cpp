// The Profile sheet.
#include "xlsx_report_writer.hpp"

#include <algorithm>
#include <cmath>

namespace pierre::io::detail {

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

}  // namespace pierre::io::detail
