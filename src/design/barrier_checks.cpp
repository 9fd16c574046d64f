// The check lines of a barrier (design-checks.md §1, "Check lines"), from a computed design.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pierre/design/barrier_check.hpp"

#include "pierre/design/number_kind.hpp"
#include "pierre/design/number_text.hpp"

namespace pierre::design {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string num(double v, int sig = 4) { return std::isnan(v) ? "n/a" : number_text(v, sig); }
std::string pct(double p) { return std::isnan(p) ? "n/a" : num(100 * p, 3) + " %"; }

struct Builder {
  const BarrierDesign& d;
  const BarrierRuleSet& r;
  std::vector<CheckLine> lines;

  CheckLine& add(const std::string& id, std::string what, double value, double limit,
                 std::string unit) {
    CheckLine l;
    l.subject = d.spec.name;
    l.id = id;
    l.what = std::move(what);
    l.value = value;
    l.limit = limit;
    l.unit = std::move(unit);
    l.rule = rule_reference(r, id);
    lines.push_back(std::move(l));
    return lines.back();
  }
};

void set(CheckLine& l, CheckStatus s, std::string reason) {
  l.status = s;
  l.reason = std::move(reason);
}

// A PASS whose margin lies within the requirement's bootstrap interval (upper bound `upper`,
// NaN when there is none) is not one to rely on: a WARN that says so (the sample.size line
// gives the interval's width).
void within_interval(CheckLine& l, double value, double upper, const char* unit,
                     double confidence) {
  if (l.status != CheckStatus::pass || !std::isfinite(upper) || !(value < upper)) return;
  l.status = CheckStatus::warn;
  l.reason += ", but " + within_interval_text("the requirement's", confidence, "up to " + quantity_text(upper, unit)) +
              std::string(kWithinUncertainty);
}

// `declares_energy`: the candidate gives some capacity (a class, a MEL or a SEL). One that gives
// none is checked on its height alone, and the line WARNs that its capacity was not compared
// (an N/A would read, in a pipeline, like a check that does not apply); one that gives a capacity
// but not the one the rule set designs on cannot pass that check. `upper`, `confidence`: the
// requirement's bootstrap interval (within_interval).
void capacity_line(Builder& b, const char* id, const char* name, bool needed, double declared,
                   double required, bool declares_energy, double upper, double confidence) {
  CheckLine& l = b.add(id, std::string("candidate ") + name + " against the required " + name +
                               " (γE · E_d)",
                       declared, required, "kJ");
  if (!needed) {
    // Not a requirement, but a kit whose capacity is below it is one the design event exceeds
    // (a service-level overload): said, for information.
    std::string why = std::string("the rule set designs on ") + to_string(b.r.design_on) + ", not " + name;
    if (!std::isnan(declared) && !at_least(declared, required)) {
      const auto [has, needs] = compared_texts(declared, required, "kJ");
      why += std::string(" (for information: the candidate's ") + name + " " + has + " is below " +
             name + "_req " + needs + ")";
    }
    set(l, CheckStatus::not_applicable, why);
  }
  else if (std::isnan(declared)) {
    const std::string missing = std::string("the candidate declares no ") + name + " (give " +
                                (std::string(name) == "MEL" ? "mel" : "sel") +
                                ", or an energy_class whose " + name + " the class table holds)";
    if (!declares_energy)
      set(l, CheckStatus::warn, missing + ": required " + quantity_text(required, "kJ") +
                                    " not compared");
    else
      set(l, CheckStatus::fail,
          "the rule set designs on " +
              std::string(b.r.design_on == DesignOn::both ? "MEL and SEL" : to_string(b.r.design_on)) +
              " and " + missing);
  }
  else {
    const auto [has, needs] = compared_texts(declared, required, "kJ");
    const bool pass = at_least(declared, required);
    set(l, pass ? CheckStatus::pass : CheckStatus::fail,
        std::string("candidate ") + name + " " + has + (pass ? " >= " : " < ") + "required " + needs);
    within_interval(l, declared, upper, "kJ", confidence);
  }
}

void elongation_line(Builder& b, const CandidateBarrier& c) {
  struct Test {
    const char* name;
    std::optional<double> gamma_d, elongation;
    bool governs;
  };
  const Test tests[] = {{"MEL", b.r.gamma_d_MEL, c.elongation_mel, needs_mel(b.r.design_on)},
                        {"SEL", b.r.gamma_d_SEL, c.elongation_sel, needs_sel(b.r.design_on)}};
  double limit = kNaN;
  std::string how;
  bool rule_has = false;
  for (const Test& t : tests) {
    if (!t.governs || !t.gamma_d) continue;
    rule_has = true;
    if (!t.elongation) continue;
    const double need = *t.gamma_d * *t.elongation;
    if (std::isnan(limit) || need > limit) {
      limit = need;
      how = std::string("γd · elongation (") + t.name + " test) = " + num(*t.gamma_d) + " × " +
            num(*t.elongation) + " m";
    }
  }
  const double value = c.distance_to_object.value_or(kNaN);
  CheckLine& l = b.add("elongation",
                       "distance from the barrier to the protected object against γd times the "
                       "declared maximum elongation of the governing test",
                       value, limit, "m");
  if (!rule_has)
    set(l, CheckStatus::not_applicable, "not applicable: the rule set has no γd for its design test");
  else if (std::isnan(limit) || std::isnan(value))
    set(l, CheckStatus::not_applicable,
        "not applicable: the candidate does not declare both the elongation of the governing "
        "test and distance_to_object");
  else {
    const auto [has, needs] = compared_texts(value, limit, "m");
    const bool pass = at_least(value, limit);
    set(l, pass ? CheckStatus::pass : CheckStatus::fail,
        "distance " + has + (pass ? " >= " : " < ") + how + " = " + needs);
  }
}

// Value and limit in % (unit "%"), as the reason words them and as sample.size is; judged on the
// fractions.
// The values a Weibull fit stands on, when fewer than the rule set asks of a line (reach): its
// tail and its KS test then say little, and a line that would PASS on them WARNs instead (a
// FAIL stays a FAIL). Empty when the fit has enough.
std::string too_few_values(const Builder& b, const QuantityFit& q) {
  if (!q.weibull || static_cast<double>(q.weibull->used) >= b.r.min_crossings) return {};
  return "from " + std::to_string(q.weibull->used) + " value" + (q.weibull->used == 1 ? "" : "s") +
         ", fewer than the " + num(b.r.min_crossings) + " crossings the rule set asks (reach)";
}

// Whether the fit line of `q` rejects its Weibull fit (KS p below the rule set's).
bool fit_rejected(const Builder& b, const QuantityFit& q) {
  return q.weibull_ks && q.weibull_ks->p_value_stephens < b.r.fit_p_value;
}

// A characteristic value the design takes from its Weibull fit, below the sample's own percentile.
bool weibull_below_own(const Characteristic& c) {
  return c.value == c.weibull && c.empirical > c.weibull;
}

// A Weibull fit its own fit line rejects (KS p below the rule set's): its tail is no basis to
// pass either. Empty when the fit stands.
// "a Weibull fit that fit.E rejects (p = 0.01)": the words every line uses for such a fit.
std::string rejected_weibull(const QuantityFit& q, const char* fit_id) {
  return std::string("a Weibull fit that ") + fit_id + " rejects (p = " +
         num(q.weibull_ks->p_value_stephens, 3) + ")";
}

std::string rejected_fit(const Builder& b, const QuantityFit& q, const char* fit_id, double empirical) {
  if (!fit_rejected(b, q)) return {};
  return rejected_weibull(q, fit_id) + "; of the simulated values themselves " + pct(empirical) +
         " exceed";
}

// A characteristic value (v_k, h_k) taken from a Weibull fit that its own fit line rejects and
// lying below the simulated values' own percentile: a rule set that designs on the fit
// (thesis-2015) takes it whatever the KS says, and the requirement is then the lower of the two
// the procedure could give. A capacity line that passes only on that one is a WARN, its reason
// giving the requirement from the simulated values' own percentile (`alt_required`, in the
// line's unit). `what`: "v_k", `unit` of the characteristic value.
void below_own_percentile(const Builder& b, CheckLine& l, const Characteristic& c,
                          const QuantityFit& q, const char* fit_id, const char* what,
                          const char* unit, double alt_required) {
  if (l.status != CheckStatus::pass || !weibull_below_own(c) || !fit_rejected(b, q) ||
      at_least(l.value, alt_required))
    return;
  l.status = CheckStatus::warn;
  l.reason += std::string(", but ") + what + " " + quantity_text(c.value, unit) +
              " comes from " + rejected_weibull(q, fit_id) + ", below the simulated values' own P" +
              num(b.r.percentile) + " " + quantity_text(c.empirical, unit) +
              ", with which the requirement would be " + quantity_text(alt_required, l.unit);
}

// The candidate's own capacity (its MEL, its height) where the spec's probability is taken at
// the required one (MEL_req, h_i): `name` ("MEL"), its value, its unit and its capacity line.
struct OwnCapacity {
  const char* name;
  double value;
  const char* unit;
  const char* line;
  // For a FAIL, which the candidate cannot mend: the requirement judged ("MEL_req"), the
  // simulated quantity ("energies") and what raises the requirement besides the rule set.
  const char* required;
  const char* quantity;
  const char* raised_by;
};

// `row`: its column of Table 4.2 (none without a design). The line judges P(X > required), as
// design-checks.md §1 fixes it, whatever the candidate; a candidate below the requirement is
// exceeded more often: the reason adds how often, and a PASS becomes a WARN.
void exceedance_line(Builder& b, const char* id, const std::string& what, const ExceedanceRow* row,
                     std::optional<double> acceptable, const QuantityFit& fit, const char* fit_id,
                     const OwnCapacity& own) {
  const double p = row ? row->simulated_weibull : kNaN;
  CheckLine& l = b.add(id, what, 100 * p, 100 * acceptable.value_or(kNaN), "%");
  const std::string few = too_few_values(b, fit);
  const std::string rejected = rejected_fit(b, fit, fit_id, row ? row->simulated_empirical : kNaN);
  if (!acceptable)
    set(l, CheckStatus::not_applicable, "no acceptable probability given (" + pct(p) + ")");
  else if (std::isnan(p))
    set(l, CheckStatus::fail, "cannot be evaluated: no Weibull fit of the simulated sample");
  else if (at_most(p, *acceptable) && !few.empty())
    set(l, CheckStatus::warn, pct(p) + " <= acceptable " + pct(*acceptable) +
                                  ", but the Weibull fit is " + few +
                                  ": its tail is no basis to pass (more throws)");
  else if (at_most(p, *acceptable) && !rejected.empty())
    set(l, CheckStatus::warn, pct(p) + " <= acceptable " + pct(*acceptable) + ", but from " +
                                  rejected + ": its tail is no basis to pass");
  else if (at_most(p, *acceptable))
    set(l, CheckStatus::pass, pct(p) + " <= acceptable " + pct(*acceptable));
  else {
    // The requirement itself is exceeded too often: no candidate mends that, the design values
    // do. It is the fit's tail that says so (design-checks.md §1), which the simulated values'
    // own share may not bear out: both are given, and a rejected fit is named (user review: "the
    // simulated energies exceed" read as a fact where none of 2 130 did).
    set(l, CheckStatus::fail, pct(p) + " > acceptable " + pct(*acceptable) + ": the Weibull fit of the simulated " +
                                  own.quantity + " exceeds the design's own " + own.required + " " +
                                  quantity_text(row->threshold, own.unit) +
                                  " too often, whatever the candidate (the rule set's percentile "
                                  "and partial factors (data_quality) raise it, and " +
                                  own.raised_by + "); of the simulated values themselves " +
                                  pct(row->simulated_empirical) + " exceed it");
    if (!rejected.empty())
      l.reason += "; it is " + rejected_weibull(fit, fit_id) +
                  ": the line judges its tail all the same, as the rule is written; compare "
                  "the simulated share";
    if (!few.empty()) l.reason += "; the Weibull fit is " + few + ": more throws";
  }
  if (row && !std::isnan(p) && l.status == CheckStatus::fail && at_least(own.value, row->threshold))
    l.reason += std::string("; the candidate's own ") + own.name + " " +
                quantity_text(own.value, own.unit) + " is exceeded with " +
                pct(weibull_exceedance(fit, own.value));
  if (row && own.value < row->threshold) {
    // Not a PASS beside the FAIL of the candidate's own capacity line: the line still judges
    // the spec's value, and says what it does not cover (in the capacity line's numbers).
    const bool failed = l.status == CheckStatus::fail;
    if (l.status == CheckStatus::pass) l.status = CheckStatus::warn;
    const auto [has, needs] = compared_texts(own.value, row->threshold, own.unit);
    l.reason += std::string(failed ? "; and" : "; but") + " the candidate's own " + own.name +
                " " + has + " is below the required " + needs + " (" + own.line +
                ") and is exceeded " + (failed ? "still more often, with " : "with ") +
                pct(weibull_exceedance(fit, own.value));
  }
}

// `c`, `what`, `unit`: the characteristic value this fit gives (v_k, h_k; none for E), whose
// fit rejected is said with it when the design takes it below the sample's own percentile.
void fit_line(Builder& b, const char* id, const char* quantity, const QuantityFit& q,
              const Characteristic* c = nullptr, const char* what = "", const char* unit = "") {
  const double p = q.weibull_ks ? q.weibull_ks->p_value_stephens : kNaN;
  CheckLine& l = b.add(id,
                       std::string("Kolmogorov–Smirnov p-value (Stephens) of the Weibull fit of ") +
                           quantity,
                       p, b.r.fit_p_value, "");
  if (std::isnan(p))
    set(l, CheckStatus::warn, "no Weibull fit: " + (q.error.empty() ? std::string("too few values") : q.error));
  else if (p < b.r.fit_p_value)
    set(l, CheckStatus::warn,
        "p = " + num(p, 3) + " < " + num(b.r.fit_p_value) +
            ": the Weibull fit is doubtful (D = " + num(q.weibull_ks->statistic, 3) + "); " +
            (c && weibull_below_own(*c)
                 ? std::string("the design takes ") + what + " from it, " +
                       quantity_text(c->weibull, unit) + ", below the simulated values' own P" +
                       num(b.r.percentile) + " " + quantity_text(c->empirical, unit) +
                       ": its requirements are the lower of the two"
                 : std::string("compare the empirical value")));
  else if (const std::string few = too_few_values(b, q); !few.empty())
    set(l, CheckStatus::warn, "p = " + num(p, 3) + " >= " + num(b.r.fit_p_value) + ", but " + few +
                                  ": a test on so few values rejects almost no fit");
  else
    set(l, CheckStatus::pass, "p = " + num(p, 3) + " >= " + num(b.r.fit_p_value) +
                                  " (fitted to the same sample: weak support, Lilliefors)");
}

void sample_line(Builder& b) {
  const BarrierDesign& d = b.d;
  struct Q {
    const char* name;
    const std::optional<stats::BootstrapInterval>* ci;
  };
  const Q qs[] = {{"v_k", &d.v_k.interval}, {"h_k", &d.h_k.interval}, {"E_d", &d.E_d_interval},
                  {"h_i", &d.h_i_interval}};
  double worst = kNaN;
  std::string which, missing;
  for (const Q& q : qs) {
    if (!*q.ci) {
      missing += (missing.empty() ? "" : ", ") + std::string(q.name);
      continue;
    }
    const double ratio = (*q.ci)->half_width() / std::abs((*q.ci)->estimate);
    if (std::isnan(worst) || ratio > worst) {
      worst = ratio;
      which = q.name;
    }
  }
  const double tol = b.r.sample_tolerance;
  CheckLine& l = b.add("sample.size",
                       "largest half-width of the " + num(100 * b.r.sample_confidence, 6) +
                           " % bootstrap interval of v_k, h_k, E_d, h_i relative to its value" + (which.empty() ? std::string() : " (" + which + ")"),
                       100 * worst, 100 * tol, "%");  // in % as the quarries' sample.size
  if (!missing.empty()) {
    // Why: the design's note on the bootstrap (e.g. a resample of few distinct values that no
    // Weibull fits), else the sample itself.
    std::string why = "the resamples gave none";
    for (const auto& n : d.notes)
      if (n.rfind("bootstrap: ", 0) == 0) why = n.substr(11);
    std::string reason = "no bootstrap interval of " + missing + " (" + why + ")";
    if (!which.empty()) reason += "; the largest half-width of the others is " + pct(worst) + " of " + which;
    set(l, CheckStatus::warn, reason);
    return;
  }
  if (worst <= tol) {
    set(l, CheckStatus::pass, "half-width " + pct(worst) + " of " + which + " <= tolerance " + pct(tol));
    return;
  }
  const double n = static_cast<double>(d.crossings + d.not_reached);
  const SampleNeeded needed = sample_needed(n, d.throws, worst, tol);
  set(l, CheckStatus::warn,
      "half-width " + pct(worst) + " of " + which + " > tolerance " + pct(tol) + ": about " +
          num(needed.trajectories, 6) + " trajectories needed (n · (" + num(worst, 3) + " / " +
          num(tol, 3) + ")² with n = " + num(n, 9) + ")" + throws_needed_text(needed));
}

}  // namespace

