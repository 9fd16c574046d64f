#include "pierre/stats/censored_lognormal_fit.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>
#include <gsl/gsl_sf_erf.h>

#include <boost/math/distributions/lognormal.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <string>
#include <vector>

#include "pierre/stats/math_policy.hpp"

namespace pierre::stats {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// GSL aborts the process on an error unless its handler is off (library-notes.md); the
// statuses are checked below instead. Done once, here, so the layer needs no start-up call.
void gsl_errors_as_statuses() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

// ln Q(w), Q the standard normal survival, without underflow for large w.
double log_normal_survival(double w) {
  return gsl_sf_log_erfc(w / std::numbers::sqrt2) - std::numbers::ln2;
}

struct LogData {
  std::vector<double> observed;  // ln x of the observed positive values
  std::vector<double> censored;  // ln c of the censoring thresholds
};

// Negative log-likelihood per value, f = (m s + ½ Σ z² - Σ ln Q(w)) / N over v = (μ, s = ln σ),
// and its gradient: ∂f/∂μ = -(Σ z + Σ h) / (σ N), ∂f/∂s = (m - Σ z² - Σ h w) / N, with
// h = φ(w)/Q(w) the inverse Mills ratio (gsl_sf_hazard).
void objective(const LogData& d, double mu, double s, double* f, double* g_mu, double* g_s) {
  const double sigma = std::exp(s);
  double sz = 0, sz2 = 0, slq = 0, sh = 0, shw = 0;
  for (double l : d.observed) {
    const double z = (l - mu) / sigma;
    sz += z;
    sz2 += z * z;
  }
  for (double l : d.censored) {
    const double w = (l - mu) / sigma;
    if (f) slq += log_normal_survival(w);
    if (g_mu) {
      const double h = gsl_sf_hazard(w);
      sh += h;
      shw += h * w;
    }
  }
  const double m = static_cast<double>(d.observed.size());
  const double total = m + static_cast<double>(d.censored.size());
  if (f) *f = (m * s + 0.5 * sz2 - slq) / total;
  if (g_mu) {
    *g_mu = -(sz + sh) / (sigma * total);
    *g_s = (m - sz2 - shw) / total;
  }
}

double gsl_f(const gsl_vector* v, void* p) {
  double f = 0;
  objective(*static_cast<const LogData*>(p), gsl_vector_get(v, 0), gsl_vector_get(v, 1), &f,
            nullptr, nullptr);
  return std::isfinite(f) ? f : GSL_POSINF;
}

void gsl_df(const gsl_vector* v, void* p, gsl_vector* g) {
  double gm = 0, gs = 0;
  objective(*static_cast<const LogData*>(p), gsl_vector_get(v, 0), gsl_vector_get(v, 1), nullptr,
            &gm, &gs);
  gsl_vector_set(g, 0, gm);
  gsl_vector_set(g, 1, gs);
}

void gsl_fdf(const gsl_vector* v, void* p, double* f, gsl_vector* g) {
  double gm = 0, gs = 0;
  objective(*static_cast<const LogData*>(p), gsl_vector_get(v, 0), gsl_vector_get(v, 1), f, &gm,
            &gs);
  if (!std::isfinite(*f)) *f = GSL_POSINF;
  gsl_vector_set(g, 0, gm);
  gsl_vector_set(g, 1, gs);
}

struct MinimizerDeleter {
  void operator()(gsl_multimin_fdfminimizer* m) const { gsl_multimin_fdfminimizer_free(m); }
};
struct VectorDeleter {
  void operator()(gsl_vector* v) const { gsl_vector_free(v); }
};

}  // namespace

double censored_lognormal_log_likelihood(std::span<const double> observed_positive,
                                         std::span<const double> censored_at, double mu,
                                         double sigma) {
  LogData d;
  for (double x : observed_positive) d.observed.push_back(std::log(x));
  for (double c : censored_at) d.censored.push_back(std::log(c));
  double f = 0;
  objective(d, mu, std::log(sigma), &f, nullptr, nullptr);
  return -f * static_cast<double>(d.observed.size() + d.censored.size());
}

