#include "pierre/stats/bootstrap.hpp"

#include <algorithm>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <utility>

#include "pierre/stats/math_policy.hpp"
#include "pierre/stats/percentile.hpp"
#include "pierre/stats/resample_blocks.hpp"
#include "pierre/stats/resample_index_stream.hpp"

namespace pierre::stats {
namespace {

// Efron's percentile interval from the replicates.
Outcome<BootstrapInterval> interval(double estimate, std::vector<double> replicates,
                                    const BootstrapOptions& options) {
  for (double r : replicates) {
    if (std::isnan(r)) return Outcome<BootstrapInterval>::failure("bootstrap replicate is NaN");
  }
  std::sort(replicates.begin(), replicates.end());
  const auto ends = percentile_interval_ends(options.confidence);
  BootstrapInterval b;
  b.estimate = estimate;
  b.lower = percentile_of_sorted(replicates, ends[0]);
  b.upper = percentile_of_sorted(replicates, ends[1]);
  b.confidence = options.confidence;
  b.resamples = replicates.size();
  return Outcome<BootstrapInterval>::success(b);
}

bool bad_confidence(double c) { return !(c > 0.0 && c < 1.0); }

}  // namespace

std::array<double, 2> percentile_interval_ends(double confidence) {
  const double c = 100.0 * confidence;  // 90 exactly for 0.9, so the ends are 5 and 95 exactly
  return {0.5 * (100.0 - c), 0.5 * (100.0 + c)};
}

std::string bootstrap_sample_problem(std::size_t n, std::size_t resamples) {
  if (n == 0) return "bootstrap of an empty sample";
  if (n > ResampleIndexStream::kMaxValues) return "bootstrap of more than 2^33 values";
  if (resamples < 2) return "bootstrap needs at least 2 resamples";
  return {};
}

Outcome<std::size_t> visit_resamples(std::span<const double> sample, std::uint64_t seed,
                                     std::size_t resamples, unsigned threads,
                                     const ResampleVisitor& visit) {
  const std::vector<double> v = without_nan(sample);
  if (auto e = bootstrap_sample_problem(v.size(), resamples); !e.empty()) {
    return Outcome<std::size_t>::failure(e);
  }
  const std::uint64_t n = v.size();
  for_resample_blocks(resamples, threads, [&](std::size_t first, std::size_t last) {
    std::vector<double> buffer(v.size());  // reused: one allocation per block of resamples
    for (std::size_t r = first; r < last; ++r) {
      ResampleIndexStream stream(seed, r);
      for (double& x : buffer) x = v[stream.next(n)];
      visit(r, buffer);
    }
  });
  return Outcome<std::size_t>::success(v.size());
}

Outcome<std::vector<double>> bootstrap_replicates(std::span<const double> sample,
                                                  const Statistic& statistic, std::uint64_t seed,
                                                  std::size_t resamples, unsigned threads) {
  std::vector<double> out(resamples);
  const auto done =
      visit_resamples(sample, seed, resamples, threads,
                      [&](std::size_t r, std::span<double> x) { out[r] = statistic(x); });
  if (!done) return Outcome<std::vector<double>>::failure(done.error);
  return Outcome<std::vector<double>>::success(std::move(out));
}

Outcome<BootstrapInterval> bootstrap_interval(std::span<const double> sample,
                                              const Statistic& statistic, std::uint64_t seed,
                                              const BootstrapOptions& options) {
  if (bad_confidence(options.confidence)) {
    return Outcome<BootstrapInterval>::failure("bootstrap confidence must be in (0, 1)");
  }
  auto reps = bootstrap_replicates(sample, statistic, seed, options.resamples);
  if (!reps) return Outcome<BootstrapInterval>::failure(reps.error);
  std::vector<double> copy = without_nan(sample);
  const double estimate = statistic(copy);
  return interval(estimate, std::move(*reps.value), options);
}

Outcome<std::vector<double>> bootstrap_percentile_replicates(std::span<const double> sample,
                                                             double p, std::uint64_t seed,
                                                             std::size_t resamples) {
  std::vector<double> s = without_nan(sample);
  if (auto e = bootstrap_sample_problem(s.size(), resamples); !e.empty()) {
    return Outcome<std::vector<double>>::failure(e);
  }
  if (!(p >= 0.0 && p <= 100.0)) {
    return Outcome<std::vector<double>>::failure("bootstrap percentile must be in [0, 100]");
  }
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  const double nd = static_cast<double>(n);
  // The type-7 ranks lo and lo + 1 (0-based).
  std::size_t lo = 0;
  double frac = 0;
  type7_position(n, p, lo, frac);
  const bool two = frac > 0.0 && lo + 1 < n;
  const double a = static_cast<double>(lo + 1);  // 1-based rank j: U_(j) ~ Beta(j, n - j + 1)
  const double b = nd - a + 1.0;
  const double above = nd - a;  // uniforms above U_(j)
  const auto index = [&](double u) {
    return std::min(n - 1, static_cast<std::size_t>(std::floor(nd * u)));
  };
  std::vector<double> out(resamples);
  for (std::size_t r = 0; r < resamples; ++r) {
    const auto blk = ResampleIndexStream(seed, r).block(0, ResampleIndexStream::kReservedAttempt);
    const double u1 = open_unit_interval(ResampleIndexStream::word(blk, 0));
    const double u2 = open_unit_interval(ResampleIndexStream::word(blk, 1));
    const double uj = boost::math::ibeta_inv(a, b, u1, MathPolicy());
    const double x1 = s[index(uj)];
    if (!two) {
      out[r] = x1;
      continue;
    }
    // The smallest of the n - j uniforms above U_(j): U_(j) + (1 - U_(j)) (1 - V^(1/(n-j))).
    const double uj1 = uj + (1.0 - uj) * -std::expm1(std::log(u2) / above);
    const double x2 = s[index(uj1)];
    out[r] = type7_interpolate(x1, x2, frac);
  }
  return Outcome<std::vector<double>>::success(std::move(out));
}

Outcome<BootstrapInterval> bootstrap_percentile_interval(std::span<const double> sample, double p,
                                                         std::uint64_t seed,
                                                         const BootstrapOptions& options) {
  if (bad_confidence(options.confidence)) {
    return Outcome<BootstrapInterval>::failure("bootstrap confidence must be in (0, 1)");
  }
  auto reps = bootstrap_percentile_replicates(sample, p, seed, options.resamples);
  if (!reps) return Outcome<BootstrapInterval>::failure(reps.error);
  return interval(percentile(sample, p), std::move(*reps.value), options);
}

}  // namespace pierre::stats
