#include "pierre/design/quarry_zones.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "pierre/design/number_kind.hpp"
#include "pierre/design/number_text.hpp"
#include "pierre/stats/percentile.hpp"

namespace pierre::design {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// What to do when fewer blocks than min_reached reached the floor: with some stopped above the
// toe, look at the source and the face; with every one on the floor, too few were thrown.
std::string few_reached_advice(const QuarryRow& row) {
  return row.reached_floor < row.thrown
             ? "check that the source lies over the face, not behind the crest, or whether a "
               "ledge or bench above the toe held the blocks"
             : "more throws";
}

std::string num(double v, int precision = 4) {
  if (std::isinf(v)) return v > 0 ? "beyond the profile" : "-inf";
  return number_text(v, precision);
}

std::string rule_of(const QuarryRuleSet& r, const std::string& id) {
  auto it = r.clauses.find(id);
  if (it == r.clauses.end()) {
    const auto dot = id.find('.');
    if (dot != std::string::npos) it = r.clauses.find(id.substr(0, dot));
  }
  return it == r.clauses.end() ? r.name : r.name + " " + it->second;
}

double mean_of_finite(const std::vector<double>& v, std::size_t* n = nullptr) {
  double s = 0;
  std::size_t k = 0;
  for (double x : v)
    if (std::isfinite(x)) s += x, ++k;
  if (n) *n = k;
  return k ? s / static_cast<double>(k) : kNaN;
}

CheckLine line(const std::string& subject, const std::string& id, const QuarryRuleSet& rules) {
  CheckLine l;
  l.subject = subject;
  l.id = id;
  l.rule = rule_of(rules, id);
  return l;
}

}  // namespace

GoverningDistance governing_distance(const DistanceSample& sample, const DistanceStatistics& st,
                                     const QuarryRuleSet& rules) {
  GoverningDistance g;
  g.percentile_h = g.maximum_h = g.lognormal_h = kNaN;
  g.value_h = kNaN;
  std::string how;
  // "<label> 0.51 H", "<label> beyond the profile", or "<label>: no values" (an empty sample).
  // Two decimals of H, as the tables of /H (Tables 6.2/6.3) print them.
  auto of_h = [](double v_h) {
    return std::isfinite(v_h) ? fixed_text(v_h, 2) + " H" : num(v_h);
  };
  auto labelled = [&](const std::string& label, double v_h) {
    if (std::isnan(v_h)) return label + ": no values";
    return label + " " + of_h(v_h);
  };
  auto take = [&](double v, const std::string& text) {
    how += (how.empty() ? "" : ", ") + text;
    if (std::isnan(v)) return;
    g.value_h = std::isnan(g.value_h) ? v : std::max(g.value_h, v);
  };
  for (QuarryGoverning c : rules.governing) {
    switch (c) {
      case QuarryGoverning::percentile:
        g.percentile_h = censored_percentile(sample.normalized, sample.beyond, rules.percentile);
        take(g.percentile_h, labelled("P" + num(rules.percentile), g.percentile_h));
        break;
      case QuarryGoverning::maximum:
        g.maximum_h = st.max_h;
        take(g.maximum_h, labelled("maximum", g.maximum_h));
        break;
      case QuarryGoverning::lognormal:
        if (st.fit) {
          g.lognormal_h = stats::value_at_exceedance(*st.fit, 1.0 - rules.lognormal_percentile / 100.0);
          take(g.lognormal_h, "log-normal P" + num(rules.lognormal_percentile) + " " +
                                  of_h(g.lognormal_h));
        } else {
          take(kNaN, "log-normal P" + num(rules.lognormal_percentile) + ": no fit (" + st.fit_error + ")");
        }
        break;
    }
  }
  g.how = rules.governing.size() > 1 ? "larger of " + how : how;
  return g;
}

double governing_value_h(const DistanceSample& sample, const QuarryRuleSet& rules) {
  // governing_distance itself, on the statistics it reads made from the sample alone as
  // distance_statistics makes them, and only those the rule set's governing list names: the
  // bootstrap calls this once a resample.
  auto governs = [&](QuarryGoverning c) {
    return std::find(rules.governing.begin(), rules.governing.end(), c) != rules.governing.end();
  };
  DistanceStatistics st;
  if (governs(QuarryGoverning::maximum))
    st.max_h = censored_percentile(sample.normalized, sample.beyond, 100);
  if (governs(QuarryGoverning::lognormal)) {
    std::vector<double> finite;
    finite.reserve(sample.normalized.size());
    for (double x : sample.normalized)
      if (std::isfinite(x)) finite.push_back(x);
    if (const auto fit = stats::fit_censored_lognormal(finite, sample.censored_at)) st.fit = *fit;
  }
  return governing_distance(sample, st, rules).value_h;
}

