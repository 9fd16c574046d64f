// Runout-type distribution (design-checks.md §2, thesis Fig 6.5): a point mass p0 at zero
// (blocks that stop above the toe), a log-normal for the positive values fitted by maximum
// likelihood with right-censored observations (blocks that leave the profile: known only to
// exceed its end), so that
//   P(X > d) = (1 - p0) · S_logn(d)  for d > 0,   P(X > d) = 1 for d < 0.
// p0 = zeros / (zeros + observed positives + censored).
//
// The censored log-likelihood (observed x_i, censored at c_j; z = (ln x - μ)/σ,
// w = (ln c - μ)/σ)
//   ℓ(μ, σ) = Σ_i [-ln σ - z_i²/2] + Σ_j ln Q(w_j)   (Q the standard normal survival)
// has no closed form; it is maximised with GSL's BFGS minimiser
// (gsl_multimin_fdfminimizer_vector_bfgs2) over (μ, ln σ), with the analytic gradient
// (inverse Mills ratio from gsl_sf_hazard, ln Q from gsl_sf_log_erfc), started from the fit
// that takes the censoring thresholds as observed values. With nothing censored the closed
// form of lognormal_fit.hpp is used, which is the same maximum.
//
// Values: 0 is a zero; positive finite values are observed; negatives, NaN and infinities
// are left out (`excluded`). Thresholds: positive finite ones are censored observations,
// the rest are left out. The fit fails with no observed positive value (μ unbounded) or
// when the minimiser does not converge (e.g. σ → 0).
#pragma once

#include <cstddef>
#include <span>

#include "pierre/stats/lognormal_fit.hpp"
#include "pierre/stats/outcome.hpp"

namespace pierre::stats {

struct CensoredLognormalFit {
  LognormalFit positive;  // the log-normal of the positive values (used = observed + censored)
  double zero_share = 0;  // p0
  std::size_t zeros = 0;
  std::size_t observed = 0;  // positive values seen in full
  std::size_t censored = 0;  // values known only to exceed their threshold
  std::size_t excluded = 0;  // values and thresholds left out
};

Outcome<CensoredLognormalFit> fit_censored_lognormal(std::span<const double> values,
                                                     std::span<const double> censored_at);

// The log-likelihood above (without the constant -Σ ln x_i - m ln √(2π)), for checking a fit.
double censored_lognormal_log_likelihood(std::span<const double> observed_positive,
                                         std::span<const double> censored_at, double mu,
                                         double sigma);

// P(X > d) of the mixture.
double exceedance_probability(const CensoredLognormalFit& fit, double d);
// The distance d with P(X > d) = q: 0 when q >= 1 - p0 (the zeros cover it), NaN for q
// outside [0, 1], +infinity for q = 0.
double value_at_exceedance(const CensoredLognormalFit& fit, double q);

}  // namespace pierre::stats