std::vector<CheckLine> barrier_check_lines(const BarrierDesign& d, const BarrierRuleSet& rules) {
  Builder b{d, rules, {}};
  // A design (no candidate) that no class of the table meets recommends no barrier: `check`
  // must not pass it. (A candidate is judged on its own declared capacities below.)
  if (!d.spec.candidate && !d.energy_class) {
    CheckLine& l = b.add("design", "an energy class of the table that meets the required capacities",
                         needs_mel(rules.design_on) ? d.MEL_req_kJ : d.SEL_req_kJ, kNaN, "kJ");
    set(l, CheckStatus::fail,
        "no class of the class table meets " +
            (needs_mel(rules.design_on) ? "MEL_req " + num(d.MEL_req_kJ) + " kJ" : std::string()) +
            (needs_mel(rules.design_on) && needs_sel(rules.design_on) ? " and " : "") +
            (needs_sel(rules.design_on) ? "SEL_req " + num(d.SEL_req_kJ) + " kJ" : std::string()) +
            ": a barrier beyond the table (declare it as a candidate with its mel and sel), or "
            "protection of another kind");
  }
  if (d.spec.candidate) {
    const CandidateBarrier& c = *d.spec.candidate;
    const bool declares_energy = c.energy_class || c.mel_kJ || c.sel_kJ;
    // The requirements' upper bounds: E_d's interval scaled as E_d is (γE · E_d), and h_i's.
    const double e_upper = d.E_d_interval ? d.E_d_interval->upper : kNaN;
    const double e_conf = d.E_d_interval ? d.E_d_interval->confidence : kNaN;
    capacity_line(b, "energy.mel", "MEL", needs_mel(rules.design_on), d.candidate_mel_kJ,
                  d.MEL_req_kJ, declares_energy, d.gamma_E_MEL * e_upper, e_conf);
    capacity_line(b, "energy.sel", "SEL", needs_sel(rules.design_on), d.candidate_sel_kJ,
                  d.SEL_req_kJ, declares_energy, d.gamma_E_SEL * e_upper, e_conf);
    // E_d ∝ v_k² (E_d = ½ m_d (γF v_k)²): the requirements from the speeds' own percentile.
    const double v_ratio = d.v_k.weibull > 0 ? d.v_k.empirical / d.v_k.weibull : kNaN;
    below_own_percentile(b, b.lines[b.lines.size() - 2], d.v_k, d.speed, "fit.v", "v_k", "m/s",
                         d.MEL_req_kJ * v_ratio * v_ratio);
    below_own_percentile(b, b.lines.back(), d.v_k, d.speed, "fit.v", "v_k", "m/s",
                         d.SEL_req_kJ * v_ratio * v_ratio);
    {
      const double value = c.height.value_or(kNaN);
      CheckLine& l = b.add("height.interception",
                           "candidate's vertical interception height against h_i = h_k γh + f",
                           value, d.h_i, "m");
      const auto [has, needs] = compared_texts(value, d.h_i, "m");
      if (!c.height)  // WARN, not N/A: the check applies, it could not be made
        set(l, CheckStatus::warn, "the candidate declares no height (give height, m): h_i " +
                                      needs + " not compared");
      else if (at_least(*c.height, d.h_i))
        set(l, CheckStatus::pass, "height " + has + " >= h_i " + needs);
      else
        set(l, CheckStatus::fail, "height " + has + " < h_i " + needs);
      if (d.h_i_interval)
        within_interval(l, value, d.h_i_interval->upper, "m", d.h_i_interval->confidence);
      // h_i = h_k γh + f: the same from the heights' own percentile.
      below_own_percentile(b, l, d.h_k, d.height, "fit.h", "h_k", "m",
                           d.h_i + (d.h_k.empirical - d.h_k.weibull) * d.gamma_h.value);
    }
    elongation_line(b, c);
    // Table 4.2's columns: P(E > SEL_req), P(E > MEL_req), P(h > h_i), ...
    auto column = [&](std::size_t k) { return d.exceedance.size() > k ? &d.exceedance[k] : nullptr; };
    exceedance_line(b, "exceedance.energy",
                    "P(E > MEL_req) from the Weibull fit of the simulated energies", column(1),
                    d.spec.acceptable_energy_exceedance, d.energy, "fit.E",
                    {"MEL", d.candidate_mel_kJ, "kJ", "energy.mel", "MEL_req", "energies",
                     "a heavier design block"});
    exceedance_line(b, "exceedance.height",
                    "P(h > h_i) from the Weibull fit of the simulated passing heights", column(2),
                    d.spec.acceptable_height_exceedance, d.height, "fit.h",
                    {"height", c.height.value_or(kNaN), "m", "height.interception", "h_i",
                     "passing heights", "a larger free board"});
  }
  fit_line(b, "fit.v", "the speeds", d.speed, &d.v_k, "v_k", "m/s");
  fit_line(b, "fit.h", "the passing heights", d.height, &d.h_k, "h_k", "m");
  fit_line(b, "fit.E", "the translational energies", d.energy);
  sample_line(b);
  {
    CheckLine& l = b.add("reach", "crossings of the line (first in the main direction)",
                         static_cast<double>(d.crossings), rules.min_crossings, "");
    const std::string counts = num(static_cast<double>(d.crossings), 12) + " crossing" +
                               (d.crossings == 1 ? "" : "s") + ", " +
                               num(static_cast<double>(d.not_reached), 12) + " did not reach the line";
    if (static_cast<double>(d.crossings) < rules.min_crossings)
      set(l, CheckStatus::warn, counts + ": fewer than " + num(rules.min_crossings) +
                                    ", the statistics are weak");
    else
      set(l, CheckStatus::pass, counts);
  }
  return b.lines;
}

}  // namespace pierre::design
