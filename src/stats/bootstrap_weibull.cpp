// The bootstrap of a Weibull-ML quantile: exact for small samples, the Poisson bootstrap over
// quantile bins for large ones. The method and why its error is negligible:
// bootstrap_weibull.hpp.
#include "pierre/stats/bootstrap_weibull.hpp"

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "pierre/stats/bootstrap.hpp"
#include "pierre/stats/math_policy.hpp"
#include "pierre/stats/percentile.hpp"
#include "pierre/stats/resample_blocks.hpp"
#include "pierre/stats/resample_index_stream.hpp"
#include "pierre/stats/weibull_fit.hpp"

namespace pierre::stats {
namespace {

using Out = Outcome<WeibullQuantileReplicates>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// The Poisson counts' Philox blocks: attempts 2^31, 2^31 + 1, ... of pair = bin. The
// within-bin indices (ResampleIndexStream::next) use attempts 0, 1, ...: never as high.
constexpr std::uint32_t kCountAttempt = 0x80000000u;
constexpr std::uint32_t kMaxCountTries = 1000;  // PTRS accepts with probability > 0.8 per try

// ---- exact: Efron's bootstrap, as the design procedure always did for n <= exact_up_to ----

Out exact_replicates(std::span<const double> sample, double p, std::uint64_t seed,
                     const WeibullBootstrapOptions& o) {
  WeibullQuantileReplicates out;
  out.method = WeibullBootstrapMethod::exact;
  out.weibull.resize(o.resamples);
  if (o.empirical) out.empirical.resize(o.resamples);
  // Each resample's shape is near the sample's own: Newton from there (weibull_fit.hpp).
  const auto whole = fit_weibull(sample);
  const double k_hat = whole ? whole->shape : kNaN;
  const auto n = visit_resamples(sample, seed, o.resamples, o.threads,
                                 [&](std::size_t r, std::span<double> x) {
                                   const auto w = whole ? fit_weibull(x, k_hat) : fit_weibull(x);
                                   // percentile copies: x is not reordered
                                   if (o.empirical) out.empirical[r] = percentile(x, p);
                                   out.weibull[r] = w ? quantile(*w, p / 100.0) : kNaN;
                                 });
  if (!n) return Out::failure(n.error);
  out.values = *n;
  return Out::success(std::move(out));
}

// ---- binned: the Poisson bootstrap over quantile bins ----

// One bin of consecutive sorted values, with what its Poisson count needs (PTRS constants,
// Hörmann 1993 as in NumPy's random_poisson_ptrs, for mu >= 10; e^-mu for inversion below).
struct Bin {
  std::size_t start = 0, size = 0;
  double mu = 0, exp_minus_mu = 0, log_mu = 0;
  double b = 0, a = 0, log_inv_alpha = 0, vr = 0;
};

Bin make_bin(std::size_t start, std::size_t size) {
  Bin bin;
  bin.start = start;
  bin.size = size;
  bin.mu = static_cast<double>(size);
  bin.exp_minus_mu = std::exp(-bin.mu);
  bin.log_mu = std::log(bin.mu);
  bin.b = 0.931 + 2.53 * std::sqrt(bin.mu);
  bin.a = -0.059 + 0.02483 * bin.b;
  bin.log_inv_alpha = std::log(1.1239 + 1.1328 / (bin.b - 3.4));
  bin.vr = 0.9277 - 3.6224 / (bin.b - 2);
  return bin;
}

// A Poisson(bin.mu) count from the Philox blocks of `stream` at pair `pair`; -1 if PTRS
// rejected kMaxCountTries times (probability below 0.2^1000).
std::int64_t poisson_count(const ResampleIndexStream& stream, std::uint32_t pair, const Bin& bin) {
  if (bin.mu < 10) {  // inversion: the smallest k with F(k) >= u
    const auto blk = stream.block(pair, kCountAttempt);
    const double u = open_unit_interval(ResampleIndexStream::word(blk, 0));
    double prob = bin.exp_minus_mu, cdf = prob;
    std::int64_t k = 0;
    while (u > cdf && k < 1000) {  // (rounding can leave cdf a hair below 1)
      ++k;
      prob *= bin.mu / static_cast<double>(k);
      cdf += prob;
    }
    return k;
  }
  for (std::uint32_t t = 0; t < kMaxCountTries; ++t) {
    const auto blk = stream.block(pair, kCountAttempt + t);
    const double u = open_unit_interval(ResampleIndexStream::word(blk, 0)) - 0.5;
    const double v = open_unit_interval(ResampleIndexStream::word(blk, 1));
    const double us = 0.5 - std::abs(u);  // > 0: u is never exactly ±0.5
    const auto k =
        static_cast<std::int64_t>(std::floor((2 * bin.a / us + bin.b) * u + bin.mu + 0.43));
    if (us >= 0.07 && v <= bin.vr) return k;
    if (k < 0 || (us < 0.013 && v > us)) continue;
    const double kd = static_cast<double>(k);
    if (std::log(v) + bin.log_inv_alpha - std::log(bin.a / (us * us) + bin.b) <=
        -bin.mu + kd * bin.log_mu - boost::math::lgamma(kd + 1, MathPolicy()))
      return k;
  }
  return -1;
}

// The Weibull ML fit of weighted bins (weights w_b, the resample's counts): the root of
//   g(k) = A1/A0 - 1/k - T,  A_j = Σ w_b mean_b(t^j e^{kt}),  T = Σ w_b t̄_b / Σ w_b,
// with mean_b e^{kt} = e^{k t̄}(1 + k² v / 2) and its k-derivatives (bootstrap_weibull.hpp).
class BinnedWeibull {
 public:
  BinnedWeibull(std::vector<double> t_mean, std::vector<double> t_var, double log_max)
      : t_(std::move(t_mean)), v_(std::move(t_var)), log_max_(log_max) {}

