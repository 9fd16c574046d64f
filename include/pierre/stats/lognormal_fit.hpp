// Log-normal distribution fitted by maximum likelihood: ln X ~ Normal(μ, σ²), with the
// closed-form estimates μ = mean(ln x) and σ² = mean((ln x - μ)²) — divisor n, the ML
// estimate, not the unbiased n - 1. Only positive, finite values are fitted; the rest are
// counted in `excluded`. The fit fails with fewer than two positive values or when they
// are all equal (σ = 0). Distribution functions: boost::math::lognormal_distribution.
// For right-censored values and a point mass of zeros see censored_lognormal_fit.hpp.
#pragma once

#include <cstddef>
#include <span>

#include "pierre/stats/outcome.hpp"

namespace pierre::stats {

struct LognormalFit {
  double mu = 0;     // location: mean of ln x
  double sigma = 1;  // scale: standard deviation of ln x
  std::size_t used = 0;
  std::size_t excluded = 0;
};

Outcome<LognormalFit> fit_lognormal(std::span<const double> sample);

double cdf(const LognormalFit& fit, double x);                 // 0 for x <= 0
double survival(const LognormalFit& fit, double x);            // 1 for x <= 0
double pdf(const LognormalFit& fit, double x);                 // 0 for x <= 0
double quantile(const LognormalFit& fit, double probability);  // NaN outside [0, 1]

}  // namespace pierre::stats
