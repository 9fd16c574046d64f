// Empirical percentiles, Hyndman & Fan (1996) type 7 — the default of R's quantile() and of
// NumPy's percentile (method "linear"). For the sorted sample x[0] <= ... <= x[n-1] and
// p in [0, 100]:
//   h = (n - 1) p / 100,  j = floor(h),  P(p) = x[j] + (h - j) (x[j+1] - x[j])
// (P(p) = x[j] when h is whole or j = n - 1). So P(0) is the minimum and P(100) the maximum.
//
// Rules: NaN values are left out. +infinity is allowed and means "beyond every value" (a
// right-censored runout, design-checks.md §2): a percentile that needs it is +infinity.
// An empty sample (after NaNs are left out) or p outside [0, 100] gives NaN.
//
// Hand-written: the formula is three lines, and neither Boost nor GSL offers type 7 on an
// unsorted sample in O(n) (gsl_stats_quantile_from_sorted_data is type 7 but needs a sort).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace pierre::stats {

// A copy of the sample without its NaN values (missing values), in the same order.
std::vector<double> without_nan(std::span<const double> sample);

// One percentile in O(n) (std::nth_element on a copy): the input is not reordered.
double percentile(std::span<const double> sample, double p);

// Many percentiles from one copy, in O(n) for each (no sort).
std::vector<double> percentiles(std::span<const double> sample, std::span<const double> ps);

// One percentile of a sample already sorted ascending (no NaN): O(1).
double percentile_of_sorted(std::span<const double> sorted, double p);

// The type-7 position h = (n - 1) p / 100 as its whole part `lo` (0-based rank) and fraction
// `frac`; false when n = 0 or p is outside [0, 100]. Every type-7 percentile here, the
// bootstraps' included, finds its ranks with this.
bool type7_position(std::size_t n, double p, std::size_t& lo, double& frac);

// x_lo + frac (x_lo+1 - x_lo), but exact when frac = 0 or the two are equal, so that an
// infinite neighbour does not turn a finite answer into NaN (inf - inf, 0 · inf).
double type7_interpolate(double x_lo, double x_next, double frac);

}  // namespace pierre::stats
