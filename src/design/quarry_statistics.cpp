#include "pierre/design/quarry_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pierre/stats/cdf_rmse.hpp"
#include "pierre/stats/empirical_cdf.hpp"
#include "pierre/stats/lognormal_fit.hpp"
#include "pierre/stats/percentile.hpp"

namespace pierre::design {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

void DistanceSample::add(std::span<const double> values_m, double height, double censor_distance) {
  for (double v : values_m) {
    metres.push_back(v);
    normalized.push_back(v / height);
    if (std::isinf(v)) censored_at.push_back(censor_distance / height);
  }
  beyond = std::max(beyond, censor_distance / height);
  beyond_m = std::max(beyond_m, censor_distance);
}

std::vector<double> censored_percentiles(std::span<const double> values, double beyond,
                                         std::span<const double> ps) {
  std::vector<double> bounded;
  bounded.reserve(values.size());
  std::size_t k = 0;
  for (double v : values) {
    if (std::isnan(v)) continue;
    if (std::isinf(v)) {
      bounded.push_back(beyond);
      ++k;
    } else {
      bounded.push_back(v);
    }
  }
  const std::vector<double> q = stats::percentiles(bounded, ps);  // NaN: a bad p, or no values
  const double n = static_cast<double>(bounded.size());
  std::vector<double> out;
  out.reserve(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!std::isnan(q[i]) && static_cast<double>(k) * 100.0 > (100.0 - ps[i]) * n * (1.0 + 1e-9)) {
      // "More than (1 − p) of all blocks leave": k > (1 − p/100) n, with a hair of slack for
      // the rounding of 100 − p (p = 99.9 and k = 1 of 1000 is exactly the limit, not beyond it).
      out.push_back(kInf);
    } else {
      out.push_back(q[i]);
    }
  }
  return out;
}

double censored_percentile(std::span<const double> values, double beyond, double p) {
  const double ps[] = {p};
  return censored_percentiles(values, beyond, ps).front();
}

stats::Outcome<PositivePartKs> positive_part_ks(std::span<const double> sample,
                                                const stats::CensoredLognormalFit& fit,
                                                double below) {
  using Result = stats::Outcome<PositivePartKs>;
  // The zeros are left out: their share is the fit's p0 itself (its maximum-likelihood value),
  // so they cannot disagree with it. Kept in, they add nothing to D but their count to n: D
  // shrinks by (1 − p0) while n does not, and √n·D by √(1 − p0) under the fit, a test that
  // rejected almost nothing (75 % zeros: p 0.40 where the positive values alone give 0.003).
  std::vector<double> x;
  x.reserve(sample.size());
  for (double v : sample)
    if (v > 0) x.push_back(v);  // NaN and the zeros out; the censored (+inf) in
  if (x.empty()) return Result::failure("no value above zero");
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  auto F = [&](double d) { return stats::cdf(fit.positive, d); };
  double D = 0;
  std::size_t i = 0;
  while (i < x.size() && x[i] < below) {
    const double v = x[i];
    std::size_t j = i;
    while (j < x.size() && x[j] == v) ++j;  // ties stepped together
    const double f = F(v);
    D = std::max({D, std::abs(static_cast<double>(j) / n - f), std::abs(static_cast<double>(i) / n - f)});
    i = j;
  }
  if (std::isfinite(below)) {  // just below the censoring threshold
    const double fn = static_cast<double>(i) / n;
    D = std::max(D, std::abs(fn - F(below)));
  }
  PositivePartKs out;
  out.statistic = D;
  out.n = x.size();
  out.observed = i;
  out.below = below;
  // n, not the values below `below`: the sample CDF is over all n (a censored value is one above
  // the threshold). The supremum over d < below only is a smaller statistic than the full one
  // under the fit, so Stephens' p (for the full range) errs large: towards passing a fit.
  out.p_value = stats::kolmogorov_p_value_stephens(D, n);
  return Result::success(out);
}

