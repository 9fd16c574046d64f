// design_barrier: steps 1–8 of design-checks.md §1 put together. The parts live beside it:
// barrier_fits.cpp (fits, characteristic values, exceedance), barrier_values.cpp (the design
// arithmetic), barrier_checks.cpp (check lines), barrier_rules.cpp (factors, classes).
#include "pierre/design/barrier_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "pierre/design/number_text.hpp"
#include "pierre/stats/bootstrap.hpp"
#include "pierre/stats/bootstrap_weibull.hpp"
#include "pierre/stats/percentile.hpp"

namespace pierre::design {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::vector<double> scaled(const std::vector<double>& v, double f) {
  std::vector<double> out(v.size());
  std::transform(v.begin(), v.end(), out.begin(), [f](double x) { return x * f; });
  return out;
}

// The replicates of the governing characteristic value at p, and how they were drawn (for
// the notes). `empirical`: the order-statistic bootstrap of the percentile (bootstrap.hpp).
// `weibull` and `larger`: the bootstrap of the Weibull-ML quantile (bootstrap_weibull.hpp):
// exact resampling and refitting up to stats::WeibullBootstrapOptions::exact_up_to values
// (20 000), the Poisson bootstrap over quantile bins above (its error is far below the
// interval's Monte Carlo error: bootstrap_weibull.hpp says why, the stats tests check it).
struct Replicates {
  std::vector<double> values;
  std::optional<stats::WeibullQuantileReplicates> weibull;  // the Weibull bootstrap's details
};
stats::Outcome<Replicates> characteristic_replicates(std::span<const double> sample, double p,
                                                     Governing g, std::size_t resamples,
                                                     std::uint64_t seed, unsigned threads) {
  using Out = stats::Outcome<Replicates>;
  if (g == Governing::empirical) {
    auto r = stats::bootstrap_percentile_replicates(sample, p, seed, resamples);
    if (!r) return Out::failure(r.error);
    return Out::success(Replicates{std::move(*r.value), std::nullopt});
  }
  stats::WeibullBootstrapOptions o;
  o.resamples = resamples;
  o.empirical = g == Governing::larger;
  o.threads = threads;
  auto r = stats::bootstrap_weibull_quantile_replicates(sample, p, seed, o);
  if (!r) return Out::failure(r.error);
  Replicates out;
  out.values = r.value->weibull;
  if (g == Governing::larger) {
    for (std::size_t i = 0; i < out.values.size(); ++i) {
      const double q = out.values[i];
      out.values[i] = std::isnan(q) ? kNaN : std::max(q, r.value->empirical[i]);
    }
  }
  out.weibull = std::move(*r.value);
  out.weibull->weibull.clear();
  out.weibull->empirical.clear();
  return Out::success(std::move(out));
}

// What an engineer should know about a binned bootstrap.
std::string binned_note(const char* what, const stats::WeibullQuantileReplicates& r) {
  return std::string("bootstrap of ") + what + ": " + std::to_string(r.values) +
         " crossings, more than " + std::to_string(stats::WeibullBootstrapOptions{}.exact_up_to) +
         ": the Weibull refits use the Poisson bootstrap over " + std::to_string(r.bins) +
         " quantile bins (Hanley & MacGibbon 2006) instead of resampling every value; its "
         "error is far below the interval's Monte Carlo error";
}

// The percentile interval of f(replicate) at `confidence` (e.g. 90 %: the 5th to the 95th
// percentile), with f(estimate) as its estimate.
template <class F>
std::optional<stats::BootstrapInterval> interval(const std::vector<double>& replicates,
                                                 double confidence, double estimate, F f) {
  std::vector<double> r;
  r.reserve(replicates.size());
  for (double x : replicates) {
    if (!std::isfinite(x)) return std::nullopt;
    r.push_back(f(x));
  }
  stats::BootstrapInterval ci;
  ci.confidence = confidence;
  ci.resamples = r.size();
  ci.estimate = f(estimate);
  const auto q = stats::percentiles(r, stats::percentile_interval_ends(confidence));
  ci.lower = q[0];
  ci.upper = q[1];
  return ci;
}

std::optional<QuantityFit> observed_fit(const std::vector<double>& v) {
  if (v.empty()) return std::nullopt;
  return fit_quantity(v);
}

// BarrierDesign::how: where each quantity of the factors table comes from, with the rule
// set's citations, so that the report traces every number to a formula or a source.
void describe_derivations(BarrierDesign& d, const BarrierRuleSet& rules,
                          const EnergyClassTable& classes) {
  const std::string p = "P" + number_text(rules.percentile);
  const std::string weibull = p + " of the Weibull fit", empirical = p + " of the crossings";
  const std::string governing =
      rules.governing == Governing::weibull     ? weibull
      : rules.governing == Governing::empirical ? empirical
                                                : "the larger of the " + weibull + " and the " + empirical;
  d.how["v_k_weibull"] = d.how["h_k_weibull"] = weibull;
  d.how["v_k_empirical"] = d.how["h_k_empirical"] = empirical;
  d.how["v_k"] = d.how["h_k"] = governing + " (" + rules.name + ")";
  auto cited = [&](const char* key, const char* symbol, double v) {
    const auto s = rules.sources.find(key);
    return std::string(symbol) + " = " + number_text(v) + " (given" +
           (s == rules.sources.end() ? std::string() : ": " + s->second) + ")";
  };
  d.how["gamma_E_MEL"] = cited("gamma_E_MEL", "γE,MEL", d.gamma_E_MEL);
  d.how["gamma_E_SEL"] = cited("gamma_E_SEL", "γE,SEL", d.gamma_E_SEL);
  const std::string elongation =
      "; the elongation check asks a distance to the protected object of at least γd times the "
      "kit's declared elongation";
  if (d.gamma_d_MEL)
    d.how["gamma_d_MEL"] = cited("gamma_d_MEL", "γd,MEL", *d.gamma_d_MEL) + elongation;
  if (d.gamma_d_SEL)
    d.how["gamma_d_SEL"] = cited("gamma_d_SEL", "γd,SEL", *d.gamma_d_SEL) + elongation;
  d.how["free_board"] = "f = max(" + number_text(rules.free_board_abs) + " m, " +
                        number_text(rules.free_board_rel) + " · D_f) (" + rules.name + ")";
  d.how["h_d"] = "h_k · γh";
  d.how["h_i"] = "h_d + f";
  d.how["h_max_sim"] = "the largest simulated passing height";
  std::string needed = rules.design_on == DesignOn::mel   ? "MEL_req (the rule set designs on MEL; SEL_req is for information)"
                      : rules.design_on == DesignOn::sel ? "SEL_req (the rule set designs on SEL; MEL_req is for information)"
                                                         : "MEL_req and SEL_req";
  // Designing on both, one of them often sets the class alone (at Vaujany the SEL: class 7
  // where the MEL needs class 5), a cost step the client asks about: said.
  if (rules.design_on == DesignOn::both && d.energy_class && !d.energy_class->open_ended) {
    const auto on_mel = select_energy_class(classes, DesignOn::mel, d.MEL_req_kJ, d.SEL_req_kJ);
    const auto on_sel = select_energy_class(classes, DesignOn::sel, d.MEL_req_kJ, d.SEL_req_kJ);
    const int chosen = d.energy_class->number;
    if (on_mel && on_sel && on_mel->number < chosen && on_sel->number == chosen)
      needed += " (SEL_req governs: MEL_req alone needs class " + std::to_string(on_mel->number) + ")";
    else if (on_mel && on_sel && on_sel->number < chosen && on_mel->number == chosen)
      needed += " (MEL_req governs: SEL_req alone needs class " + std::to_string(on_sel->number) + ")";
    else if (on_mel && on_sel && on_mel->number == chosen && on_sel->number == chosen)
      needed += " (each alone needs class " + std::to_string(chosen) + ")";
  }
  // The table by its title for the reader, and by the name a scenario gives it.
  const std::string table = classes.title.empty() ? classes.name : classes.title + " (" + classes.name + ")";
  d.how["energy_class"] = "the smallest class of the " + table + " meeting " + needed +
                          (classes.source.empty() ? std::string() : "; " + classes.source);
}

// What the simulated Weibull fits leave out: only positive values fit a Weibull, and a block
// sliding or rolling across the line has its centre on the ground, h = 0 (model-2d.md §5).
// Leaving such zeros out raises the fitted quantiles and survivals: conservative, but said.
void note_zeros_left_out(BarrierDesign& d) {
  for (auto [what, q] : {std::pair{"speeds", &d.speed}, std::pair{"passing heights", &d.height},
                         std::pair{"translational energies", &d.energy}}) {
    if (!q->weibull || q->weibull->excluded == 0) continue;
    const std::size_t left = q->weibull->excluded, n = left + q->weibull->used;
    d.notes.push_back(std::to_string(left) + " of " + std::to_string(n) + " " + what +
                      " at the line are 0 (blocks sliding or rolling across it): the Weibull fit "
                      "is of the " + std::to_string(q->weibull->used) +
                      " positive values, so its characteristic value and exceedance "
                      "probabilities describe the blocks in flight (conservative); the empirical "
                      "values count every block");
  }
}

// Step 7: the exceedance table, simulated and observed (with a note when an observed fit
// rests on fewer values than the rule set asks of a simulated line).
void exceedance(BarrierDesign& d, const BarrierRuleSet& rules, const BarrierSample& sample,
                const std::vector<double>& energy_kJ, const std::optional<ObservedSample>& observed) {
  if (observed) {
    d.observed_speed = observed_fit(observed->speed);
    d.observed_height = observed_fit(observed->height);
    d.observed_energy = observed_fit(scaled(observed->energy, 1e-3));
    // A Weibull through a handful of values gives a number, not a probability to set beside
    // the simulated one: say so when a fit rests on fewer values than the rule set asks of a
    // simulated line (reach).
    std::string few;
    for (auto [what, q] : {std::pair{"speeds", &d.observed_speed},
                           std::pair{"passing heights", &d.observed_height},
                           std::pair{"energies", &d.observed_energy}}) {
      if (*q && (*q)->weibull && static_cast<double>((*q)->weibull->used) < rules.min_crossings)
        few += (few.empty() ? "" : ", ") + std::to_string((*q)->weibull->used) + " " + what;
    }
    if (!few.empty())
      d.notes.push_back("the observed Weibull fits rest on few values (" + few + "; fewer than the " +
                        number_text(rules.min_crossings) +
                        " crossings the rule set asks of a simulated line): read the observed "
                        "exceedance probabilities as indicative only");
  }
  ExceedanceInputs ex;
  ex.SEL_req_kJ = d.SEL_req_kJ;
  ex.MEL_req_kJ = d.MEL_req_kJ;
  ex.h_i = d.h_i;
  ex.h_max_sim = d.h_max_sim;
  ex.simulated_energy = d.energy.weibull;
  ex.simulated_height = d.height.weibull;
  ex.simulated_energy_point = d.energy.point_mass;
  ex.simulated_height_point = d.height.point_mass;
  ex.simulated_energy_kJ = energy_kJ;
  ex.simulated_height_m = sample.height;
  if (d.observed_energy) ex.observed_energy = d.observed_energy->weibull;
  if (d.observed_height) ex.observed_height = d.observed_height->weibull;
  d.exceedance = exceedance_rows(ex);
}

// Step 8: bootstrap intervals of v_k, h_k and, through them, E_d and h_i. (Not of a point
// mass: every resample is the sample, and no Weibull refits it.) Each shares its resamples
// out over every thread (the same replicates for any count).
void bootstrap_intervals(BarrierDesign& d, const BarrierRuleSet& rules,
                         const BarrierSample& sample, std::uint64_t seed, unsigned threads) {
  using Reps = stats::Outcome<Replicates>;
  auto replicates = [&](const QuantityFit& fit, std::span<const double> values, std::uint64_t s) {
    return fit.point_mass ? Reps::failure("a point mass")
                          : characteristic_replicates(values, rules.percentile, rules.governing,
                                                      rules.sample_resamples, s, threads);
  };
  const auto rv = replicates(d.speed, sample.speed, splitmix64(seed ^ 1));
  const auto rh = replicates(d.height, sample.height, splitmix64(seed ^ 2));
  const double gF = d.gamma_F.value, md = d.m_d, gh = d.gamma_h.value, f = d.free_board;
  const double conf = rules.sample_confidence;
  // A point mass resamples to itself: its interval has no width (no refit can show that).
  auto point_interval = [&rules](double v) {
    stats::BootstrapInterval ci;
    ci.confidence = rules.sample_confidence;
    ci.resamples = rules.sample_resamples;
    ci.estimate = ci.lower = ci.upper = v;
    return ci;
  };
  if (d.speed.point_mass) {
    d.v_k.interval = point_interval(d.v_k.value);
    d.E_d_interval = point_interval(d.E_d_kJ);
  } else if (rv) {
    d.v_k.interval = interval(rv->values, conf, d.v_k.value, [](double v) { return v; });
    d.E_d_interval = interval(rv->values, conf, d.v_k.value,
                              [gF, md](double v) { return design_energy_kJ(v, gF, md); });
    if (rv->weibull && rv->weibull->method == stats::WeibullBootstrapMethod::binned)
      d.notes.push_back(binned_note("v_k", *rv->weibull));
  }
  if (d.height.point_mass) {
    d.h_k.interval = point_interval(d.h_k.value);
    d.h_i_interval = point_interval(d.h_i);
  } else if (rh) {
    d.h_k.interval = interval(rh->values, conf, d.h_k.value, [](double h) { return h; });
    d.h_i_interval = interval(rh->values, conf, d.h_k.value, [gh, f](double h) { return interception_height(h, gh, f); });
    if (rh->weibull && rh->weibull->method == stats::WeibullBootstrapMethod::binned)
      d.notes.push_back(binned_note("h_k", *rh->weibull));
  }
  if (!d.v_k.interval || !d.h_k.interval)
    d.notes.push_back("bootstrap: " + (!d.v_k.interval && !rv   ? rv.error
                                       : !d.h_k.interval && !rh ? rh.error
                                                                : std::string("a resample gave no fit")));
}

// The candidate's capacities (its class's, or as given) and its residual height category.
void candidate_capacities(BarrierDesign& d, const BarrierSpec& spec, const EnergyClassTable& classes) {
  d.candidate_mel_kJ = d.candidate_sel_kJ = kNaN;
  if (spec.candidate) {
    const CandidateBarrier& c = *spec.candidate;
    if (c.energy_class) {
      if (const EnergyClass* ec = find_energy_class(classes, *c.energy_class)) {
        if (!ec->open_ended) {
          d.candidate_mel_kJ = ec->mel_kJ;
          d.candidate_sel_kJ = ec->sel_kJ;
        }
      }
    }
    if (c.mel_kJ) d.candidate_mel_kJ = *c.mel_kJ;
    if (c.sel_kJ) d.candidate_sel_kJ = *c.sel_kJ;
    if (c.residual_height && c.height && classes.residual_height) {
      const ResidualHeightCategories& cat = *classes.residual_height;
      d.residual_height_category = residual_height_category(cat, *c.residual_height, *c.height);
      // Its basis: the candidate's height stands for the nominal height (the kit's declared one
      // is not an input).
      d.how["residual_height_category"] =
          "residual height " + number_text(*c.residual_height) + " m / the candidate's height " +
          number_text(*c.height) + " m (taken as the nominal height) = " +
          number_text(100 * *c.residual_height / *c.height, 3) + " %: A from " +
          number_text(100 * cat.a_min) + " %, B above " + number_text(100 * cat.b_min) +
          " %, else C (" + classes.name + ")";
    }
  }
}

}  // namespace

