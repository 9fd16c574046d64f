// Steps 2 and 7 of design-checks.md §1: fits of one quantity, its characteristic value, and
// the exceedance table (Table 4.2's columns).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pierre/design/barrier_check.hpp"
#include "pierre/stats/exceedance.hpp"
#include "pierre/stats/percentile.hpp"

namespace pierre::design {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double fraction_above(std::span<const double> sample, double threshold) {
  std::size_t n = 0, above = 0;
  for (double x : sample) {
    if (std::isnan(x)) continue;
    ++n;
    above += x > threshold;
  }
  return n ? static_cast<double>(above) / static_cast<double>(n) : kNaN;
}

double weibull_survival(const std::optional<stats::WeibullFit>& f,
                        const std::optional<double>& point, double x) {
  if (f) return stats::exceedance_probability(*f, x);
  if (point) return x < *point ? 1.0 : 0.0;
  return kNaN;
}

}  // namespace

QuantityFit fit_quantity(std::span<const double> sample) {
  QuantityFit q;
  q.summary = stats::summarize(sample);
  const auto w = stats::fit_weibull(sample);
  if (w) {
    q.weibull = *w;
    const stats::WeibullFit f = *w;
    const auto ks = stats::kolmogorov_smirnov(sample, [f](double x) { return stats::cdf(f, x); });
    if (ks) q.weibull_ks = *ks;
  } else {
    q.error = "Weibull: " + w.error;
    // A point mass: no positive value, or all of them one value (the Weibull fit leaves the
    // zeros out, so a mix of zeros and one value is a point mass at that value: conservative).
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    bool finite = !sample.empty();
    std::size_t zeros = 0;
    for (double x : sample) {
      if (!std::isfinite(x) || x < 0) finite = false;
      if (x > 0) lo = std::min(lo, x), hi = std::max(hi, x);
      zeros += x == 0;
    }
    if (finite && (hi == 0 || lo == hi)) {
      q.point_mass = hi;
      char v[32];
      std::snprintf(v, sizeof v, "%.4g", hi);
      const std::string n = std::to_string(sample.size());
      q.error = (hi == 0 || zeros == 0 ? "all " + n + " values are " + v
                                       : "all " + std::to_string(sample.size() - zeros) + " positive values of " + n + " are " + v) +
                ": a point mass there, the Weibull's limit";
    }
  }
  const auto l = stats::fit_lognormal(sample);
  if (l) {
    q.lognormal = *l;
    const stats::LognormalFit f = *l;
    const auto ks = stats::kolmogorov_smirnov(sample, [f](double x) { return stats::cdf(f, x); });
    if (ks) q.lognormal_ks = *ks;
  } else {
    q.error += (q.error.empty() ? "" : "; ") + std::string("log-normal: ") + l.error;
  }
  return q;
}

Characteristic characteristic_value(const QuantityFit& fit, std::span<const double> sample,
                                    double p, Governing governing) {
  Characteristic c;
  c.weibull = fit.weibull ? stats::quantile(*fit.weibull, p / 100.0) : fit.point_mass.value_or(kNaN);
  c.empirical = stats::percentile(sample, p);
  switch (governing) {
    case Governing::weibull: c.value = c.weibull; break;
    case Governing::empirical: c.value = c.empirical; break;
    case Governing::larger:
      c.value = std::isnan(c.weibull) ? kNaN : std::max(c.weibull, c.empirical);
      break;
  }
  return c;
}

double weibull_exceedance(const QuantityFit& q, double x) {
  return weibull_survival(q.weibull, q.point_mass, x);
}

std::vector<ExceedanceRow> exceedance_rows(const ExceedanceInputs& in) {
  struct Spec {
    const char* what;
    double threshold;
    const char* unit;
    const std::optional<stats::WeibullFit>* sim;
    const std::optional<double>* sim_point;
    std::span<const double> sample;
    const std::optional<stats::WeibullFit>* obs;
  };
  const Spec specs[] = {
      {"P(E > SEL_req)", in.SEL_req_kJ, "kJ", &in.simulated_energy, &in.simulated_energy_point,
       in.simulated_energy_kJ, &in.observed_energy},
      {"P(E > MEL_req)", in.MEL_req_kJ, "kJ", &in.simulated_energy, &in.simulated_energy_point,
       in.simulated_energy_kJ, &in.observed_energy},
      {"P(h > h_i)", in.h_i, "m", &in.simulated_height, &in.simulated_height_point,
       in.simulated_height_m, &in.observed_height},
      {"P(h > h_max,sim)", in.h_max_sim, "m", &in.simulated_height, &in.simulated_height_point,
       in.simulated_height_m, &in.observed_height},
  };
  std::vector<ExceedanceRow> rows;
  for (const Spec& s : specs) {
    ExceedanceRow r;
    r.what = s.what;
    r.threshold = s.threshold;
    r.unit = s.unit;
    r.simulated_weibull = weibull_survival(*s.sim, *s.sim_point, s.threshold);
    r.simulated_empirical = fraction_above(s.sample, s.threshold);
    if (*s.obs) r.observed_weibull = stats::exceedance_probability(**s.obs, s.threshold);
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace pierre::design