DistanceStatistics distance_statistics(const DistanceSample& s) {
  DistanceStatistics out;
  out.count = s.size();
  for (double v : s.normalized) {
    if (v == 0) ++out.zeros;
    if (std::isinf(v)) ++out.censored;
  }
  const double ps[] = {50, 95, 99, 100};
  const auto m = censored_percentiles(s.metres, s.beyond_m, ps);
  const auto h = censored_percentiles(s.normalized, s.beyond, ps);
  out.p50 = m[0], out.p95 = m[1], out.p99 = m[2], out.max = m[3];
  out.p50_h = h[0], out.p95_h = h[1], out.p99_h = h[2], out.max_h = h[3];
  if (out.count == 0) {
    out.fit_error = "no values";
    return out;
  }
  std::vector<double> finite;
  for (double v : s.normalized)
    if (std::isfinite(v)) finite.push_back(v);
  const auto fit = stats::fit_censored_lognormal(finite, s.censored_at);
  if (!fit) {
    out.fit_error = fit.error;
    return out;
  }
  out.fit = *fit;
  const double below =
      s.censored_at.empty() ? kInf : *std::min_element(s.censored_at.begin(), s.censored_at.end());
  if (auto ks = positive_part_ks(s.normalized, *fit, below)) out.ks = *ks;
  return out;
}

double empirical_at_exceedance(const DistanceSample& sample, double q) {
  if (!(q >= 0 && q <= 1)) return kNaN;
  return censored_percentile(sample.normalized, sample.beyond, 100.0 * (1.0 - q));
}

double empirical_exceedance(std::span<const double> sample, double d) {
  std::size_t n = 0, above = 0;
  for (double v : sample) {
    if (std::isnan(v)) continue;
    ++n;
    if (v > d) ++above;
  }
  return n == 0 ? kNaN : static_cast<double>(above) / static_cast<double>(n);
}

ObservedComparison compare_observed(const DistanceSample& simulated, const ObservedDistance& obs,
                                    double height) {
  ObservedComparison out;
  out.p50 = out.p95 = out.max = kNaN;
  out.p50_h = out.p95_h = out.max_h = kNaN;
  if (!obs.metres.empty()) {
    out.raw = true;
    out.count = obs.metres.size();
    std::vector<double> norm(obs.metres.size());
    for (std::size_t i = 0; i < norm.size(); ++i) {
      const double h = i < obs.heights.size() ? obs.heights[i] : height;
      out.at_row_height = out.at_row_height && h == height;
      norm[i] = obs.metres[i] / h;
    }
    const double ps[] = {50, 95, 100};
    const auto m = stats::percentiles(obs.metres, ps);
    const auto h = stats::percentiles(norm, ps);
    out.p50 = m[0], out.p95 = m[1], out.max = m[2];
    out.p50_h = h[0], out.p95_h = h[1], out.max_h = h[2];
    out.breaks_h = norm;
    std::sort(out.breaks_h.begin(), out.breaks_h.end());
    out.breaks_h.erase(std::unique(out.breaks_h.begin(), out.breaks_h.end()), out.breaks_h.end());
    out.observed_cdf = stats::empirical_cdf(norm, out.breaks_h);
    out.simulated_cdf = stats::empirical_cdf(simulated.normalized, out.breaks_h);
    if (auto ks = stats::kolmogorov_smirnov_two_sample(simulated.normalized, norm)) out.ks = *ks;
  } else {
    out.count = obs.count.value_or(0);
    if (obs.p50) out.p50 = *obs.p50, out.p50_h = *obs.p50 / height;
    if (obs.p95) out.p95 = *obs.p95, out.p95_h = *obs.p95 / height;
    if (obs.max) out.max = *obs.max, out.max_h = *obs.max / height;
    const std::pair<std::optional<double>, double> pts[] = {
        {obs.p50, 0.50}, {obs.p95, 0.95}, {obs.max, 1.0}};
    for (const auto& [v, F] : pts)
      if (v) {
        out.breaks_h.push_back(*v / height);
        out.observed_cdf.push_back(F);
      }
    out.simulated_cdf = stats::empirical_cdf(simulated.normalized, out.breaks_h);
  }
  if (!out.breaks_h.empty() && !simulated.normalized.empty())
    if (auto r = stats::cdf_rmse(out.simulated_cdf, out.observed_cdf)) out.cdf_rmse = *r;
  return out;
}

DurationStatistics duration_statistics(std::span<const double> durations) {
  DurationStatistics out;
  for (double d : durations)
    if (!std::isnan(d)) ++out.count;
  const double ps[] = {50, 95, 100};
  const auto v = stats::percentiles(durations, ps);
  out.p50 = v.size() > 0 ? v[0] : kNaN;
  out.p95 = v.size() > 1 ? v[1] : kNaN;
  out.max = v.size() > 2 ? v[2] : kNaN;
  return out;
}

}  // namespace pierre::design
