#include "pierre/stats/cdf_rmse.hpp"

#include <cmath>
#include <string>

#include "pierre/stats/empirical_cdf.hpp"

namespace pierre::stats {

// Hand-written: Eq 4.1 is one sum.
Outcome<double> cdf_rmse(std::span<const double> predicted_cdf,
                         std::span<const double> observed_cdf) {
  if (predicted_cdf.size() != observed_cdf.size()) {
    return Outcome<double>::failure("RMSE of CDFs with different numbers of break points (" +
                                    std::to_string(predicted_cdf.size()) + " and " +
                                    std::to_string(observed_cdf.size()) + ")");
  }
  if (predicted_cdf.empty()) return Outcome<double>::failure("RMSE of CDFs with no break points");
  double ss = 0;
  for (std::size_t i = 0; i < predicted_cdf.size(); ++i) {
    const double e = predicted_cdf[i] - observed_cdf[i];
    if (std::isnan(e)) return Outcome<double>::failure("RMSE of CDFs holding NaN");
    ss += e * e;
  }
  return Outcome<double>::success(std::sqrt(ss / static_cast<double>(predicted_cdf.size())));
}

Outcome<double> cdf_rmse(std::span<const double> simulated, std::span<const double> observed,
                         std::span<const double> breaks) {
  const auto predicted = empirical_cdf(simulated, breaks);
  const auto obs = empirical_cdf(observed, breaks);
  return cdf_rmse(std::span<const double>(predicted), std::span<const double>(obs));
}

}  // namespace pierre::stats
