#include "pierre/stats/weibull_fit.hpp"

#include <algorithm>
#include <boost/math/distributions/weibull.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "pierre/stats/math_policy.hpp"

namespace pierre::stats {
namespace {

using Weibull = boost::math::weibull_distribution<double, MathPolicy>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Sums over t_i = ln x_i - ln x_max <= 0 (the shift keeps x^k from overflowing and cancels
// out of g): S0 = Σ e^{k t}, S1 = Σ t e^{k t}, S2 = Σ t² e^{k t}.
struct PowerSums {
  double s0 = 0, s1 = 0, s2 = 0;
};

PowerSums power_sums(const std::vector<double>& t, double k) {
  PowerSums s;
  for (double ti : t) {
    const double e = std::exp(k * ti);
    s.s0 += e;
    s.s1 += ti * e;
    s.s2 += ti * ti * e;
  }
  return s;
}

Outcome<WeibullFit> fit_from(std::span<const double> sample, std::optional<double> shape_hint) {
  std::vector<double> t;
  t.reserve(sample.size());
  std::size_t excluded = 0;
  double log_max = -std::numeric_limits<double>::infinity();
  for (double x : sample) {
    if (!(x > 0.0) || !std::isfinite(x)) {
      ++excluded;
      continue;
    }
    t.push_back(std::log(x));
    log_max = std::max(log_max, t.back());
  }
  const std::size_t n = t.size();
  if (n < 2) {
    return Outcome<WeibullFit>::failure("Weibull fit needs at least two positive values, got " +
                                        std::to_string(n) + " (" + std::to_string(excluded) +
                                        " zero, negative or non-finite left out)");
  }
  double mean_t = 0;
  for (double& ti : t) {
    ti -= log_max;
    mean_t += ti;
  }
  mean_t /= static_cast<double>(n);
  double var_t = 0;
  for (double ti : t) var_t += (ti - mean_t) * (ti - mean_t);
  var_t /= static_cast<double>(n - 1);
  if (!(var_t > 0.0)) {
    return Outcome<WeibullFit>::failure(
        "Weibull fit: all positive values are equal, the shape is unbounded");
  }

  // g(k) and g'(k) for Newton–Raphson; g' = S2/S0 - (S1/S0)² + 1/k² > 0.
  auto g = [&](double k) {
    const PowerSums s = power_sums(t, k);
    const double a = s.s1 / s.s0;
    return std::pair<double, double>{a - 1.0 / k - mean_t, s.s2 / s.s0 - a * a + 1.0 / (k * k)};
  };
  constexpr int kDigits = 40;  // ~1e-12 relative: far below any sampling error
  double k = kNaN;
  PowerSums s;
  if (shape_hint && *shape_hint > 0 && std::isfinite(*shape_hint)) {
    // Newton from a hint near the root, kept within [hint/4, 4 hint]. Its end is taken when the
    // equation holds there: g' > 1/k², so |g(k)| <= 1e-10 / k puts k within 1e-10 k of the
    // root. (A root outside the range leaves Newton near a bound, not at it: the step-size test
    // alone would take that.) Else the bracketed search below decides.
    const double lo = *shape_hint / 4, hi = *shape_hint * 4;
    std::uintmax_t iterations = 100;
    try {
      const double kh =
          boost::math::tools::newton_raphson_iterate(g, *shape_hint, lo, hi, kDigits, iterations);
      if (iterations < 100 && std::isfinite(kh) && kh > 0) {
        s = power_sums(t, kh);  // the scale's sums too
        if (std::abs(s.s1 / s.s0 - 1.0 / kh - mean_t) <= 1e-10 / kh) k = kh;
      }
    } catch (const std::exception&) {  // Boost's "no root here": the bracketed search decides
    }
  }
  if (std::isnan(k)) {
    const double k0 = std::numbers::pi / std::sqrt(6.0 * var_t);  // Menon (1963)
    // Bracket the root: g < 0 at the lower bound, > 0 at the upper one.
    // (Each g costs a pass of n exponentials: the values at the ends are kept, not recomputed.)
    double k_lo = k0 / 4, k_hi = k0 * 4;
    double g_lo = g(k_lo).first, g_hi = g(k_hi).first;
    for (int i = 0; i < 60 && g_lo > 0; ++i) g_lo = g(k_lo /= 4).first;
    for (int i = 0; i < 60 && g_hi < 0; ++i) g_hi = g(k_hi *= 4).first;
    if (!(g_lo <= 0 && g_hi >= 0)) {
      return Outcome<WeibullFit>::failure("Weibull fit: could not bracket the shape");
    }
    std::uintmax_t iterations = 100;
    k = boost::math::tools::newton_raphson_iterate(g, std::clamp(k0, k_lo, k_hi), k_lo, k_hi,
                                                   kDigits, iterations);
    if (iterations >= 100 || !std::isfinite(k) || !(k > 0)) {
      return Outcome<WeibullFit>::failure("Weibull fit: the shape iteration did not converge");
    }
    s = power_sums(t, k);
  }
  WeibullFit fit;
  fit.shape = k;
  fit.scale = std::exp(log_max + std::log(s.s0 / static_cast<double>(n)) / k);
  fit.used = n;
  fit.excluded = excluded;
  return Outcome<WeibullFit>::success(fit);
}

}  // namespace

Outcome<WeibullFit> fit_weibull(std::span<const double> sample) {
  return fit_from(sample, std::nullopt);
}

Outcome<WeibullFit> fit_weibull(std::span<const double> sample, double shape_hint) {
  return fit_from(sample, shape_hint);
}

double cdf(const WeibullFit& fit, double x) {
  if (std::isnan(x)) return kNaN;
  if (x <= 0) return 0.0;
  return boost::math::cdf(Weibull(fit.shape, fit.scale), x);
}

double survival(const WeibullFit& fit, double x) {
  if (std::isnan(x)) return kNaN;
  if (x <= 0) return 1.0;
  return boost::math::cdf(boost::math::complement(Weibull(fit.shape, fit.scale), x));
}

double pdf(const WeibullFit& fit, double x) {
  if (std::isnan(x)) return kNaN;
  if (x < 0) return 0.0;
  return boost::math::pdf(Weibull(fit.shape, fit.scale), x);
}

double quantile(const WeibullFit& fit, double probability) {
  if (!(probability >= 0.0 && probability <= 1.0)) return kNaN;
  return boost::math::quantile(Weibull(fit.shape, fit.scale), probability);
}

}  // namespace pierre::stats
