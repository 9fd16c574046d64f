// Empirical cumulative distribution F_n(b) = #{x_i <= b} / n at given break points (the
// right-continuous step function, as R's ecdf). NaN values are left out of the count and of
// n; +infinity counts in n and lies above every finite break (a right-censored value).
// An empty sample gives NaN at every break. Hand-written: a sort and a binary search.
#pragma once

#include <span>
#include <vector>

namespace pierre::stats {

std::vector<double> empirical_cdf(std::span<const double> sample, std::span<const double> breaks);

}  // namespace pierre::stats
