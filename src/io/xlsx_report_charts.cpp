// Chart helpers: scatter charts, series, markers, labels, axes at one scale or over a curve,
// and the data they draw (trajectory paths, histogram outlines, curve grids).
#include "xlsx_report_writer.hpp"

#include "pierre/io/chart_scale.hpp"

#include <algorithm>
#include <cmath>

#include "pierre/stats/empirical_cdf.hpp"

namespace pierre::io::detail {
namespace {

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

}  // namespace

lxw_chart* Report::scatter_chart(std::string_view chart_key, const std::string& name) {
  const std::string section = "chart." + std::string(chart_key);
  lxw_chart_font title_font{};
  title_font.size = 11;
  title_font.bold = LXW_EXPLICIT_FALSE;
  return scatter_chart(chart_key, with_name(t_.get(section, "title"), name),
                       title_font);
}

lxw_chart* Report::scatter_chart(std::string_view chart_key, const std::string& title,
                                 lxw_chart_font title_font) {
  lxw_chart* chart =
      check_ptr(workbook_add_chart(wb_, LXW_CHART_SCATTER_STRAIGHT), "workbook_add_chart");
  const std::string section = "chart." + std::string(chart_key);
  chart_title_set_name(chart, keep(title));
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
  if (!valid_extent(xmin, xmax, zmin, zmax)) return;
  // The plot area: the chart less its axis labels and legend (about 85 % by 68 %).
  const AxisBounds b = equal_scale_bounds(xmin, xmax, zmin, zmax, t_.chart_width * x_scale * 0.85,
                                          t_.chart_height * y_scale * 0.68);
  chart_axis_set_min(chart->x_axis, b.x0);
  chart_axis_set_max(chart->x_axis, b.x1);
  chart_axis_set_min(chart->y_axis, b.z0);
  chart_axis_set_max(chart->y_axis, b.z1);
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

Bounds bounds(const std::vector<geometry::Vec2>& points) {
  Bounds b;
  for (const auto& p : points) {
    b.xmin = std::min(b.xmin, p.x);
    b.xmax = std::max(b.xmax, p.x);
    b.zmin = std::min(b.zmin, p.z);
    b.zmax = std::max(b.zmax, p.z);
  }
  return b;
}

void Report::curve_axes(lxw_chart* c, double lo, double hi) {
  // On round numbers, so that the tick labels are (the data's own ends are not).
  const AxisRange x = round_axis(lo, hi);
  chart_axis_set_min(c->x_axis, x.lo);
  chart_axis_set_max(c->x_axis, x.hi);
  if (x.step > 0) chart_axis_set_major_unit(c->x_axis, x.step);
  chart_axis_set_min(c->y_axis, 0);
  chart_axis_set_num_format(c->x_axis, keep(t_.get("formats", "general")));
}

Row Report::outline_rows(lxw_worksheet* ws, Row r0, Col xc, double lo, double width,
                         const std::vector<double>& density, lxw_format* xf, lxw_format* yf) {
  Row o = r0;
  for (std::size_t i = 0; i < density.size(); ++i) {
    const double a = lo + width * static_cast<double>(i), e = a + width;
    for (auto [px, py] : {std::pair{a, 0.0}, std::pair{a, density[i]}, std::pair{e, density[i]},
                          std::pair{e, 0.0}}) {
      num(ws, o, xc, px, xf);
      num(ws, o++, xc + 1, py, yf);
    }
  }
  return o;
}

std::vector<double> even_grid(double lo, double hi, int n) {
  std::vector<double> grid(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) grid[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (n - 1);
  return grid;
}

std::vector<double> sample_cdf(const std::vector<double>& x, const std::vector<double>& grid) {
  return x.empty() ? std::vector<double>(grid.size(), kNaN) : stats::empirical_cdf(x, grid);
}

}  // namespace pierre::io::detail
