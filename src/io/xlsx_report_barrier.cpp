// A barrier's sheet: the tables (statistics and fits, bootstrap intervals, Table 4.1's design
// values, the factors and how each was obtained, Table 4.2's exceedance, the check lines), then
// on a page of their own the histogram and the CDF of speed, height and energy at the barrier's
// line, drawn from a data block below them.
#include "xlsx_report_writer.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "pierre/design/number_text.hpp"
#include "pierre/stats/lognormal_fit.hpp"
#include "pierre/stats/percentile.hpp"
#include "pierre/stats/weibull_fit.hpp"

namespace pierre::io::detail {
namespace {

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

}  // namespace

// The sample at the barrier's line, energies in kJ.
struct Report::BarrierSample {
  std::vector<double> speed, height, energy, rotational;
};

// A column of the statistics table: a quantity, its fit (none for the rotational energy), and
// the sample of its empirical percentiles (empty for an observed quantity).
struct Report::StatisticsColumn {
  const design::QuantityFit* fit;
  const stats::SampleSummary* summary;
  std::string_view key, fmt;
  const std::vector<double>* sample;
};

// A quantity drawn on the chart page: its sample at the line and its fits.
struct Report::BarrierPlot {
  std::string_view key, fmt;
  const std::vector<double>* sample;
  const design::QuantityFit* fit;
};

// Where a quantity's data block went: the bins and the curves from row r0, the columns' outline
// up to (not including) row `outline_end`, the curves up to row `curves_last`, on x from lo to hi.
struct Report::BarrierChartData {
  Row r0, outline_end, curves_last;
  double lo, hi;
  bool columns;  // the sample has columns to draw
};

// A note over the tables' width: column A (34) and B:I (8 × 14).
constexpr Col kBarrierNoteLast = 8;
constexpr double kBarrierNoteWidth = 34 + 8 * 14;

void Report::barrier(lxw_worksheet* ws, const std::string& sheet, const design::BarrierDesign& b) {
  page_setup(ws);
  width(ws, 0, 0, 34);
  width(ws, 1, 12, 14);
  text(ws, 0, 0, with_name(t_.get("titles", "barrier"), b.spec.name), title());
  check(worksheet_set_row(ws, 0, 24, nullptr), "worksheet_set_row");
  Row r = barrier_overview(ws, 2, b);
  const BarrierSample sample = barrier_sample(b);
  r = barrier_statistics(ws, r, b, sample);
  r = barrier_bootstrap(ws, r, b);
  r = barrier_design_values(ws, r, b);
  r = barrier_factors(ws, r, b);
  r = barrier_exceedance(ws, r, b);
  r = barrier_checks(ws, r, b);
  barrier_charts(ws, sheet, r, b, sample);
}

// The line, the rules, how many trajectories crossed and the bootstrap's seed.
Row Report::barrier_overview(lxw_worksheet* ws, Row r, const design::BarrierDesign& b) {
  auto kv_text = [&](std::string_view label, const std::string& v) {
    text(ws, r, 0, std::string(label), bold());
    text(ws, r++, 1, v);
  };
  kv_text(h("barriers", "line"), fmt::format("{} ({} m)", b.spec.line, format_number(b.chainage)));
  kv_text(t_.get("labels", "rules"),
          fmt::format("{} — {}", b.rules_name.empty() ? b.spec.rules : b.rules_name,
                      b.rules_title));
  if (!b.rules_source.empty()) text(ws, r++, 1, b.rules_source, note());
  if (!b.rules_file.empty())
    text(ws, r++, 1, read_from(b.rules_file), note());
  if (!b.classes_name.empty()) {
    kv_text(t_.get("labels", "energy_classes"),
            b.classes_title.empty() ? b.classes_name
                                    : fmt::format("{} — {}", b.classes_name, b.classes_title));
    if (!b.classes_file.empty())
      text(ws, r++, 1, read_from(b.classes_file), note());
  }
  text(ws, r, 0, t_.get("labels", "crossings"), bold());
  count(ws, r++, 1, b.crossings);
  text(ws, r, 0, t_.get("labels", "not_reached"), bold());
  count(ws, r++, 1, b.not_reached);
  text(ws, r, 0, t_.get("labels", "bootstrap_seed"), bold());
  seed(ws, r++, 1, b.bootstrap_seed, number("general"));
  return r;
}

// The sample at the line: the one the design used (first crossings in the main direction), else
// the same taken from the report's crossings.
Report::BarrierSample Report::barrier_sample(const design::BarrierDesign& b) const {
  BarrierSample s;
  const auto li = line_index(b.spec.line);
  const int dir = d_.scenario ? d_.scenario->scenario.profile.main_direction() : 1;
  if (li && d_.samples && *li < d_.samples->lines().size()) {
    const design::LineSamples& ls = d_.samples->lines()[*li];
    s.speed = ls.speed;
    s.height = ls.height;
    for (double e : ls.translational_energy) s.energy.push_back(e / 1000);
    for (double e : ls.rotational_energy) s.rotational.push_back(e / 1000);
  } else if (li) {
    std::uint64_t last = std::numeric_limits<std::uint64_t>::max();
    for (const auto& c : d_.crossings) {
      if (c.line != *li || c.direction != dir || c.trajectory == last) continue;
      last = c.trajectory;
      s.speed.push_back(c.speed);
      s.height.push_back(c.height);
      s.energy.push_back(c.translational_energy / 1000);
      s.rotational.push_back(c.rotational_energy / 1000);
    }
  }
  return s;
}

// Statistics: one row per statistic, one column per quantity (the observed ones when given).
Row Report::barrier_statistics(lxw_worksheet* ws, Row r, const design::BarrierDesign& b,
                               const BarrierSample& sample) {
  r = table_title(ws, r, "statistics");
  std::vector<StatisticsColumn> qs = {
      {&b.speed, &b.speed.summary, "speed", "speed", &sample.speed},
      {&b.height, &b.height.summary, "height", "length", &sample.height},
      {&b.energy, &b.energy.summary, "energy", "energy", &sample.energy},
      {nullptr, &b.rotational_energy, "rotational_energy", "energy", &sample.rotational}};
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
  const char* rows[] = {"count", "mean", "sd", "min", "max", "p50", "p95", "weibull_k",
                        "weibull_lambda", "weibull_ks_d", "weibull_ks_p", "lognormal_mu",
                        "lognormal_sigma", "lognormal_ks_d", "lognormal_ks_p"};
  for (const char* stat : rows) {
    text(ws, r, 0, h("statistics", stat), bold());
    for (std::size_t i = 0; i < qs.size(); ++i) statistic(ws, r, static_cast<Col>(1 + i), stat, qs[i]);
    ++r;
  }
  for (const auto& q : qs)
    if (q.fit && !q.fit->error.empty())
      text(ws, r++, 0, fmt::format("{}: {}", h("statistics", q.key), q.fit->error), note());
  paragraph(ws, r++, 0, kBarrierNoteLast, kBarrierNoteWidth, t_.get("labels", "passing_height_note"),
            wrapped_note());
  return r;
}

// One cell of the statistics table; P50 and P95 are empirical (type 7) from the sample.
void Report::statistic(lxw_worksheet* ws, Row r, Col c, std::string_view s,
                       const StatisticsColumn& q) {
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
    return;
  } else if (s == "weibull_k" && q.fit->weibull) num(ws, r, c, q.fit->weibull->shape, number("parameter"));
  else if (s == "weibull_lambda" && q.fit->weibull) num(ws, r, c, q.fit->weibull->scale, qf);
  else if (s == "weibull_ks_d" && q.fit->weibull_ks) num(ws, r, c, q.fit->weibull_ks->statistic, number("parameter"));
  else if (s == "weibull_ks_p" && q.fit->weibull_ks) num(ws, r, c, q.fit->weibull_ks->p_value_stephens, number("p_value"));
  else if (s == "lognormal_mu" && q.fit->lognormal) num(ws, r, c, q.fit->lognormal->mu, number("parameter"));
  else if (s == "lognormal_sigma" && q.fit->lognormal) num(ws, r, c, q.fit->lognormal->sigma, number("parameter"));
  else if (s == "lognormal_ks_d" && q.fit->lognormal_ks) num(ws, r, c, q.fit->lognormal_ks->statistic, number("parameter"));
  else if (s == "lognormal_ks_p" && q.fit->lognormal_ks) num(ws, r, c, q.fit->lognormal_ks->p_value_stephens, number("p_value"));
}

