// Bootstrap of a Weibull-ML quantile (design-checks.md §1 step 8: the 90 % interval of v_k and
// h_k when the rule set's `governing` is `weibull` or `larger`). Each replicate is the
// quantile at p of the two-parameter Weibull fitted by maximum likelihood to a resample
// (weibull_fit.hpp), with the type-7 empirical percentile p of the same resample beside it
// (for `larger` = the greater of the two).
//
// Two methods, both seeded bootstraps of the same statistic:
//
// exact (n <= exact_up_to, 20 000 by default): Efron's bootstrap as bootstrap_replicates —
//   n indices per resample from ResampleIndexStream, fit_weibull and percentile on the
//   resample, each fit's Newton started from the sample's own shape k̂ (a resample's is
//   near it). Cost: R · n · (one Philox index, one log, ~6 exp: the Newton passes; ~10 from
//   Menon's estimate with the bracketing, before 2026-11-24): 0.7 s per quantity at
//   n = 20 000 and 1000 resamples, 35 s at 10^6.
//
// binned (n > exact_up_to): the Poisson bootstrap over quantile bins, O(n log n) once and
//   O(bins) per resample (bins <= rank_bins + a few hundred: 4 332 at n = 10^6; 0.3 s per
//   quantity at n = 10^6 and 1000 resamples, sort and full-sample fit included):
//   1. Resample weights. The Poisson bootstrap (Hanley & MacGibbon 2006, "Creating
//      non-parametric bootstrap samples using Poisson frequencies", Comput. Methods Programs
//      Biomed. 83:57; Chamandy, Muralidharan, Najmi & Naidu 2012, "Estimating uncertainty
//      for massive data streams", Google; Oza & Russell 2001, online bagging) gives every
//      value an independent Poisson(1) count instead of the multinomial(n; 1/n, ...) counts
//      of drawing n indices. The two agree to O(1/n): both have E c_i = 1, Var c_i = 1 -
//      O(1/n), and the Weibull MLE and the percentile depend on the counts only through the
//      weighted empirical distribution (c_i / Σc), whose covariances agree to O(1/n²). A
//      resample's size Σ c_i is Poisson(n), not n: it enters the type-7 position only.
//   2. Bins. Sort once; cut the sorted values into bins of at most ceil(n / rank_bins)
//      consecutive values, and, among the positive finite values, also wherever a bin's
//      range of t = ln x would exceed max_bin_width / k̂ (k̂ the sample's ML shape): so bins
//      are quantile bins in the body and narrow in ln x in both tails (236 more bins for
//      Weibull samples of 10^6 values). Per bin: its count m_b, the mean t̄_b of t
//      and the variance v_b of t within it. The sum of m_b Poisson(1) counts is Poisson(m_b):
//      one draw per bin gives the bin's count C_b — exactly, under the Poisson bootstrap.
//   3. Weibull refit. The ML equation g(k) = Σ c e^{kt} t / Σ c e^{kt} - 1/k - Σ c t / Σ c
//      needs Σ_i c_i f(t_i) for f = 1, t, e^{kt}, t e^{kt}, t² e^{kt}. Given the bin counts
//      C_b, the counts inside a bin are multinomial(C_b; uniform), so the conditional mean of
//      Σ_{i in b} c_i f(t_i) is C_b · mean_b f: that is what the binned fit uses, with mean_b
//      e^{kt} = e^{k t̄_b} (1 + k² v_b / 2) (and its k-derivatives for the t e^{kt}, t² e^{kt}
//      terms, so Newton uses the exact derivative of the equation it solves). Newton from the
//      binned full-sample root, safeguarded by the bracket of the sign changes, to 1e-12.
//   4. Empirical percentile. The type-7 position in the resample of Σ C_b values falls in a
//      known bin (cumulative C_b); only there (and in the next bin when the neighbour rank is
//      past it) are the C_b counts spread over the bin's values, by C_b uniform indices from
//      ResampleIndexStream — so the empirical replicate is exact under the Poisson bootstrap.
//
// Why the binning error is negligible next to the interval's Monte Carlo error. The binned
// replicate differs from the exact Poisson-bootstrap replicate by (a) the Taylor remainder of
// mean_b e^{kt}, relative O((k w_b)^3) ≤ 2e-6 for a bin of ln-width w_b ≤ 0.02 / k̂ (and the
// resample's k within a few % of k̂), the same in every replicate; (b) the within-bin spread of
// the counts that step 3 averages out: its variance is Σ_b m_b Var_b f ≈ Σ_b m_b f'(t̄_b)² v_b,
// with v_b ≤ w_b² / 12, against the bootstrap variance Σ_i Var f of the whole sum — a fraction
// below (0.02)² / 12 ≈ 3e-5 in the narrow tail bins and of order 1 / (12 rank_bins²) ≈ 5e-9 in
// the body. So the replicates' spread, and the interval's half-width, change by a relative
// 1e-5 or less. The Monte Carlo error of the endpoints of a 90 % percentile interval from
// R = 1000 replicates is sd ≈ √(0.05 · 0.95 / R) / φ(1.645) ≈ 0.067 σ ≈ 4 % of the half-width
// (σ the replicates' sd): three orders of magnitude more. (The tests compare the binned and
// exact intervals on 50 000 values, and the binned one with the delta-method standard error.
// Measured on 25 000 Weibull values, 3 × 20 000 replicates: the replicates' sd with 3 630
// bins and with one bin per value (no binning) agree to 0.1 %.)
//
// Random numbers: the binned path's count for bin b of resample r uses the Philox blocks of
// ResampleIndexStream(seed, r) at pair b and attempts 2^31, 2^31 + 1, ... (Hörmann's PTRS
// transformed rejection for m_b >= 10, "The transformed rejection method for generating
// Poisson random variables", Insurance: Math. Econ. 12 (1993) 39, as in NumPy; inversion
// below 10); its within-bin indices use the same stream's next() (attempts 0, 1, ...). Same
// seed, same replicates; the rejection tests and the fit are floating point (std::exp/log,
// Boost's lgamma), so another C library may differ in the last bits, as for the other paths.
//
// NaN values are left out (as bootstrap_replicates). Errors (no exception): empty sample,
// fewer than 2 resamples, p outside [0, 100], more than 2^33 values, and for the binned path a
// sample whose own Weibull fit fails. A replicate whose fit fails is NaN (the caller decides).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pierre/stats/outcome.hpp"

