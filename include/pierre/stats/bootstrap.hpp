// Seeded nonparametric bootstrap (Efron's percentile interval) for the confidence of a
// statistic (design-checks.md §1 step 8: the 90 % interval of v_k, h_k, E_d, h_i).
//
// Each of R resamples draws n values with replacement (uniform indices from
// ResampleIndexStream: Philox keyed by the seed, counter = (draw, resample) — the same seed
// gives the same interval on every platform), the statistic is evaluated on it, and the
// interval is the type-7 percentiles 100 (1 - c)/2 and 100 (1 + c)/2 of the R replicates.
//
// bootstrap_percentile_interval is the same bootstrap for the statistic "type-7 percentile
// p", done exactly without drawing n indices per resample: sort the sample once; the j-th
// smallest of n uniform indices is floor(n U_(j)), U_(j) the j-th order statistic of n
// uniforms on (0, 1), which is Beta(j, n - j + 1) (drawn by inversion with Boost.Math's
// ibeta_inv), and given U_(j) the next one is U_(j) + (1 - U_(j)) (1 - V^(1/(n - j))).
// Its replicates have the same distribution as the generic path's (a test checks this) but
// are not the same numbers. Cost: O(n log n) once, then O(1) special functions per
// resample, instead of O(n) per resample. Its uniforms come from the resample's Philox block
// at the reserved attempt, so they are platform-independent; the Beta inversion is floating
// point (std::log/exp/pow inside Boost), which may differ in the last bit between C
// libraries — an index could change only when n·U falls within ~1e-15 of a whole number.
//
// NaN values in the sample are left out. Errors (no exception): empty sample, fewer than 2
// resamples, confidence outside (0, 1), p outside [0, 100], more than 2^33 values, a NaN
// replicate.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "pierre/stats/outcome.hpp"

namespace pierre::stats {

struct BootstrapOptions {
  std::size_t resamples = 1000;
  double confidence = 0.90;
};

struct BootstrapInterval {
  double estimate = 0;  // the statistic on the sample itself
  double lower = 0;
  double upper = 0;
  double confidence = 0;
  std::size_t resamples = 0;
  double half_width() const { return (upper - lower) / 2; }
};

// The percentiles (0..100) at the ends of Efron's percentile interval at `confidence`:
// 100 (1 - c)/2 and 100 (1 + c)/2, exactly 5 and 95 for c = 0.9 (100 c is whole first).
std::array<double, 2> percentile_interval_ends(double confidence);

// What makes a sample unfit for a bootstrap (empty, more than 2^33 values, fewer than two
// resamples), said as the bootstraps' failures say it; empty when it is fit.
std::string bootstrap_sample_problem(std::size_t n, std::size_t resamples);

// A statistic of a resample. It may reorder its argument (e.g. std::nth_element): the
// buffer is refilled for each resample.
using Statistic = std::function<double(std::span<double>)>;

Outcome<BootstrapInterval> bootstrap_interval(std::span<const double> sample,
                                              const Statistic& statistic, std::uint64_t seed,
                                              const BootstrapOptions& options = {});

// The R replicates of the generic bootstrap, in resample order. With threads > 1 the
// resamples are shared out over that many threads (resample_blocks.hpp: the same replicates
// for any count), and `statistic` is called from all of them at once.
Outcome<std::vector<double>> bootstrap_replicates(std::span<const double> sample,
                                                  const Statistic& statistic, std::uint64_t seed,
                                                  std::size_t resamples, unsigned threads = 1);

// The generic bootstrap's loop, for statistics of more than one number: draws every resample r
// of the sample (NaN left out) and calls visit(r, resample), over `threads` threads as above
// (visit is called at once for different r). Returns the number of values resampled.
using ResampleVisitor = std::function<void(std::size_t, std::span<double>)>;
Outcome<std::size_t> visit_resamples(std::span<const double> sample, std::uint64_t seed,
                                     std::size_t resamples, unsigned threads,
                                     const ResampleVisitor& visit);

// The bootstrap of the type-7 percentile p (0..100), by order statistics (see above).
Outcome<BootstrapInterval> bootstrap_percentile_interval(std::span<const double> sample, double p,
                                                         std::uint64_t seed,
                                                         const BootstrapOptions& options = {});

Outcome<std::vector<double>> bootstrap_percentile_replicates(std::span<const double> sample,
                                                             double p, std::uint64_t seed,
                                                             std::size_t resamples);

}  // namespace pierre::stats
