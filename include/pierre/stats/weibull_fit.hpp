// Two-parameter Weibull distribution fitted by maximum likelihood (thesis §4.7 and appendix
// D; design-checks.md §1 steps 2 and 7):
//   F(x) = 1 - exp(-(x / λ)^k),  S(x) = exp(-(x / λ)^k)  for x >= 0,
// k the shape, λ the scale (appendix D's text swaps the names; Table D.2's columns are right).
//
// The fit: the profile-likelihood equation for k,
//   g(k) = Σ x^k ln x / Σ x^k - 1/k - mean(ln x) = 0,
// has one root (g increases from -inf to max ln x - mean ln x > 0); it is solved with
// Boost.Math's Newton–Raphson (boost::math::tools::newton_raphson_iterate, analytic g'),
// started from Menon's estimate k0 = π / (√6 · sd(ln x)). Then λ = (mean x^k)^(1/k).
//
// Rule for values a Weibull cannot hold: only positive, finite values are fitted; zeros,
// negatives, infinities and NaN are left out and counted in `excluded`. The fit fails (with
// a reason) with fewer than two positive values or when they are all equal (k unbounded).
//
// The distribution functions use boost::math::weibull_distribution (with MathPolicy: NaN,
// not an exception, for a probability outside [0, 1]).
#pragma once

#include <cstddef>
#include <span>

#include "pierre/stats/outcome.hpp"

namespace pierre::stats {

struct WeibullFit {
  double shape = 1;          // k
  double scale = 1;          // λ, in the unit of the data
  std::size_t used = 0;      // positive finite values fitted
  std::size_t excluded = 0;  // zeros, negatives and non-finite values left out
};

Outcome<WeibullFit> fit_weibull(std::span<const double> sample);
// The same fit with Newton started from `shape_hint` (a bootstrap resample's, from the sample's
// own k̂), where the root is near: a few passes over the values instead of the bracketing and the
// steps from Menon's estimate. The same root to the iteration's tolerance (1e-12 relative); a
// hint off by more than a factor of 4 falls back to the fit above.
Outcome<WeibullFit> fit_weibull(std::span<const double> sample, double shape_hint);

double cdf(const WeibullFit& fit, double x);       // P(X <= x); 0 for x <= 0
double survival(const WeibullFit& fit, double x);  // P(X > x) = exp(-(x/λ)^k); 1 for x <= 0
double pdf(const WeibullFit& fit, double x);       // 0 for x < 0
// The x with P(X <= x) = probability (the non-exceedance); NaN outside [0, 1].
double quantile(const WeibullFit& fit, double probability);

}  // namespace pierre::stats