std::optional<stats::BootstrapInterval> governing_interval(const DistanceSample& sample,
                                                           const QuarryRuleSet& rules,
                                                           std::uint64_t seed) {
  // A bootstrap of one value has no spread and says nothing: two at least.
  // Beyond the profile: no interval (sample_size_line says why).
  if (sample.normalized.size() < 2 || !std::isfinite(governing_value_h(sample, rules)))
    return std::nullopt;
  stats::BootstrapOptions opt;
  opt.resamples = rules.sample_resamples;
  opt.confidence = rules.sample_confidence;
  if (rules.governing == std::vector{QuarryGoverning::percentile}) {
    auto ci = stats::bootstrap_percentile_interval(sample.normalized, rules.percentile, seed, opt);
    return ci ? std::optional(*ci) : std::nullopt;
  }
  // Resample the blocks by index, so that a censored block keeps its own threshold (a pool's
  // sections have different floors).
  const std::size_t n = sample.normalized.size();
  std::vector<double> index(n), threshold(n, kNaN);
  for (std::size_t i = 0, c = 0; i < n; ++i) {
    index[i] = static_cast<double>(i);
    if (std::isinf(sample.normalized[i]) && c < sample.censored_at.size())
      threshold[i] = sample.censored_at[c++];
  }
  const stats::Statistic gov = [&](std::span<double> picked) {
    DistanceSample r;
    r.beyond = sample.beyond;
    r.normalized.reserve(picked.size());
    for (double x : picked) {
      const auto i = static_cast<std::size_t>(x);
      r.normalized.push_back(sample.normalized[i]);
      if (std::isinf(sample.normalized[i])) r.censored_at.push_back(threshold[i]);
    }
    return governing_value_h(r, rules);
  };
  auto ci = stats::bootstrap_interval(index, gov, seed, opt);
  return ci ? std::optional(*ci) : std::nullopt;
}

namespace {

// The rows of the tables: a lone section, or the sections of one group, in the order they first
// appear; and each section's result, its inputs copied. An error when one cannot be designed.
std::string group_rows(const std::vector<QuarrySectionInput>& in, QuarryDesign& d) {
  std::map<std::string, std::size_t> group_row;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const QuarrySectionInput& s = in[i];
    if (!(s.geometry.height > 0)) {
      return "section \"" + s.spec.name + "\" has no height H > 0";
    }
    std::size_t r;
    if (!s.spec.group.empty() && group_row.count(s.spec.group)) {
      r = group_row[s.spec.group];
      QuarryRow& row = d.rows[r];
      if (in[row.sections.front()].rules.name != s.rules.name) {
        return "sections of group \"" + s.spec.group + "\" use different rule sets (\"" +
               in[row.sections.front()].rules.name + "\", \"" + s.rules.name + "\")";
      }
      row.pooled = true;
    } else {
      r = d.rows.size();
      QuarryRow row;
      row.name = s.spec.group.empty() ? s.spec.name : s.spec.group;
      row.rules = s.rules.name;
      row.min_reached = s.rules.min_reached;
      d.rows.push_back(std::move(row));
      if (!s.spec.group.empty()) group_row[s.spec.group] = r;
    }
    QuarryRow& row = d.rows[r];
    row.throws = row.sections.empty() || row.throws == s.throws ? s.throws : 0;  // else unknown
    row.sections.push_back(i);
    QuarrySectionResult sr;
    sr.spec = s.spec;
    sr.rules_title = s.rules.title;
    sr.rules_source = s.rules.source;
    sr.rules_file = s.rules.file;
    sr.geometry = s.geometry;
    sr.distances = s.distances;
    sr.row = r;
    d.sections.push_back(std::move(sr));
  }
  return {};
}

