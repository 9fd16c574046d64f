// The charts of a quarry row's sheet, on a page of their own: each section drawn at one scale
// with its zones and work areas, then RD and ID (histogram with the fitted density, empirical
// against fitted CDF with the observed points), from a data block below them.
#include "xlsx_report_writer.hpp"

#include <algorithm>
#include <cmath>

#include "pierre/stats/lognormal_fit.hpp"

namespace pierre::io::detail {

namespace {

// The columns of a distance's histogram: the positive finite values in `bins` columns from 0,
// density over every value (zeros and censored count in n), so that they compare with
// (1 − p0) f_logn; the columns reach the largest value or observed break point.
struct DistanceColumns {
  double hi = 0, width = 1, dmax = 0;
  std::size_t positive = 0;
  std::vector<double> density;
};

DistanceColumns distance_columns(const std::vector<double>& x,
                                 const std::optional<design::ObservedComparison>& obs, int bins) {
  DistanceColumns c;
  double hi = 0;
  for (double v : x)
    if (std::isfinite(v) && v > 0) {
      hi = std::max(hi, v);
      ++c.positive;
    }
  if (obs)
    for (double b : obs->breaks_h)
      if (std::isfinite(b)) hi = std::max(hi, b);
  if (!(hi > 0)) hi = 1;
  const double w = hi / bins;
  std::vector<double> density(static_cast<std::size_t>(bins), 0.0);
  for (double v : x)
    if (std::isfinite(v) && v > 0) {
      const auto b = std::clamp(static_cast<long>(std::floor(v / w)), 0L, static_cast<long>(bins) - 1);
      density[static_cast<std::size_t>(b)] += 1;
    }
  for (double& d : density) {
    d /= static_cast<double>(x.size()) * w;
    c.dmax = std::max(c.dmax, d);
  }
  c.hi = hi;
  c.width = w;
  c.density = std::move(density);
  return c;
}

}  // namespace

// The charts on a page of their own after the tables: the sections first, then RD and ID; their
// data block below them stays on the sheet, out of the print area.
void Report::quarry_charts(lxw_worksheet* ws, const std::string& sheet, Row r,
                           const design::QuarryRow& row, const QuarrySections& secs) {
  ++r;
  const Row chart_row = r;
  const Row rows_per_chart = static_cast<Row>(std::ceil(t_.chart_height / 20.0)) + 1;
  const Row rows_per_section = static_cast<Row>(std::ceil(1.4 * t_.chart_height / 20.0)) + 1;
  const Row n_sections = static_cast<Row>(secs.size());
  Row data_row = chart_row + n_sections * rows_per_section + 2 * rows_per_chart + 1;
  text(ws, data_row++, 0, t_.get("titles", "chart_data"), section());
  check(worksheet_print_area(ws, 0, 0, data_row - 3, 13), "worksheet_print_area");
  // Page breaks between charts, never through one: a page holds what a lone section's page
  // does (its section, RD and ID), so a group's charts go on as many pages as they need.
  auto& breaks = breaks_.emplace_back(std::vector<lxw_row_t>{chart_row});
  {
    const Row page = rows_per_section + 2 * rows_per_chart;
    Row page_start = chart_row, end = chart_row;
    std::vector<Row> heights(secs.size(), rows_per_section);
    heights.insert(heights.end(), 2, rows_per_chart);  // RD, then ID
    for (const Row height : heights) {
      if (end + height - page_start > page) {
        breaks.push_back(end);
        page_start = end;
      }
      end += height;
    }
  }
  breaks.push_back(0);
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

// A distance of a row (RD or ID) as drawn: its sample (/H), its statistics and fit, and the
// observed values.
struct Report::QuarryDistance {
  std::string_view key;
  const std::vector<double>& x;
  const design::DistanceStatistics& st;
  const std::optional<design::ObservedComparison>& obs;
};

// Where a distance's data block went: from row r0 the columns' outline up to (not including)
// `outline_end`, the curves up to `curves_last`, the observed points up to `observed_end`; the
// x axis from 0 to hi, and the largest column and fitted density (the y axis).
struct Report::DistanceChartData {
  Row r0, outline_end, curves_last, observed_end;
  double hi, dmax, cmax;
  bool columns;
};

Row Report::quarry_distance_charts(lxw_worksheet* ws, const std::string& sheet, Row data_row,
                                   Cell at, Col cdf_col, std::string_view which,
                                   const design::QuarryRow& row) {
  const bool rd = which == "rd";
  const QuarryDistance d{which, (rd ? row.rd_sample : row.id_sample).normalized,
                         rd ? row.rd : row.id, rd ? row.observed_rd : row.observed_id};
  const DistanceChartData cd = quarry_distance_data(ws, data_row, d);
  quarry_histogram_chart(ws, sheet, at, d, cd, row.name);
  quarry_cdf_chart(ws, sheet, {at.row, cdf_col}, d, cd, row.name);
  return std::max({cd.outline_end, cd.curves_last + 1, cd.observed_end}) + 1;
}

// A distance's data block from `data_row`: the columns' outline, on an even grid from 0 the
// fitted density, the empirical and the fitted CDF, and the observed points.
Report::DistanceChartData Report::quarry_distance_data(lxw_worksheet* ws, Row data_row,
                                                       const QuarryDistance& d) {
  const std::vector<double>& x = d.x;
  const design::DistanceStatistics& st = d.st;
  const auto& obs = d.obs;
  ++data_row;
  text(ws, data_row++, 0, t_.get("labels", d.key), section());
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

  const DistanceColumns cols = distance_columns(x, obs, t_.histogram_bins);
  const double hi = cols.hi;
  const Row o = cols.positive > 0 ? outline_rows(ws, r0, 0, 0.0, cols.width, cols.density, hf, pf)
                                  : r0;
  // Curves on an even grid from 0.
  const int n = t_.curve_points;
  const std::vector<double> grid = even_grid(0.0, hi, n), ecdf = sample_cdf(x, grid);
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
  return {r0, o, rn, ob, hi, cols.dmax, cmax, cols.positive > 0};
}

// The histogram with the fitted density.
void Report::quarry_histogram_chart(lxw_worksheet* ws, const std::string& sheet, Cell at,
                                    const QuarryDistance& d, const DistanceChartData& cd,
                                    const std::string& name) {
  if (!cd.columns && !d.st.fit) return;
  lxw_chart* hc = scatter_chart(std::string(d.key) + "_histogram", name);
  if (cd.columns)
    xy_series(hc, sheet, cd.r0, cd.outline_end - 1, 0, 1, h("quarry_chart", "histogram"),
              t_.colour("histogram"), 1.25f);
  if (d.st.fit)
    xy_series(hc, sheet, cd.r0, cd.curves_last, 2, 3, h("quarry_chart", "fitted_pdf"),
              t_.colour("lognormal"), 2.0f);
  curve_axes(hc, 0, cd.hi);
  // A density spike at 0 must not flatten the columns.
  if (cd.dmax > 0 && cd.cmax > 2.5 * cd.dmax) chart_axis_set_max(hc->y_axis, 1.5 * cd.dmax);
  insert_chart(ws, at, hc);
}

// The empirical against the fitted CDF, with the observed points.
void Report::quarry_cdf_chart(lxw_worksheet* ws, const std::string& sheet, Cell at,
                              const QuarryDistance& d, const DistanceChartData& cd,
                              const std::string& name) {
  if (d.x.empty() && !d.st.fit) return;
  const Row r0 = cd.r0, rn = cd.curves_last;
  lxw_chart* cc = scatter_chart(std::string(d.key) + "_cdf", name);
  if (!d.x.empty())
    xy_series(cc, sheet, r0, rn, 2, 4, h("quarry_chart", "empirical_cdf"),
              t_.colour("empirical"), 2.0f);
  if (d.st.fit)
    xy_series(cc, sheet, r0, rn, 2, 5, h("quarry_chart", "fitted_cdf"), t_.colour("lognormal"),
              1.5f, LXW_CHART_LINE_DASH_DASH);
  if (cd.observed_end > r0) {
    lxw_chart_series* s = xy_series(cc, sheet, r0, cd.observed_end - 1, 6, 7,
                                    h("quarry_chart", "observed_cdf"), t_.colour("observed"), 1.0f);
    markers(s, LXW_CHART_MARKER_CIRCLE, 5, t_.colour("observed"), false);
  }
  curve_axes(cc, 0, cd.hi);
  chart_axis_set_max(cc->y_axis, 1);
  insert_chart(ws, at, cc);
}

Row Report::quarry_section_chart(lxw_worksheet* ws, const std::string& sheet, Row data_row,
                                 Cell at, const design::QuarrySectionResult& s) {
  const ReportData::QuarrySectionView* view = section_view(s.spec.name);
  if (!view || !view->profile || view->profile->vertices().empty()) return data_row;
  const geometry::Profile& prof = *view->profile;

  ++data_row;
  text(ws, data_row++, 0, s.spec.name, section());
  const Row head = data_row;
  std::size_t k = 0;
  for (const char* key :
       {"profile", "paths", "toe", "danger_zone", "first_impact_zone", "work_areas", "bench"}) {
    text(ws, head, static_cast<Col>(2 * k), h("quarry_chart", key), heading());
    text(ws, head + 1, static_cast<Col>(2 * k), h("quarry_chart", "x"), heading());
    text(ws, head + 1, static_cast<Col>(2 * k + 1), h("quarry_chart", "z"), heading());
    ++k;
  }
  const Row r0 = head + 2;
  lxw_format* xf = number("coordinate");

  lxw_chart* chart = scatter_chart("quarry_section", s.spec.name);
  const Bounds ext = bounds(prof.vertices());
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
  const Row last = std::max({pr, vr, quarry_section_marks(ws, sheet, chart, r0, s, prof)});
  equal_scale(chart, ext.xmin, ext.xmax, ext.zmin, ext.zmax, 2.0, 1.4);
  chart_axis_set_num_format(chart->x_axis, keep(t_.get("formats", "general")));
  insert_chart(ws, at, chart, 2.0, 1.4);
  return last + 1;
}

// The marks on a section's ground: the toe, the ends of the danger zone and of the
// first-impact zone and the planned catch bench's outer edge (vertical segments, a series
// each), and the work areas (named points); returns the row after the last one written (r0
// when none is).
Row Report::quarry_section_marks(lxw_worksheet* ws, const std::string& sheet, lxw_chart* chart,
                                 Row r0, const design::QuarrySectionResult& s,
                                 const geometry::Profile& prof) {
  const auto& g = s.geometry;
  lxw_format* xf = number("coordinate");
  Row last = r0;
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
  // The bench's edge: where bench.retention counts a block as retained.
  if (s.spec.bench_width)
    mark(12, g.toe.x + g.direction * *s.spec.bench_width, "bench", t_.colour("bench"), 1.75f,
         LXW_CHART_LINE_DASH_ROUND_DOT);
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
  return last;
}

}  // namespace pierre::io::detail