namespace pierre::stats {

enum class WeibullBootstrapMethod { automatic, exact, binned };

struct WeibullBootstrapOptions {
  std::size_t resamples = 1000;
  WeibullBootstrapMethod method = WeibullBootstrapMethod::automatic;
  std::size_t exact_up_to = 20000;  // automatic: exact for n <= this (NaN left out), else binned
  std::size_t rank_bins = 4096;     // binned: at most ceil(n / rank_bins) values per bin
  double max_bin_width = 0.02;      // binned: k̂ · (a bin's range of ln x) at most this
  bool empirical = true;            // also the empirical percentile of each resample
  unsigned threads = 1;             // resamples shared out over this many threads (the same
                                    // replicates for any count: resample_blocks.hpp)
};

struct WeibullQuantileReplicates {
  std::vector<double> weibull;    // ML Weibull quantile at p of each resample (NaN: no fit)
  std::vector<double> empirical;  // type-7 percentile p of the same resample (if asked)
  WeibullBootstrapMethod method = WeibullBootstrapMethod::exact;  // the one used
  std::size_t values = 0;         // n, NaN left out
  std::size_t bins = 0;           // binned: the number of bins
};

// p in [0, 100]; the replicates in resample order.
Outcome<WeibullQuantileReplicates> bootstrap_weibull_quantile_replicates(
    std::span<const double> sample, double p, std::uint64_t seed,
    const WeibullBootstrapOptions& options = {});

}  // namespace pierre::stats