// A row's pooled statistics (/H over its sections), counts, exceedance distances, governing
// distances, RD_gov's bootstrap interval (stream seed + r) and observed comparison; a group's
// sections get their own statistics too.
void pool_row(QuarryDesign& d, std::size_t r, const std::vector<QuarrySectionInput>& in,
              std::uint64_t seed) {
  QuarryRow& row = d.rows[r];
  const QuarrySectionInput& first = in[row.sections.front()];
  const QuarryRuleSet& rules = first.rules;
  std::vector<double> durations;
  double h_sum = 0;
  ObservedDistance obs_id, obs_rd;
  for (std::size_t i : row.sections) {
    const QuarrySectionInput& s = in[i];
    const QuarryDistances& q = s.distances;
    const double H = s.geometry.height;
    h_sum += H;
    row.id_sample.add(q.id, H, q.censor_distance);
    row.rd_sample.add(q.rd, H, q.censor_distance);
    if (row.sections.size() > 1) {  // a group: each section's own statistics too
      DistanceSample own_id, own_rd;
      own_id.add(q.id, H, q.censor_distance);
      own_rd.add(q.rd, H, q.censor_distance);
      d.sections[i].id = distance_statistics(own_id);
      d.sections[i].rd = distance_statistics(own_rd);
    }
    d.all_id.add(q.id, H, q.censor_distance);
    d.all_rd.add(q.rd, H, q.censor_distance);
    durations.insert(durations.end(), q.duration.begin(), q.duration.end());
    row.thrown += q.thrown;
    row.reached_floor += q.reached_floor;
    row.not_reached_floor += q.not_reached_floor;
    row.above_toe += q.above_toe;
    row.left_profile += q.left_profile;
    row.left_upslope += q.left_upslope;
    row.abnormal += q.abnormal;
    // Observed: raw values pooled; printed summary values from the first section giving them.
    for (auto [src, dst] : {std::pair{&s.observed.id, &obs_id}, std::pair{&s.observed.rd, &obs_rd}}) {
      dst->metres.insert(dst->metres.end(), src->metres.begin(), src->metres.end());
      dst->heights.insert(dst->heights.end(), src->metres.size(), H);
      if (!dst->p50 && !dst->p95 && !dst->max) {
        dst->p50 = src->p50;
        dst->p95 = src->p95;
        dst->max = src->max;
        dst->count = src->count;
      }
    }
  }
  row.height = h_sum / static_cast<double>(row.sections.size());
  row.id = distance_statistics(row.id_sample);
  row.rd = distance_statistics(row.rd_sample);
  if (row.sections.size() == 1) {
    d.sections[row.sections.front()].id = row.id;
    d.sections[row.sections.front()].rd = row.rd;
  }
  row.duration = duration_statistics(durations);
  for (double q : first.spec.exceedance) {
    ExceedanceDistance e;
    e.probability = q;
    e.rd_fit_h = row.rd.fit ? stats::value_at_exceedance(*row.rd.fit, q) : kNaN;
    e.id_fit_h = row.id.fit ? stats::value_at_exceedance(*row.id.fit, q) : kNaN;
    e.rd_empirical_h = empirical_at_exceedance(row.rd_sample, q);
    e.id_empirical_h = empirical_at_exceedance(row.id_sample, q);
    e.rd_fit = e.rd_fit_h * row.height;
    e.id_fit = e.id_fit_h * row.height;
    e.rd_empirical = e.rd_empirical_h * row.height;
    e.id_empirical = e.id_empirical_h * row.height;
    row.exceedance.push_back(e);
  }
  row.rd_gov = governing_distance(row.rd_sample, row.rd, rules);
  row.id_gov = governing_distance(row.id_sample, row.id, rules);
  row.rd_interval = governing_interval(row.rd_sample, rules, seed + r);
  if (!obs_id.empty()) row.observed_id = compare_observed(row.id_sample, obs_id, row.height);
  if (!obs_rd.empty()) row.observed_rd = compare_observed(row.rd_sample, obs_rd, row.height);
}