// Bootstrap intervals of v_k, h_k, E_d and h_i.
Row Report::barrier_bootstrap(lxw_worksheet* ws, Row r, const design::BarrierDesign& b) {
  r = table_title(ws, r, "bootstrap");
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
  return r;
}

// The design values (Table 4.1's columns).
Row Report::barrier_design_values(lxw_worksheet* ws, Row r, const design::BarrierDesign& b) {
  r = table_title(ws, r, "design");
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
    num(ws, r, 7, b.energy_class->number, number(b.energy_class->open_ended ? "open_class" : "count"));
  else
    text(ws, r, 7, t_.get("labels", "none"));
  ++r;
  if (b.rotational_energy.count > 0)
    paragraph(ws, r++, 0, kBarrierNoteLast, kBarrierNoteWidth,
              // In the statistics table's decimals (energies to 0.1 kJ).
              replace_all(replace_all(t_.get("labels", "translational_energy_note"), "{mean}",
                                      fmt::format("{:.1f}", b.rotational_energy.mean)),
                          "{max}", fmt::format("{:.1f}", b.rotational_energy.max)),
              wrapped_note());
  return r;
}

// The factors and design quantities, with how each was obtained.
Row Report::barrier_factors(lxw_worksheet* ws, Row r, const design::BarrierDesign& b) {
  r = table_title(ws, r, "factors");
  headings(ws, r, 0, "factors", {"quantity", "value", "unit"});
  merged(ws, r, 3, 8, h("factors", "how"), heading());
  ++r;
  // How each was obtained: the design's own words (BarrierDesign::how), else the formula.
  auto fr = [&](std::string_view key, double v, std::string_view kind, std::string_view unit,
                const std::string& formula = {}) {
    text(ws, r, 0, h("factors", key), bold());
    num(ws, r, 1, v, number(kind));
    text(ws, r, 2, std::string(unit), indented());  // apart from the right-aligned value
    const auto it = b.how.find(std::string(key));
    // Under the merged heading (D:I, 6 columns of 14), wrapped: the derivations of the partial
    // factors ran off the printed page.
    paragraph(ws, r, 3, 8, 6 * 14, it != b.how.end() ? it->second : formula, wrap());
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
  if (b.gamma_d_MEL) fr("gamma_d_MEL", *b.gamma_d_MEL, "factor", "");
  if (b.gamma_d_SEL) fr("gamma_d_SEL", *b.gamma_d_SEL, "factor", "");
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
    text(ws, r, 1, b.residual_height_category);
    if (const auto it = b.how.find("residual_height_category"); it != b.how.end())
      paragraph(ws, r, 3, 8, 6 * 14, it->second, wrap());
    ++r;
  }
  return r;
}

