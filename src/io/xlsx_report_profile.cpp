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

  lxw_chart_font title_font{};
  title_font.size = 12;  // the sheet's one large chart: a larger title, bold as Excel's default
  lxw_chart* chart = scatter_chart("profile", t_.get("chart.profile", "title"), title_font);
  bool any = false;
  const Bounds ext = d_.scenario ? bounds(d_.scenario->scenario.profile.vertices()) : Bounds{};

  // Paths first so that the profile is drawn over them.
  const Row pr = path_rows(ws, r0, d_.sample_paths, xf);
  if (pr > r0) {
    xy_series(chart, sheet, r0, pr - 2, 2, 3, h("profile", "paths"), t_.colour("paths"), 0.75f);
    any = true;
  }
  if (d_.scenario) {
    const auto& prof = d_.scenario->scenario.profile;
    const auto& v = prof.vertices();
    // Lines drawn at least 6 % of the profile's height, so that they show on a tall slope.
    const double z_range = ext.zmax - ext.zmin;
    const double line_height =
        std::max(t_.profile_line_height, std::isfinite(z_range) ? 0.06 * z_range : 0.0);
    Row vr = r0;
    for (const auto& p : v) {
      num(ws, vr, 0, p.x, xf);
      num(ws, vr++, 1, p.z, xf);
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
    equal_scale(chart, ext.xmin, ext.xmax, ext.zmin, ext.zmax, 1.6, 1.6);
    insert_chart(ws, {chart_row, 0}, chart, 1.6, 1.6);
  }
}

}  // namespace pierre::io::detail