// A section's catch bench (bench_width given): bench.retention, the share of all its row's
// blocks stopping on it, and bench.ritchie, the modified Ritchie width as a cross-check.
void bench_checks(QuarrySectionResult& sr, const QuarryRow& row, const QuarryRuleSet& rules,
                  std::vector<CheckLine>& checks) {
  const double H = sr.geometry.height;
  const std::string& subject = sr.spec.name;
  const double w = *sr.spec.bench_width;
  const double above = empirical_exceedance(row.rd_sample.normalized, w / H);
  sr.bench_retention = std::isnan(above) ? kNaN : 1.0 - above;
  CheckLine l = line(subject, "bench.retention", rules);
  l.what = "share of all blocks stopping within the catch bench (RD <= " + num(w) + " m) vs the target";
  l.value = 100.0 * *sr.bench_retention;
  l.limit = 100.0 * rules.retention_target;
  l.unit = "%";
  if (std::isnan(l.value)) {
    l.status = CheckStatus::not_applicable;
    l.reason = "no runout sample";
  } else {
    l.status = at_least(*sr.bench_retention, rules.retention_target) ? CheckStatus::pass : CheckStatus::fail;
    const auto [value, limit] = compared_texts(l.value, l.limit, "%");
    l.reason = value + " of " + std::to_string(row.thrown) + " blocks retained " +
               (l.status == CheckStatus::pass ? ">= " : "< ") + limit;
    // Blocks that never passed the toe are "retained" by a bench they never reached: a full
    // bench from a section whose blocks stop on the face, or behind the crest, is no evidence.
    if (l.status == CheckStatus::pass && row.reached_floor < rules.min_reached) {
      l.status = CheckStatus::warn;
      l.reason += ", but only " + std::to_string(row.reached_floor) + " of them reached the floor (< " +
                  std::to_string(rules.min_reached) + ", the rule set's min_reached): " +
                  (row.reached_floor < row.thrown
                       ? "the others stopped above the toe and say nothing of the bench; "
                       : "too few blocks thrown: ") +
                  few_reached_advice(row);
    }
  }
  checks.push_back(std::move(l));

  sr.ritchie_width = rules.ritchie_factor * H + rules.ritchie_offset;
  CheckLine k = line(subject, "bench.ritchie", rules);
  k.what = "planned bench width vs the modified Ritchie width " + num(rules.ritchie_factor) +
           "·H + " + num(rules.ritchie_offset) + " m (an empirical cross-check, not a design rule)";
  k.value = w;
  k.limit = *sr.ritchie_width;
  k.unit = "m";
  k.status = at_least(w, k.limit) ? CheckStatus::pass : CheckStatus::warn;
  const auto [bench, ritchie] = compared_texts(w, k.limit, "m");
  k.reason = "bench " + bench + (at_least(w, k.limit) ? " >= " : " < ") + ritchie + " (H = " +
             quantity_text(H, "m") + ")";
  checks.push_back(std::move(k));
}