  std::size_t size() const { return t_.size(); }

  // The shape and scale for weights w (one per bin), Newton from k_start; nullopt when the
  // weights hold fewer than two values or no spread, or Newton fails.
  std::optional<WeibullFit> fit(std::span<const double> w, double k_start) const {
    double total = 0, sum_t = 0;
    for (std::size_t b = 0; b < t_.size(); ++b) {
      total += w[b];
      sum_t += w[b] * t_[b];
    }
    if (!(total >= 2)) return std::nullopt;
    const double mean_t = sum_t / total;
    double var_t = 0;
    for (std::size_t b = 0; b < t_.size(); ++b)
      var_t += w[b] * (v_[b] + (t_[b] - mean_t) * (t_[b] - mean_t));
    if (!(var_t > 1e-300)) return std::nullopt;

    double k = k_start, lo = 0, hi = kInf;
    for (int it = 0; it < 100; ++it) {
      double a0 = 0, a1 = 0, a2 = 0;
      for (std::size_t b = 0; b < t_.size(); ++b) {
        const double t = t_[b], v = v_[b];
        const double e = w[b] * std::exp(k * t);
        const double c = 1 + 0.5 * k * k * v;
        a0 += e * c;
        a1 += e * (t * c + k * v);
        a2 += e * (t * t * c + 2 * t * k * v + v);
      }
      const double r = a1 / a0;
      const double g = r - 1 / k - mean_t;
      const double gp = a2 / a0 - r * r + 1 / (k * k);
      if (!std::isfinite(g) || !(gp > 0) || !(a0 > 0)) return std::nullopt;
      const double step = g / gp;
      if (std::abs(step) <= 1e-11 * k) {
        WeibullFit f;
        f.shape = k;
        f.scale = std::exp(log_max_ + std::log(a0 / total) / k);
        f.used = static_cast<std::size_t>(total);
        return f;
      }
      if (g < 0)
        lo = k;
      else
        hi = k;
      double next = k - step;
      if (!(next > lo && next < hi)) next = std::isinf(hi) ? 2 * k : 0.5 * (lo + hi);
      k = next;
    }
    return std::nullopt;
  }

 private:
  std::vector<double> t_, v_;  // per fitted bin: mean and variance of t = ln x - log_max
  double log_max_;
};

Out binned_replicates(std::span<const double> sample, double p, std::uint64_t seed,
                      const WeibullBootstrapOptions& o) {
  std::vector<double> s = without_nan(sample);
  const std::size_t n = s.size();
  std::sort(s.begin(), s.end());
  const auto full = fit_weibull(s);
  if (!full) return Out::failure("binned bootstrap: " + full.error);
  const double k_hat = full->shape;

  // Bins: the values <= 0 and the +infinities (in no fit, but in the percentile's ranks) in
  // runs of at most m; the positive finite ones also cut where t's range would pass w_max.
  const std::size_t m =
      std::max<std::size_t>(1, (n + o.rank_bins - 1) / std::max<std::size_t>(1, o.rank_bins));
  const auto i0 = static_cast<std::size_t>(
      std::partition_point(s.begin(), s.end(), [](double x) { return !(x > 0); }) - s.begin());
  const auto i1 = static_cast<std::size_t>(
      std::partition_point(s.begin(), s.end(), [](double x) { return x < kInf; }) - s.begin());
  const double log_max = std::log(s[i1 - 1]);  // fit_weibull succeeded: i1 - i0 >= 2
  const double t_width = o.max_bin_width / k_hat;
  std::vector<Bin> bins;
  std::vector<double> t_mean, t_var;
  std::size_t first_fit = 0;  // bins [first_fit, first_fit + t_mean.size()) are fitted
  const auto runs = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; i += m) bins.push_back(make_bin(i, std::min(m, to - i)));
  };
  runs(0, i0);
  first_fit = bins.size();
  {
    std::vector<double> t(i1 - i0);
    for (std::size_t i = i0; i < i1; ++i) t[i - i0] = std::log(s[i]) - log_max;
    std::size_t start = 0;
    while (start < t.size()) {
      std::size_t end = start + 1;
      while (end < t.size() && end - start < m && t[end] - t[start] <= t_width) ++end;
      double mean = 0;
      for (std::size_t i = start; i < end; ++i) mean += t[i];
      mean /= static_cast<double>(end - start);
      double var = 0;
      for (std::size_t i = start; i < end; ++i) var += (t[i] - mean) * (t[i] - mean);
      var /= static_cast<double>(end - start);
      bins.push_back(make_bin(i0 + start, end - start));
      t_mean.push_back(mean);
      t_var.push_back(var);
      start = end;
    }
  }
  runs(i1, n);
  if (bins.size() >= (std::uint64_t{1} << 32))
    return Out::failure("binned bootstrap: more than 2^32 bins");
  const BinnedWeibull model(std::move(t_mean), std::move(t_var), log_max);
  const std::size_t nfit = model.size();

