#include "pierre/stats/lognormal_fit.hpp"

#include <boost/math/distributions/lognormal.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "pierre/stats/math_policy.hpp"

namespace pierre::stats {
namespace {

using Lognormal = boost::math::lognormal_distribution<double, MathPolicy>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

// Closed form: the ML estimates of a normal fitted to ln x. Two passes (mean, then squared
// deviations) keep σ accurate when the logs share a large offset.
Outcome<LognormalFit> fit_lognormal(std::span<const double> sample) {
  std::size_t n = 0, excluded = 0;
  double sum = 0;
  for (double x : sample) {
    if (!(x > 0.0) || !std::isfinite(x)) {
      ++excluded;
      continue;
    }
    ++n;
    sum += std::log(x);
  }
  if (n < 2) {
    return Outcome<LognormalFit>::failure(
        "log-normal fit needs at least two positive values, got " + std::to_string(n));
  }
  const double mu = sum / static_cast<double>(n);
  double ss = 0;
  for (double x : sample) {
    if (!(x > 0.0) || !std::isfinite(x)) continue;
    const double d = std::log(x) - mu;
    ss += d * d;
  }
  const double sigma = std::sqrt(ss / static_cast<double>(n));
  if (!(sigma > 0.0)) {
    return Outcome<LognormalFit>::failure("log-normal fit: all positive values are equal");
  }
  return Outcome<LognormalFit>::success(LognormalFit{mu, sigma, n, excluded});
}

double cdf(const LognormalFit& fit, double x) {
  if (std::isnan(x)) return kNaN;
  if (x <= 0) return 0.0;
  return boost::math::cdf(Lognormal(fit.mu, fit.sigma), x);
}

double survival(const LognormalFit& fit, double x) {
  if (std::isnan(x)) return kNaN;
  if (x <= 0) return 1.0;
  return boost::math::cdf(boost::math::complement(Lognormal(fit.mu, fit.sigma), x));
}

double pdf(const LognormalFit& fit, double x) {
  if (std::isnan(x)) return kNaN;
  if (x <= 0) return 0.0;
  return boost::math::pdf(Lognormal(fit.mu, fit.sigma), x);
}

double quantile(const LognormalFit& fit, double probability) {
  if (!(probability >= 0.0 && probability <= 1.0)) return kNaN;
  return boost::math::quantile(Lognormal(fit.mu, fit.sigma), probability);
}

}  // namespace pierre::stats