// Each section's zones from its row's governing distances, and its checks: zone.<work area>,
// zone.extent, bench.retention and bench.ritchie.
void section_checks(QuarryDesign& d, const QuarryRow& row, const QuarryRuleSet& rules) {
  for (std::size_t i : row.sections) {
    QuarrySectionResult& sr = d.sections[i];
    const double H = sr.geometry.height;
    const std::string& subject = sr.spec.name;
    sr.danger_zone = row.rd_gov.value_h * H;
    sr.first_impact_zone = row.id_gov.value_h * H;
    // A zone set by a log-normal the KS test rejects extrapolates a curve the blocks do not
    // follow: said where the zone is judged, not only on the row's fit.RD line.
    std::string fit_doubt;
    if (row.rd_gov.value_h == row.rd_gov.lognormal_h && row.rd.ks &&
        row.rd.ks->p_value < rules.fit_p_value)
      fit_doubt = "; RD_gov comes from a log-normal fit that fit.RD rejects (KS p = " +
                  num(row.rd.ks->p_value, 3) + " < " + num(rules.fit_p_value) +
                  "), against a simulated maximum of " + num(row.rd.max_h * H) +
                  (std::isfinite(row.rd.max_h) ? " m" : "");
    // The share of the section's blocks that stop beyond `at` (m from the toe; censored ones,
    // +inf, beyond anything): what a work area inside the zone is exposed to.
    auto share_beyond = [&](double at) {
      const std::vector<double>& rd = sr.distances.rd;
      const auto n = std::count_if(rd.begin(), rd.end(), [&](double x) { return x > at; });
      return rd.empty() ? std::string()
                        : "; " + num(100.0 * static_cast<double>(n) / static_cast<double>(rd.size()), 3) +
                              " % of the section's " + std::to_string(rd.size()) +
                              " simulated blocks stop beyond " + quantity_text(at, "m");
    };
    auto zone_line = [&](const std::string& id, const std::string& what, double value,
                         bool work_area) {
      CheckLine l = line(subject, id, rules);
      l.what = what;
      l.value = value;
      l.limit = sr.danger_zone;
      l.unit = "m";
      if (std::isnan(sr.danger_zone)) {
        l.status = CheckStatus::not_applicable;
        l.reason = "no runout sample";
      } else if (std::isinf(sr.danger_zone)) {
        l.status = CheckStatus::fail;
        // The cause is the governing rule's (a percentile, the maximum), said by its `how`.
        l.reason = "the danger zone reaches beyond the profile's end (" + row.rd_gov.how + "; " +
                   std::to_string(row.left_profile) + " of " + std::to_string(row.thrown) +
                   " blocks left the section); extend the section";
      } else {
        // In the decimals of the value and limit cells (more where those would read alike).
        const auto [at, zone] = compared_texts(value, sr.danger_zone, "m");
        const bool outside = at_least(value, sr.danger_zone);
        l.status = outside ? CheckStatus::pass : CheckStatus::fail;
        l.reason = at + " from the toe is " + (outside ? "outside" : "inside") +
                   " the danger zone: RD_gov = " + zone + " (" + row.rd_gov.how + ")" + fit_doubt;
        // Outside the zone, but not outside its bootstrap interval: the margin is within the
        // sampling uncertainty the sample.size line gives, so the PASS is not one to rely on.
        const double upper = row.rd_interval ? row.rd_interval->upper * H : kNaN;
        const bool in_interval = work_area && outside && std::isfinite(upper) && value < upper;
        // A group's pooled zone can fall short of one section's own percentile (Pauliberg A:
        // 12.43 m pooled against its own 12.46 m): an area between the two is outside the zone
        // the rule gives, but inside the one this face gives alone.
        const double own = work_area && row.pooled && outside
                               ? censored_percentile(sr.distances.rd, sr.distances.censor_distance,
                                                     rules.percentile)
                               : kNaN;
        const bool in_own = value < own;  // false for NaN
        if (in_interval || in_own) {
          l.status = CheckStatus::warn;
          std::string why;
          if (in_interval)
            why = within_interval_text("its", row.rd_interval->confidence, "up to " + quantity_text(upper, "m"));
          if (in_own)
            why += std::string(why.empty() ? "" : " and ") + "inside this section's own P" +
                   num(rules.percentile) + " (" +
                   (std::isfinite(own) ? quantity_text(own, "m") : std::string("beyond the profile")) +
                   "; the zone is the group's, pooled)";
          l.reason += ", but " + why + std::string(in_interval ? kWithinUncertainty : "");
        }
        // A zone from a handful of blocks on the floor (most stopped above the toe, or behind
        // the crest) is no zone to pass an area on: as sample.size says, too few reached it.
        if (work_area && l.status == CheckStatus::pass && row.reached_floor < rules.min_reached) {
          l.status = CheckStatus::warn;
          l.reason += ", but only " + std::to_string(row.reached_floor) + " of the " +
                      (row.pooled ? "group's " : "") + std::to_string(row.thrown) +
                      " blocks reached the floor (< " +
                      std::to_string(rules.min_reached) +
                      ", the rule set's min_reached): too few to say where the zone ends; " +
                      few_reached_advice(row);
        }
        if (work_area) l.reason += share_beyond(value);
        // An area past the modelled floor: no block was simulated over the ground there.
        if (value > sr.geometry.floor_length)
          l.reason += "; the area lies past the end of the section's floor (" +
                      quantity_text(sr.geometry.floor_length, "m") +
                      " from the toe), on ground the section does not model: extend it";
      }
      d.checks.push_back(std::move(l));
    };
    for (const WorkArea& a : sr.spec.work_areas)
      zone_line("zone." + a.name, "distance of work area \"" + a.name + "\" from the toe vs the danger zone RD_gov", a.distance, true);
    if (std::isinf(sr.danger_zone) && sr.spec.work_areas.empty()) {
      // RD_p beyond the profile FAILs its check (design-checks.md §2): without a work area
      // this is the line that carries it.
      zone_line("zone.extent", "the danger zone RD_gov vs the section's floor length", sr.geometry.floor_length, false);
    } else if (sr.danger_zone_beyond_profile() && std::isfinite(sr.danger_zone)) {
      // A finite zone longer than the floor the section models (a fit's extrapolation, or a
      // group's pooled zone on a section with a shorter floor): its end was not simulated.
      // The zone lines judge against it as the spec has them; this says how far to trust it.
      CheckLine l = line(subject, "zone.extent", rules);
      l.what = "the section's floor length vs the danger zone RD_gov";
      l.value = sr.geometry.floor_length;
      l.limit = sr.danger_zone;
      l.unit = "m";
      l.status = CheckStatus::warn;
      const auto [floor, zone] = compared_texts(sr.geometry.floor_length, sr.danger_zone, "m");
      l.reason = "RD_gov = " + zone + " (" + row.rd_gov.how + ") reaches past the floor's end at " +
                 floor + " from the toe: the zone's end is extrapolated, not simulated; extend the "
                 "section to simulate it" + fit_doubt;
      d.checks.push_back(std::move(l));
    }

    if (sr.spec.bench_width) bench_checks(sr, row, rules, d.checks);
  }
}

