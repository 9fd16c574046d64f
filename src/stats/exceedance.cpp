#include "pierre/stats/exceedance.hpp"

#include <boost/math/distributions/lognormal.hpp>
#include <boost/math/distributions/weibull.hpp>
#include <limits>

#include "pierre/stats/math_policy.hpp"

namespace pierre::stats {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double exceedance_probability(const WeibullFit& fit, double x) { return survival(fit, x); }

double exceedance_probability(const LognormalFit& fit, double x) { return survival(fit, x); }

double value_at_exceedance(const WeibullFit& fit, double q) {
  if (!(q >= 0.0 && q <= 1.0)) return kNaN;
  const boost::math::weibull_distribution<double, MathPolicy> d(fit.shape, fit.scale);
  return boost::math::quantile(boost::math::complement(d, q));
}

double value_at_exceedance(const LognormalFit& fit, double q) {
  if (!(q >= 0.0 && q <= 1.0)) return kNaN;
  const boost::math::lognormal_distribution<double, MathPolicy> d(fit.mu, fit.sigma);
  return boost::math::quantile(boost::math::complement(d, q));
}

}  // namespace pierre::stats