// The probabilities of exceeding the barrier's capacities (Table 4.2's columns).
Row Report::barrier_exceedance(lxw_worksheet* ws, Row r, const design::BarrierDesign& b) {
  r = table_title(ws, r, "exceedance");
  // The observed column only with observed data: an empty column reads as values missing.
  const bool observed = std::any_of(b.exceedance.begin(), b.exceedance.end(),
                                    [](const design::ExceedanceRow& e) { return e.observed_weibull.has_value(); });
  headings(ws, r, 0, "exceedance",
           {"what", "threshold", "unit", "simulated_weibull", "simulated_empirical"});
  if (observed) headings(ws, r, 5, "exceedance", {"observed_weibull"});
  ++r;
  for (const auto& e : b.exceedance) {
    text(ws, r, 0, e.what, bold());
    num(ws, r, 1, e.threshold, number(e.unit == "kJ" ? "energy" : "length"));
    text(ws, r, 2, e.unit);
    num(ws, r, 3, e.simulated_weibull, number("probability"));
    num(ws, r, 4, e.simulated_empirical, number("probability"));
    if (e.observed_weibull) num(ws, r, 5, *e.observed_weibull, number("probability"));
    ++r;
  }
  return r;
}

// This barrier's check lines, then the design's notes.
Row Report::barrier_checks(lxw_worksheet* ws, Row r, const design::BarrierDesign& b) {
  if (!b.checks.empty()) {
    r = table_title(ws, r, "barrier_checks");
    // id in A (wide), what in B.. would be cut: keep Summary's columns minus the subject.
    r = check_table(ws, r, b.checks, false);
    if (std::any_of(b.checks.begin(), b.checks.end(), [](const design::CheckLine& l) {
          return l.rule.find("(verify)") != std::string::npos;
        }))
      paragraph(ws, r++, 0, kBarrierNoteLast, kBarrierNoteWidth,
                t_.get("labels", "verify_note"), wrapped_note());
  }
  if (!b.notes.empty()) {
    r = table_title(ws, r, "notes");
    for (const auto& n : b.notes) text(ws, r++, 0, n, note());
  }
  return r;
}