// The governing rule in words: "P95", "larger of maximum and log-normal P99".
std::string governing_rule_text(const QuarryRuleSet& rules) {
  std::string t;
  for (std::size_t i = 0; i < rules.governing.size(); ++i) {
    t += i == 0 ? "" : i + 1 == rules.governing.size() ? " and " : ", ";
    switch (rules.governing[i]) {
      case QuarryGoverning::percentile: t += "P" + num(rules.percentile); break;
      case QuarryGoverning::maximum: t += "maximum"; break;
      case QuarryGoverning::lognormal: t += "log-normal P" + num(rules.lognormal_percentile); break;
    }
  }
  return rules.governing.size() > 1 ? "larger of " + t : t;
}

// sample.size of a row: the relative half-width of RD_gov's bootstrap interval against the
// tolerance (design-checks.md §1 step 8 bootstraps the design values; RD_gov is the quarry's),
// and the blocks that reached the floor against the minimum.
CheckLine sample_size_line(const QuarryRow& row, const QuarryRuleSet& rules) {
  const std::string conf = num(100 * rules.sample_confidence, 6) + " %";
  CheckLine l = line(row.name, "sample.size", rules);
  l.what = "half-width of the " + conf + " bootstrap interval of RD_gov (" +
           governing_rule_text(rules) + ") / RD_gov, and blocks reaching the floor (>= " +
           std::to_string(rules.min_reached) + ")";
  l.limit = 100.0 * rules.sample_tolerance;
  l.unit = "%";
  std::string why;
  bool warn = false;
  if (row.rd_interval && row.rd_interval->estimate > 0 &&
      !std::isfinite(row.rd_interval->half_width())) {
    // Resamples with more blocks off the end than the rule allows: the interval's upper end
    // is beyond the profile, and no number of throws on this section closes it.
    warn = true;
    why = "the " + conf + " interval of RD_gov reaches beyond the profile (" +
          std::to_string(row.left_profile) + " of " + std::to_string(row.thrown) +
          " blocks left the section): extend the section";
  } else if (row.rd_interval && row.rd_interval->estimate > 0) {
    const double rel = row.rd_interval->half_width() / row.rd_interval->estimate;
    l.value = 100.0 * rel;
    if (rel > rules.sample_tolerance) {
      warn = true;
      const SampleNeeded needed =
          sample_needed(static_cast<double>(row.thrown), row.throws, rel, rules.sample_tolerance);
      const auto [value, limit] = compared_texts(l.value, l.limit, "%");
      why = "RD_gov known to ±" + value + " > " + limit + ": about " +
            number_text(needed.trajectories, 9) + " trajectories would be needed (" +
            std::to_string(row.thrown) + " run)" + throws_needed_text(needed);
    } else {
      why = "RD_gov known to ±" + quantity_text(l.value, "%");
    }
  } else {
    why = std::isinf(row.rd_gov.value_h) ? "RD_gov is beyond the profile: no interval"
                                         : "no bootstrap interval";
  }
  if (row.reached_floor < rules.min_reached) {
    warn = true;
    why += "; only " + std::to_string(row.reached_floor) +
           (row.reached_floor == 1 ? " block" : " blocks") + " reached the floor (< " +
           std::to_string(rules.min_reached) + ")";
  }
  l.status = warn ? CheckStatus::warn : (std::isnan(l.value) ? CheckStatus::not_applicable : CheckStatus::pass);
  l.reason = why;
  return l;
}