std::uint64_t barrier_bootstrap_seed(std::uint64_t scenario_seed, std::size_t index) {
  return scenario_seed ^ 0x4241525249455253ULL ^ static_cast<std::uint64_t>(index);
}

BarrierOutcome design_barrier(const BarrierSpec& spec, const BarrierRuleSet& rules,
                              const EnergyClassTable& classes, const BarrierSample& sample,
                              const std::optional<ObservedSample>& observed, double chainage,
                              std::uint64_t seed, unsigned threads) {
  BarrierOutcome out;
  BarrierDesign d;
  d.spec = spec;
  d.rules_name = rules.name;
  d.design_on = rules.design_on;
  d.rules_title = rules.title;
  d.rules_source = rules.source;
  d.rules_file = rules.file;
  d.classes_name = classes.name;
  d.classes_title = classes.title;
  d.classes_file = classes.file;
  d.chainage = chainage;
  d.crossings = sample.speed.size();
  d.not_reached = sample.not_reached;
  d.throws = sample.throws;
  d.bootstrap_seed = seed;

  // Step 1: the sample at the line.
  if (sample.height.size() != sample.speed.size() || sample.energy.size() != sample.speed.size()) {
    out.error = "the speed, height and energy samples differ in length";
    return out;
  }
  if (d.crossings < 2) {
    out.error = "fewer than two trajectories crossed the line (" + std::to_string(d.crossings) +
                "): nothing to fit, no design";
    out.check_line = "reach";
    return out;
  }
  const std::vector<double> energy_kJ = scaled(sample.energy, 1e-3);

  // Step 2: fits and characteristic values.
  d.speed = fit_quantity(sample.speed);
  d.height = fit_quantity(sample.height);
  d.energy = fit_quantity(energy_kJ);
  d.rotational_energy = stats::summarize(scaled(sample.rotational_energy, 1e-3));
  d.v_k = characteristic_value(d.speed, sample.speed, rules.percentile, rules.governing);
  d.h_k = characteristic_value(d.height, sample.height, rules.percentile, rules.governing);
  if (std::isnan(d.v_k.value) || std::isnan(d.h_k.value)) {
    out.error = "no characteristic value (" + to_string(rules.governing) +
                "): " + (d.speed.error.empty() ? d.height.error : d.speed.error);
    return out;
  }
  d.h_max_sim = *std::max_element(sample.height.begin(), sample.height.end());

  // The design block and the free-board diameter.
  const auto block = resolve_design_block(spec.design_block, spec.free_board_diameter, sample.blocks);
  if (!block) {
    out.error = block.error;
    return out;
  }
  d.design_volume = block->volume;
  d.design_density = block->density;
  d.free_board_diameter = block->free_board_diameter;
  d.how["volume"] = block->volume_how;
  d.how["density"] = block->density_how;
  d.how["free_board_diameter"] = block->free_board_diameter_how;

  // Steps 3–6.
  DesignInputs in;
  in.v_k = d.v_k.value;
  in.h_k = d.h_k.value;
  in.volume = d.design_volume;
  in.density = d.design_density;
  in.free_board_diameter = d.free_board_diameter;
  in.data_quality = spec.data_quality;
  const auto dv = design_values(rules, classes, in);
  if (!dv) {
    out.error = dv.error;
    return out;
  }
  d.gamma_F = dv->gamma_F;
  d.gamma_M = dv->gamma_M;
  d.gamma_h = dv->gamma_h;
  d.gamma_E_MEL = dv->gamma_E_MEL;
  if (needs_mel(rules.design_on)) d.gamma_d_MEL = rules.gamma_d_MEL;
  if (needs_sel(rules.design_on)) d.gamma_d_SEL = rules.gamma_d_SEL;
  d.gamma_E_SEL = dv->gamma_E_SEL;
  d.v_d = dv->v_d;
  d.m_d = dv->m_d;
  d.E_d_kJ = dv->E_d_kJ;
  d.MEL_req_kJ = dv->MEL_req_kJ;
  d.SEL_req_kJ = dv->SEL_req_kJ;
  d.energy_class = dv->energy_class;
  d.free_board = dv->free_board;
  d.h_d = dv->h_d;
  d.h_i = dv->h_i;
  if (!d.energy_class)
    d.notes.push_back("no class of " + classes.name + " meets the required capacities");
  else if (d.energy_class->open_ended)
    d.notes.push_back("class " + std::to_string(d.energy_class->number) +
                      " is open-ended: the barrier must declare MEL >= MEL_req and SEL >= SEL_req");

  note_zeros_left_out(d);
  exceedance(d, rules, sample, energy_kJ, observed);
  bootstrap_intervals(d, rules, sample, seed, threads);
  candidate_capacities(d, spec, classes);
  describe_derivations(d, rules, classes);
  d.checks = barrier_check_lines(d, rules);
  out.design = std::move(d);
  return out;
}

}  // namespace pierre::design
