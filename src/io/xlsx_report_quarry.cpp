// A quarry row's sheet (design-checks.md §2): the rules, the sections' geometry and counts,
// Tables 6.2/6.3, the fits, the exceedance distances, the governing distances, the zones and the
// check lines; its charts are in xlsx_report_quarry_charts.cpp. And the rows' table on Summary.
#include "xlsx_report_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace pierre::io::detail {

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
  r = table_title(ws, r, "quarry_summary");
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
  r = quarry_averages(ws, r);
  // Every section pooled (thesis Fig 6.5), when there is more than one row to pool.
  if (q.rows.size() > 1) {
    std::uint64_t thrown = 0;
    for (const auto& row : q.rows) thrown += row.thrown;
    const std::string& label = t_.get("labels", "quarry_all");
    text(ws, r, 0, label, bold());
    text(ws, r, 1, t_.get("labels", "calculated"), centred());
    num(ws, r, 3, static_cast<double>(thrown), number("count", 1));
    const auto &rd = q.all_rd_statistics, &id = q.all_id_statistics;
    Col c = 6;
    for (double v : {rd.p50_h, rd.p95_h, rd.max_h, id.p50_h, id.p95_h, id.max_h})
      distance(ws, r, c++, v, hf);
    ++r;
    text(ws, r++, 0, t_.get("labels", "quarry_all_note"), note());
  }
  return r;
}

// The thesis's last rows: means over the rows of the per-row ratios, calculated and observed.
Row Report::quarry_averages(lxw_worksheet* ws, Row r) {
  lxw_format* hf = number("factor", 1);
  const auto& a = d_.quarry->average;
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
  // Why the average rows have no number thrown: they are means of the rows' ratios.
  if (a.rows > 0)
    text(ws, r++, 0,
         replace_all(t_.get("labels", "quarry_average_note"), "{rows}", std::to_string(a.rows)),
         note());
  return r;
}

namespace {

// RD and ID: the calculated statistics and the observed values beside them.
struct Dist {
  std::string_view key;
  const design::DistanceStatistics* st;
  const std::optional<design::ObservedComparison>* obs;
};
std::array<Dist, 2> distances(const design::QuarryRow& row) {
  return {{{"rd", &row.rd, &row.observed_rd}, {"id", &row.id, &row.observed_id}}};
}

}  // namespace

void Report::quarry(lxw_worksheet* ws, const std::string& sheet, std::size_t ri) {
  const design::QuarryDesign& q = *d_.quarry;
  const design::QuarryRow& row = q.rows[ri];
  QuarrySections secs;
  for (std::size_t i : row.sections)
    if (i < q.sections.size()) secs.push_back(&q.sections[i]);
  page_setup(ws);
  width(ws, 0, 0, 38);  // "ID, first-impact distance from the toe" whole
  width(ws, 1, 13, 14);  // as a barrier sheet: the check table's merged columns fit its text
  text(ws, 0, 0, with_name(t_.get("titles", "quarry"), row.name), title());
  check(worksheet_set_row(ws, 0, 24, nullptr), "worksheet_set_row");
  Row r = quarry_overview(ws, 2, row, secs);
  r = quarry_geometry(ws, r, secs);
  r = quarry_counts(ws, r, row, secs);
  r = quarry_statistics(ws, r, row, secs);
  r = quarry_fits(ws, r, row);
  r = quarry_exceedance(ws, r, row, secs);
  r = quarry_governing(ws, r, row);
  r = quarry_zones(ws, r, secs);
  r = quarry_checks(ws, r, row, secs);
  quarry_charts(ws, sheet, r, row, secs);
}

// The rules, the sections pooled and where the observed values come from.
Row Report::quarry_overview(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                            const QuarrySections& secs) {
  auto label = [&](const std::string& l) { text(ws, r, 0, l, bold()); };
  label(t_.get("labels", "rules"));
  text(ws, r++, 1,
       secs.empty() || secs[0]->rules_title.empty()
           ? row.rules
           : fmt::format("{} — {}", row.rules, secs[0]->rules_title));
  if (!secs.empty() && !secs[0]->rules_source.empty()) text(ws, r++, 1, secs[0]->rules_source, note());
  if (!secs.empty() && !secs[0]->rules_file.empty())
    text(ws, r++, 1, read_from(secs[0]->rules_file), note());
  if (row.pooled) {
    std::string names;
    for (const auto* s : secs) names += (names.empty() ? "" : ", ") + s->spec.name;
    label(t_.get("labels", "pooled"));
    text(ws, r++, 1, names);
  }
  if (row.duration.count > 0) {
    label(t_.get("labels", "travel_time"));
    auto sec = [](double v) { return fmt::format("{:.3g}", v); };
    text(ws, r++, 1,
         replace_all(replace_all(replace_all(replace_all(t_.get("labels", "travel_time_value"),
                                                         "{p50}", sec(row.duration.p50)),
                                             "{p95}", sec(row.duration.p95)),
                                 "{max}", sec(row.duration.max)),
                     "{count}", std::to_string(row.duration.count)));
  }
  for (const auto* s : secs)
    if (!s->spec.observed_source.empty()) {
      label(t_.get("labels", "observed_source"));
      text(ws, r++, 1, row.pooled ? fmt::format("{}: {}", s->spec.name, s->spec.observed_source)
                                  : s->spec.observed_source);
    }
  return r;
}