// observed.ID and observed.RD of a row with observed values: the field's P95 against the
// governing distance. The thesis validates the model on exactly these values (Tables 6.2,
// 6.3, calculated beside observed); a zone drawn shorter than what was seen at the face
// rests on a calibration the field contradicts, whatever the fits say.
void observed_checks(QuarryDesign& d, const QuarryRow& row, const QuarryRuleSet& rules) {
  const std::pair<const char*, const std::optional<ObservedComparison>*> kinds[] = {
      {"ID", &row.observed_id}, {"RD", &row.observed_rd}};
  for (const auto& [name, obs] : kinds) {
    if (!*obs) continue;
    const std::string what(name);
    const GoverningDistance& gov = what == "ID" ? row.id_gov : row.rd_gov;
    CheckLine l = line(row.name, "observed." + what, rules);
    l.what = "observed P95 of " + what + " (field values) vs " + what + "_gov";
    l.unit = "m";
    const ObservedComparison& o = **obs;
    const std::string n = o.count > 0 ? " (n = " + std::to_string(o.count) + ")" : "";
    // Judged in /H, where each observation carries its own face's H, and shown in metres at the
    // row's H: for observations at this face, the observed P95 itself.
    l.value = o.at_row_height ? o.p95 : o.p95_h * row.height;
    l.limit = gov.value_h * row.height;
    if (std::isnan(o.p95_h) || std::isnan(gov.value_h)) {
      l.status = CheckStatus::not_applicable;
      l.reason = std::isnan(o.p95_h) ? "no observed P95" : "no simulated " + what + " sample";
    } else if (std::isinf(gov.value_h)) {
      l.status = CheckStatus::pass;
      l.reason = what + "_gov is beyond the profile (" + gov.how + ")";
    } else {
      const bool covered = at_least(gov.value_h, o.p95_h);
      const auto [seen, zone] = compared_texts(l.value, l.limit, "m");
      l.status = covered ? CheckStatus::pass : CheckStatus::warn;
      // Covered, but RD_gov's own bootstrap interval reaches below what was seen: as for the
      // zone lines, a margin inside the sampling uncertainty is not one to rely on.
      const double lower = what == "RD" && row.rd_interval ? row.rd_interval->lower * row.height : kNaN;
      const bool in_interval = covered && std::isfinite(lower) && l.value > lower;
      l.reason = "observed P95 " + seen + n + (covered ? " <= " : " > ") + what + "_gov " + zone +
                 " (" + gov.how + ")" +
                 (covered ? ""
                          : std::string(what == "ID" ? ": blocks at the face first struck the floor"
                                                     : ": blocks at the face ran out") +
                                " farther from the toe than the simulation has them; check the "
                                "materials and roughness against the observations before "
                                "relying on the " +
                                (what == "ID" ? "first-impact zone" : "danger zone"));
      if (in_interval) {
        l.status = CheckStatus::warn;
        l.reason += ", but " +
                    within_interval_text("RD_gov's", row.rd_interval->confidence,
                                         "down to " + quantity_text(lower, "m")) +
                    std::string(kWithinUncertainty);
      }
    }
    d.checks.push_back(std::move(l));
  }
}

// A row's own checks: sample.size, fit.ID, fit.RD, and observed.ID and observed.RD with
// observed values.
void row_checks(QuarryDesign& d, const QuarryRow& row, const QuarryRuleSet& rules) {
  d.checks.push_back(sample_size_line(row, rules));
  for (auto [id, st] : {std::pair<std::string, const DistanceStatistics*>{"fit.ID", &row.id},
                        std::pair<std::string, const DistanceStatistics*>{"fit.RD", &row.rd}}) {
    CheckLine l = line(row.name, id, rules);
    l.what = "KS p-value of the log-normal fit of " + id.substr(4) +
             "/H, over the values above zero (the zeros are the fit's point mass; censored "
             "runouts as censored)";
    l.limit = rules.fit_p_value;
    if (st->fit && st->ks) {
      l.value = st->ks->p_value;
      const bool rejected = l.value < l.limit;
      // As a barrier's fit lines: a KS test on a handful of values rejects almost no fit.
      const bool few = st->ks->observed < rules.min_reached;
      l.status = rejected || few ? CheckStatus::warn : CheckStatus::pass;
      const std::string censored =
          st->ks->observed < st->ks->n
              ? " (" + std::to_string(st->ks->observed) + " below the censoring point)"
              : std::string();
      l.reason = "D = " + num(st->ks->statistic, 3) + ", n = " + std::to_string(st->ks->n) +
                 " values above zero" + censored + ", p = " + num(l.value, 3) +
                 (rejected ? " < " : " >= ") +
                 num(l.limit) +
                 (few && !rejected ? ", but from fewer than the " + std::to_string(rules.min_reached) +
                                         " values the rule set asks (min_reached): a test on so "
                                         "few values rejects almost no fit"
                                   : " (parameters fitted to the same sample: p is optimistic)");
    } else {
      l.status = CheckStatus::warn;
      l.reason = "no fit: " + (st->fit_error.empty() ? std::string("no KS statistic") : st->fit_error);
    }
    d.checks.push_back(std::move(l));
  }
  observed_checks(d, row, rules);
}

