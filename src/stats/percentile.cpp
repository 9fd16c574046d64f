#include "pierre/stats/percentile.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>

namespace pierre::stats {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

bool type7_position(std::size_t n, double p, std::size_t& lo, double& frac) {
  if (n == 0 || !(p >= 0.0 && p <= 100.0)) return false;
  const double h = static_cast<double>(n - 1) * p / 100.0;  // p/100 last: exact for whole h
  lo = std::min(static_cast<std::size_t>(std::floor(h)), n - 1);
  frac = h - static_cast<double>(lo);
  return true;
}

double type7_interpolate(double x_lo, double x_next, double frac) {
  if (frac == 0.0 || x_lo == x_next) return x_lo;
  return x_lo + frac * (x_next - x_lo);
}

double percentile_of_sorted(std::span<const double> sorted, double p) {
  std::size_t lo = 0;
  double frac = 0;
  if (!type7_position(sorted.size(), p, lo, frac)) return kNaN;
  if (lo + 1 >= sorted.size()) return sorted[lo];
  return type7_interpolate(sorted[lo], sorted[lo + 1], frac);
}

double percentile(std::span<const double> sample, double p) {
  std::vector<double> v = without_nan(sample);
  std::size_t lo = 0;
  double frac = 0;
  if (!type7_position(v.size(), p, lo, frac)) return kNaN;
  const auto nth = v.begin() + static_cast<std::ptrdiff_t>(lo);
  std::nth_element(v.begin(), nth, v.end());
  if (frac == 0.0 || lo + 1 >= v.size()) return *nth;
  // After nth_element everything past nth is >= it: the next order statistic is their minimum.
  const double next = *std::min_element(nth + 1, v.end());
  return type7_interpolate(*nth, next, frac);
}

std::vector<double> percentiles(std::span<const double> sample, std::span<const double> ps) {
  std::vector<double> v = without_nan(sample);
  // The order statistics the percentiles need, each put in its sorted place by nth_element on
  // what lies past the one before: O(n) for each, where a sort of 10^7 values costs ~1 s.
  std::vector<std::size_t> ranks;
  for (double p : ps) {
    std::size_t lo = 0;
    double frac = 0;
    if (!type7_position(v.size(), p, lo, frac)) continue;
    ranks.push_back(lo);
    if (lo + 1 < v.size()) ranks.push_back(lo + 1);
  }
  std::sort(ranks.begin(), ranks.end());
  auto from = v.begin();
  for (std::size_t k : ranks) {
    const auto nth = v.begin() + static_cast<std::ptrdiff_t>(k);
    if (nth < from) continue;  // placed already
    std::nth_element(from, nth, v.end());
    from = nth + 1;
  }
  // v is now sorted at every rank read below, which is all percentile_of_sorted reads.
  std::vector<double> out;
  out.reserve(ps.size());
  for (double p : ps) out.push_back(percentile_of_sorted(v, p));
  return out;
}

std::vector<double> without_nan(std::span<const double> sample) {
  std::vector<double> v;
  v.reserve(sample.size());
  std::copy_if(sample.begin(), sample.end(), std::back_inserter(v),
               [](double x) { return !std::isnan(x); });
  return v;
}

}  // namespace pierre::stats
