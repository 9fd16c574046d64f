// Seeded samples for the statistics tests, drawn by inversion from std::mt19937_64: the standard
// fixes that engine's output exactly (a std:: distribution's is implementation-defined), so a
// test's sample is the same on every machine and compiler.
#pragma once

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace pierre::test {

// A uniform in (0, 1): the top 53 bits of one draw, offset by half a step (never 0 or 1).
inline double seeded_uniform(std::mt19937_64& g) {
  return (static_cast<double>(g() >> 11) + 0.5) * 0x1.0p-53;
}

// A standard normal: its quantile at a uniform, −√2 erfc⁻¹(2U).
inline double seeded_normal(std::mt19937_64& g) {
  return -std::sqrt(2.0) * boost::math::erfc_inv(2 * seeded_uniform(g));
}

// n values of a Weibull(shape k, scale λ): λ (−ln U)^(1/k).
inline std::vector<double> seeded_weibull(double k, double lambda, std::size_t n,
                                          std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::vector<double> x(n);
  for (double& v : x) v = lambda * std::pow(-std::log(seeded_uniform(g)), 1.0 / k);
  return x;
}

}  // namespace pierre::test