// The averages over the rows (thesis Tables 6.2 and 6.3, last line).
QuarryAverage average_of_rows(const std::vector<QuarryRow>& rows) {
  QuarryAverage a;
  a.rows = rows.size();
  std::vector<double> v[6], o[6];
  for (const QuarryRow& row : rows) {
    v[0].push_back(row.rd.p50_h), v[1].push_back(row.rd.p95_h), v[2].push_back(row.rd.max_h);
    v[3].push_back(row.id.p50_h), v[4].push_back(row.id.p95_h), v[5].push_back(row.id.max_h);
    if (row.observed_rd || row.observed_id) ++a.observed_rows;
    if (row.observed_rd)
      o[0].push_back(row.observed_rd->p50_h), o[1].push_back(row.observed_rd->p95_h),
          o[2].push_back(row.observed_rd->max_h);
    if (row.observed_id)
      o[3].push_back(row.observed_id->p50_h), o[4].push_back(row.observed_id->p95_h),
          o[5].push_back(row.observed_id->max_h);
  }
  // A row beyond the profile makes the average beyond it too.
  auto mean = [](const std::vector<double>& x) {
    for (double y : x)
      if (std::isinf(y)) return kInf;
    return mean_of_finite(x);
  };
  a.rd50_h = mean(v[0]), a.rd95_h = mean(v[1]), a.rdmax_h = mean(v[2]);
  a.id50_h = mean(v[3]), a.id95_h = mean(v[4]), a.idmax_h = mean(v[5]);
  a.obs_rd50_h = mean(o[0]), a.obs_rd95_h = mean(o[1]), a.obs_rdmax_h = mean(o[2]);
  a.obs_id50_h = mean(o[3]), a.obs_id95_h = mean(o[4]), a.obs_idmax_h = mean(o[5]);
  return a;
}

}  // namespace

QuarryOutcome design_quarry(const std::vector<QuarrySectionInput>& in, std::uint64_t seed) {
  QuarryOutcome result;
  if (in.empty()) {
    result.error = "no quarry section";
    return result;
  }
  QuarryDesign d;
  if (std::string error = group_rows(in, d); !error.empty()) {
    result.error = std::move(error);
    return result;
  }
  for (std::size_t r = 0; r < d.rows.size(); ++r) {
    const QuarryRuleSet& rules = in[d.rows[r].sections.front()].rules;  // one per row
    pool_row(d, r, in, seed);
    section_checks(d, d.rows[r], rules);
    row_checks(d, d.rows[r], rules);
  }
  d.average = average_of_rows(d.rows);
  d.all_id_statistics = distance_statistics(d.all_id);
  d.all_rd_statistics = distance_statistics(d.all_rd);
  result.design = std::move(d);
  return result;
}

std::vector<DoubtedInput> pooled_doubts(const QuarryDesign& design, std::vector<DoubtedInput> doubts) {
  const std::size_t given = doubts.size();
  for (std::size_t k = 0; k < given; ++k) {
    const DoubtedInput d = doubts[k];  // a copy: push_back may move doubts[k]
    for (const QuarryRow& row : design.rows) {
      const bool in_row = std::any_of(row.sections.begin(), row.sections.end(), [&](std::size_t i) {
        return design.sections[i].spec.name == d.subject;
      });
      if (!in_row) continue;
      // The row's own lines (a group's, even of one section): its distances are this section's.
      if (row.name != d.subject) {
        doubts.push_back(d);
        doubts.back().subject = row.name;
      }
      // The other sections' lines, only for an input of the simulation (blocks, sources: every
      // line, no ids): their zones come from the pooled distances. A bench width or a work area
      // (ids given) is the section's own.
      if (!d.ids.empty()) continue;
      for (std::size_t i : row.sections)
        if (design.sections[i].spec.name != d.subject) {
          doubts.push_back(d);
          doubts.back().subject = design.sections[i].spec.name;
        }
    }
  }
  return doubts;
}

}  // namespace pierre::design