// Geometry: crest, toe, H (given or found), and the seed of each section's run.
Row Report::quarry_geometry(lxw_worksheet* ws, Row r, const QuarrySections& secs) {
  lxw_format *xf = number("coordinate"), *lf = number("length"), *af = number("angle");
  r = table_title(ws, r, "quarry_geometry");
  headings(ws, r++, 0, "quarry_geometry",
           {"section", "crest_x", "crest_z", "crest_origin", "toe_x", "toe_z", "toe_origin",
            "height", "height_derived", "height_origin", "floor_angle", "floor_length", "seed"},
           45);
  for (const auto* s : secs) {
    const auto& g = s->geometry;
    if (const auto* v = section_view(s->spec.name)) seed(ws, r, 12, v->seed, number("general"));
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
  return r;
}

// How many blocks were thrown and where they went, per section and in total.
Row Report::quarry_counts(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                          const QuarrySections& secs) {
  r = table_title(ws, r, "quarry_counts");
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
  return r;
}

// Tables 6.2 / 6.3: calculated beside observed.
Row Report::quarry_statistics(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                              const QuarrySections& secs) {
  lxw_format *lf = number("length"), *hf = number("factor");
  r = table_title(ws, r, "quarry_statistics");
  headings(ws, r++, 0, "quarry_statistics",
           {"distance", "source", "count", "zeros", "censored", "p50", "p95", "p99", "max",
            "p50_h", "p95_h", "p99_h", "max_h"},
           30);
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
  for (const auto& dd : distances(row)) {
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
  return r;
}

// The log-normal mixture fits and the comparison with the observed values.
Row Report::quarry_fits(lxw_worksheet* ws, Row r, const design::QuarryRow& row) {
  lxw_format *hf = number("factor"), *pf = number("parameter");
  r = table_title(ws, r, "quarry_fits");
  headings(ws, r++, 0, "quarry_fits",
           {"distance", "zero_share", "mu", "sigma", "observed", "censored", "ks_d", "ks_p",
            "ks_below", "cdf_rmse", "observed_ks_d", "observed_ks_p", "fit_error"},
           45);
  for (const auto& dd : distances(row)) {
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
  return r;
}

// Distances at the asked probabilities of exceedance.
Row Report::quarry_exceedance(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                              const QuarrySections& secs) {
  lxw_format *lf = number("length"), *hf = number("factor");
  if (!row.exceedance.empty()) {
    r = table_title(ws, r, "quarry_exceedance");
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
      const auto fit_line = std::find_if(d_.quarry->checks.begin(), d_.quarry->checks.end(),
                                         [&](const design::CheckLine& l) {
                                           return l.subject == row.name && l.id == id &&
                                                  l.status == design::CheckStatus::warn;
                                         });
      if (fit_line == d_.quarry->checks.end() || !st->ks) continue;
      // Why: a p-value below the rule set's, or too few values for a p-value to say anything
      // ("doubtful (KS p = 0.839)" read as a contradiction; it was n = 5). A line that WARNs for
      // neither (a doubted input turns its PASS into a WARN) says nothing of the fit.
      const std::string p = fmt::format("{:.3g}", st->ks->p_value);
      std::string why;
      if (st->ks->p_value < fit_line->limit)
        why = fmt::format("KS p = {} < {:g}", p, fit_line->limit);
      else if (st->ks->observed < row.min_reached)
        why = fmt::format("from only {} values above zero, where KS p = {} says little",
                          st->ks->observed, p);
      else
        continue;
      text(ws, r++, 0,
           replace_all(replace_all(replace_all(t_.get("labels", "fit_doubtful"), "{what}", what),
                                   "{why}", why),
                       "{p}", p),
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
  return r;
}

// The governing distances, with how each was obtained.
Row Report::quarry_governing(lxw_worksheet* ws, Row r, const design::QuarryRow& row) {
  lxw_format *lf = number("length"), *hf = number("factor");
  r = table_title(ws, r, "quarry_governing");
  headings(ws, r, 0, "quarry_governing", {"quantity", "value_h", "value"});
  merged(ws, r, 3, 9, h("quarry_governing", "how"), heading());
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
    const std::string how = fmt::format("{:.6g} % bootstrap interval, {} resamples (estimate {:.3f} H)",
                                        100 * iv.confidence, iv.resamples, iv.estimate);
    gov("rd_lower", iv.lower, how);
    gov("rd_upper", iv.upper, how);
  }
  return r;
}

// The zones of each section, its bench and its work areas.
Row Report::quarry_zones(lxw_worksheet* ws, Row r, const QuarrySections& secs) {
  lxw_format* lf = number("length");
  r = table_title(ws, r, "quarry_zones");
  headings(ws, r, 0, "quarry_zones",
           {"section", "danger_zone", "first_impact_zone", "bench_width", "retention",
            "ritchie_width"},
           60);
  merged(ws, r, 6, 9, h("quarry_zones", "work_areas"), heading());
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
    merged(ws, r, 6, 9, areas, wrap());
    fit_row(ws, r, {{&strings_.back(), 52}, {&s->spec.name, 30}});
    ++r;
  }
  return r;
}

// This row's check lines: the row's own and its sections'.
Row Report::quarry_checks(lxw_worksheet* ws, Row r, const design::QuarryRow& row,
                          const QuarrySections& secs) {
  std::vector<design::CheckLine> lines;
  for (const auto& l : d_.quarry->checks) {
    bool mine = l.subject == row.name;
    for (const auto* s : secs) mine = mine || l.subject == s->spec.name;
    if (mine) lines.push_back(l);
  }
  if (!lines.empty()) {
    r = table_title(ws, r, "barrier_checks");
    r = check_table(ws, r, lines, false);
  }
  return r;
}

}  // namespace pierre::io::detail
