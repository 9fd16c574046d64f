// Root mean squared error between a predicted (simulated) and an observed cumulative
// distribution on the same n break points, thesis Eq 4.1:
//   RMSE = sqrt( (1/n) Σ_i (Ŷ_i - Y_i)² ),
// Ŷ_i, Y_i the CDFs at break i (the thesis uses the break points of the observation
// reports). Fails when the two have different lengths, are empty, or hold NaN.
#pragma once

#include <span>

#include "pierre/stats/outcome.hpp"

namespace pierre::stats {

Outcome<double> cdf_rmse(std::span<const double> predicted_cdf,
                         std::span<const double> observed_cdf);

// The same with both CDFs taken empirically (empirical_cdf.hpp) from two samples.
Outcome<double> cdf_rmse(std::span<const double> simulated, std::span<const double> observed,
                         std::span<const double> breaks);

}  // namespace pierre::stats