// The charts on a page of their own after the tables, a row of two per quantity; their data
// block below them stays on the sheet, out of the print area.
void Report::barrier_charts(lxw_worksheet* ws, const std::string& sheet, Row r,
                            const design::BarrierDesign& b, const BarrierSample& sample) {
  ++r;
  const Row chart_row = r;
  const Row rows_per_chart = static_cast<Row>(std::ceil(t_.chart_height / 20.0)) + 1;
  Row data_row = chart_row + 3 * rows_per_chart + 1;

  text(ws, data_row++, 0, t_.get("titles", "chart_data"), section());
  text(ws, data_row++, 0,
       replace_all(replace_all(replace_all(h("histogram", "source"), "{n}",
                                           std::to_string(sample.speed.size())),
                               "{line}", b.spec.line),
                   "{total}", std::to_string(b.crossings)),
       note());
  check(worksheet_print_area(ws, 0, 0, data_row - 3, 12), "worksheet_print_area");
  auto& breaks = breaks_.emplace_back(std::vector<lxw_row_t>{chart_row, 0});
  check(worksheet_set_h_pagebreaks(ws, breaks.data()), "worksheet_set_h_pagebreaks");

  const BarrierPlot plots[] = {{"speed", "speed", &sample.speed, &b.speed},
                               {"height", "length", &sample.height, &b.height},
                               {"energy", "energy", &sample.energy, &b.energy}};
  for (std::size_t p = 0; p < 3; ++p) {
    const BarrierChartData cd = barrier_chart_data(ws, data_row, plots[p]);
    data_row = std::max<Row>(cd.outline_end, cd.curves_last + 1) + 1;
    const Row at = chart_row + static_cast<Row>(p) * rows_per_chart;
    barrier_histogram_chart(ws, sheet, {at, 0}, plots[p], cd, b.spec.line);  // the line sampled
    // Right of the histogram: column A (34) + 3 columns of 14 ≈ 620 px at 7 px/char + padding.
    barrier_cdf_chart(ws, sheet, {at, 5}, plots[p], cd, b.spec.name);
  }
}

// A quantity's data block from `data_row`: the histogram's bins and the columns' outline, and on
// an even grid the fitted densities, the empirical CDF and the fitted CDFs.
Report::BarrierChartData Report::barrier_chart_data(lxw_worksheet* ws, Row data_row,
                                                    const BarrierPlot& pl) {
  const auto& x = *pl.sample;
  const auto& fit = *pl.fit;
  ++data_row;
  text(ws, data_row++, 0, h("statistics", pl.key), section());
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
  const Row o = outline_rows(ws, r0, 4, hg.lo, hg.width, hg.density, qf, number("parameter"));
  // Curves on an even grid.
  const int n = t_.curve_points;
  const std::vector<double> grid = even_grid(lo, hi, n), ecdf = sample_cdf(x, grid);
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
  return {r0, o, r0 + static_cast<Row>(n) - 1, lo, hi, !hg.counts.empty()};
}

// The histogram chart: the columns' outline, the Weibull and log-normal densities.
void Report::barrier_histogram_chart(lxw_worksheet* ws, const std::string& sheet, Cell at,
                                     const BarrierPlot& pl, const BarrierChartData& cd,
                                     const std::string& name) {
  const auto& fit = *pl.fit;
  if (!cd.columns && !fit.weibull && !fit.lognormal) return;
  const Row r0 = cd.r0, rn = cd.curves_last;
  lxw_chart* hc = scatter_chart(std::string(pl.key) + "_histogram", name);
  if (cd.columns)
    xy_series(hc, sheet, r0, cd.outline_end - 1, 4, 5, h("histogram", "histogram"),
              t_.colour("histogram"), 1.25f);
  if (fit.weibull)
    xy_series(hc, sheet, r0, rn, 6, 7, h("histogram", "weibull_pdf"), t_.colour("weibull"),
              2.0f);
  if (fit.lognormal)
    xy_series(hc, sheet, r0, rn, 6, 8, h("histogram", "lognormal_pdf"),
              t_.colour("lognormal"), 1.5f, LXW_CHART_LINE_DASH_DASH);
  curve_axes(hc, cd.lo, cd.hi);
  insert_chart(ws, at, hc);
}

// The CDF chart: empirical against fitted.
void Report::barrier_cdf_chart(lxw_worksheet* ws, const std::string& sheet, Cell at,
                               const BarrierPlot& pl, const BarrierChartData& cd,
                               const std::string& name) {
  const auto& fit = *pl.fit;
  if (pl.sample->empty() && !fit.weibull && !fit.lognormal) return;
  const Row r0 = cd.r0, rn = cd.curves_last;
  lxw_chart* cc = scatter_chart(std::string(pl.key) + "_cdf", name);
  if (!pl.sample->empty())
    xy_series(cc, sheet, r0, rn, 6, 9, h("histogram", "empirical_cdf"),
              t_.colour("empirical"), 2.0f);
  if (fit.weibull)
    xy_series(cc, sheet, r0, rn, 6, 10, h("histogram", "weibull_cdf"), t_.colour("weibull"),
              1.5f);
  if (fit.lognormal)
    xy_series(cc, sheet, r0, rn, 6, 11, h("histogram", "lognormal_cdf"),
              t_.colour("lognormal"), 1.5f, LXW_CHART_LINE_DASH_DASH);
  curve_axes(cc, cd.lo, cd.hi);
  chart_axis_set_max(cc->y_axis, 1);
  insert_chart(ws, at, cc);
}

}  // namespace pierre::io::detail