  // The binned fit of the whole sample: the replicates' starting point.
  std::vector<double> sizes(nfit);
  for (std::size_t b = 0; b < nfit; ++b) sizes[b] = static_cast<double>(bins[first_fit + b].size);
  const auto whole = model.fit(sizes, k_hat);
  if (!whole) return Out::failure("binned bootstrap: the binned Weibull fit of the sample failed");
  const double k_start = whole->shape;

  WeibullQuantileReplicates out;
  out.method = WeibullBootstrapMethod::binned;
  out.values = n;
  out.bins = bins.size();
  out.weibull.resize(o.resamples);
  if (o.empirical) out.empirical.resize(o.resamples);
  // Blocks of resamples over the threads; each block has its own counts and picks.
  for_resample_blocks(o.resamples, o.threads, [&](std::size_t first, std::size_t last) {
    std::vector<double> w(nfit);
    std::vector<std::int64_t> count(bins.size());
    std::vector<std::uint64_t> picks;
    for (std::size_t r = first; r < last; ++r) {
      ResampleIndexStream stream(seed, r);
      bool ok = true;
      std::uint64_t total = 0;
      for (std::size_t b = 0; b < bins.size(); ++b) {
        count[b] = poisson_count(stream, static_cast<std::uint32_t>(b), bins[b]);
        ok = ok && count[b] >= 0;
        total += static_cast<std::uint64_t>(std::max<std::int64_t>(count[b], 0));
      }
      for (std::size_t b = 0; b < nfit; ++b) w[b] = static_cast<double>(count[first_fit + b]);
      const auto f = ok ? model.fit(w, k_start) : std::nullopt;
      out.weibull[r] = f ? quantile(*f, p / 100.0) : kNaN;
      if (!o.empirical) continue;
      if (!ok || total == 0) {
        out.empirical[r] = kNaN;
        continue;
      }
      // Type-7 position in the resample of `total` values; the order statistics lo and lo + 1
      // from the bins holding them, the bin's count spread over its values by uniform indices.
      std::size_t lo = 0;
      double frac = 0;
      type7_position(total, p, lo, frac);
      std::size_t bin = 0, drawn = bins.size();
      std::uint64_t before = 0;  // resample values in bins before `bin`
      const auto value_at = [&](std::uint64_t rank) {
        while (before + static_cast<std::uint64_t>(count[bin]) <= rank) {
          before += static_cast<std::uint64_t>(count[bin]);
          ++bin;
        }
        if (drawn != bin) {
          picks.resize(static_cast<std::size_t>(count[bin]));
          for (auto& i : picks) i = stream.next(bins[bin].size);
          std::sort(picks.begin(), picks.end());
          drawn = bin;
        }
        return s[bins[bin].start + picks[static_cast<std::size_t>(rank - before)]];
      };
      const double x1 = value_at(lo);
      out.empirical[r] =
          (frac > 0 && lo + 1 < total) ? type7_interpolate(x1, value_at(lo + 1), frac) : x1;
    }
  });
  return Out::success(std::move(out));
}

}  // namespace

Outcome<WeibullQuantileReplicates> bootstrap_weibull_quantile_replicates(
    std::span<const double> sample, double p, std::uint64_t seed,
    const WeibullBootstrapOptions& options) {
  const auto n = static_cast<std::size_t>(
      std::count_if(sample.begin(), sample.end(), [](double x) { return !std::isnan(x); }));
  if (auto e = bootstrap_sample_problem(n, options.resamples); !e.empty()) return Out::failure(e);
  if (!(p >= 0.0 && p <= 100.0)) return Out::failure("bootstrap percentile must be in [0, 100]");
  const bool exact =
      options.method == WeibullBootstrapMethod::exact ||
      (options.method == WeibullBootstrapMethod::automatic && n <= options.exact_up_to);
  return exact ? exact_replicates(sample, p, seed, options)
               : binned_replicates(sample, p, seed, options);
}

}  // namespace pierre::stats
