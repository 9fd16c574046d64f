// Probability of exceedance P(X > x) from a fitted distribution, and its inverse: the value
// exceeded with probability q (the thesis's "5 % probability of exceedance" is q = 0.05).
// Weibull and log-normal here; the censored mixture's pair is in censored_lognormal_fit.hpp.
// All go through the Boost.Math distributions' complements (no 1 - F cancellation for
// small q).
#pragma once

#include "pierre/stats/censored_lognormal_fit.hpp"
#include "pierre/stats/lognormal_fit.hpp"
#include "pierre/stats/weibull_fit.hpp"

namespace pierre::stats {

double exceedance_probability(const WeibullFit& fit, double x);
double exceedance_probability(const LognormalFit& fit, double x);

// x with P(X > x) = q; NaN for q outside [0, 1].
double value_at_exceedance(const WeibullFit& fit, double q);
double value_at_exceedance(const LognormalFit& fit, double q);

}  // namespace pierre::stats