Outcome<CensoredLognormalFit> fit_censored_lognormal(std::span<const double> values,
                                                     std::span<const double> censored_at) {
  using Result = Outcome<CensoredLognormalFit>;
  CensoredLognormalFit fit;
  LogData d;
  d.observed.reserve(values.size());
  for (double x : values) {
    if (x == 0.0) {
      ++fit.zeros;
    } else if (x > 0.0 && std::isfinite(x)) {
      d.observed.push_back(std::log(x));
    } else {
      ++fit.excluded;
    }
  }
  for (double c : censored_at) {
    if (c > 0.0 && std::isfinite(c)) {
      d.censored.push_back(std::log(c));
    } else {
      ++fit.excluded;
    }
  }
  fit.observed = d.observed.size();
  fit.censored = d.censored.size();
  const std::size_t all = fit.zeros + fit.observed + fit.censored;
  if (fit.observed == 0) {
    return Result::failure("censored log-normal fit needs at least one observed positive value");
  }
  fit.zero_share = static_cast<double>(fit.zeros) / static_cast<double>(all);

  // Start (and the answer when nothing is censored): the closed-form fit with the thresholds
  // taken as observed values.
  double mu = 0, ss = 0;
  for (double l : d.observed) mu += l;
  for (double l : d.censored) mu += l;
  const double npos = static_cast<double>(fit.observed + fit.censored);
  mu /= npos;
  for (double l : d.observed) ss += (l - mu) * (l - mu);
  for (double l : d.censored) ss += (l - mu) * (l - mu);
  double sigma = std::sqrt(ss / npos);
  fit.positive.used = fit.observed + fit.censored;
  fit.positive.excluded = fit.excluded + fit.zeros;
  if (d.censored.empty()) {
    if (fit.observed < 2 || !(sigma > 0.0)) {
      return Result::failure("log-normal fit needs at least two different positive values");
    }
    fit.positive.mu = mu;
    fit.positive.sigma = sigma;
    return Result::success(fit);
  }
  if (!(sigma > 0.0)) sigma = 1.0;

  gsl_errors_as_statuses();
  gsl_multimin_function_fdf fdf{&gsl_f, &gsl_df, &gsl_fdf, 2, &d};
  std::unique_ptr<gsl_vector, VectorDeleter> v(gsl_vector_alloc(2));
  std::unique_ptr<gsl_multimin_fdfminimizer, MinimizerDeleter> minimizer(
      gsl_multimin_fdfminimizer_alloc(gsl_multimin_fdfminimizer_vector_bfgs2, 2));
  if (!v || !minimizer) return Result::failure("censored log-normal fit: out of memory");
  gsl_vector_set(v.get(), 0, mu);
  gsl_vector_set(v.get(), 1, std::log(sigma));
  // Step 0.1 in (μ, ln σ); line-search tolerance 0.1 as the GSL manual advises for BFGS.
  if (gsl_multimin_fdfminimizer_set(minimizer.get(), &fdf, v.get(), 0.1, 0.1) != GSL_SUCCESS) {
    return Result::failure("censored log-normal fit: the minimiser could not start");
  }
  // The objective is per value, so its gradient is O(1): 1e-10 is converged in any unit.
  constexpr double kGradientTolerance = 1e-10;
  int status = GSL_CONTINUE;
  for (int i = 0; i < 500 && status == GSL_CONTINUE; ++i) {
    if (gsl_multimin_fdfminimizer_iterate(minimizer.get()) != GSL_SUCCESS) break;  // no progress
    status = gsl_multimin_test_gradient(gsl_multimin_fdfminimizer_gradient(minimizer.get()),
                                        kGradientTolerance);
  }
  const gsl_vector* best = gsl_multimin_fdfminimizer_x(minimizer.get());
  const gsl_vector* grad = gsl_multimin_fdfminimizer_gradient(minimizer.get());
  // A stalled line search right at the optimum is fine; accept a gradient that small.
  const double gnorm = std::hypot(gsl_vector_get(grad, 0), gsl_vector_get(grad, 1));
  mu = gsl_vector_get(best, 0);
  sigma = std::exp(gsl_vector_get(best, 1));
  if (!(gnorm < 1e-6) || !std::isfinite(mu) || !(sigma > 0.0) || !std::isfinite(sigma)) {
    return Result::failure("censored log-normal fit did not converge (gradient " +
                           std::to_string(gnorm) + ", sigma " + std::to_string(sigma) + ")");
  }
  fit.positive.mu = mu;
  fit.positive.sigma = sigma;
  return Result::success(fit);
}

double exceedance_probability(const CensoredLognormalFit& fit, double d) {
  if (std::isnan(d)) return kNaN;
  if (d < 0) return 1.0;
  if (d == 0) return 1.0 - fit.zero_share;
  return (1.0 - fit.zero_share) * survival(fit.positive, d);
}

double value_at_exceedance(const CensoredLognormalFit& fit, double q) {
  if (!(q >= 0.0 && q <= 1.0)) return kNaN;
  const double positive_share = 1.0 - fit.zero_share;
  if (q >= positive_share) return 0.0;
  const boost::math::lognormal_distribution<double, MathPolicy> d(fit.positive.mu,
                                                                  fit.positive.sigma);
  return boost::math::quantile(boost::math::complement(d, q / positive_share));
}

}  // namespace pierre::stats
