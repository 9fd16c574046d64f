// Statistics of the quarry distances (design-checks.md §2, "Statistics"): P50, P95, P99 and
// maximum of ID and RD in metres and divided by H (the columns of thesis Tables 6.2, 6.3); a
// log-normal of the /H values fitted by maximum likelihood over the positive values, with
// right-censored values as censored observations and the zeros as a point mass p0, so that
// P(X > d) = (1 − p0) S_logn(d) for d > 0 (stats/censored_lognormal_fit.hpp; thesis Fig 6.5);
// its KS statistic; the distance at a probability of exceedance; comparisons with observed
// values (CDF RMSE on the observed break points, Eq 4.1, and the two-sample KS statistic).
//
// Percentiles are type 7 (stats/percentile.hpp) with the right-censored values (+infinity: a
// block that left the profile) as design-checks.md §2 has them: when more than (1 − p) of all
// values are censored, the p-th percentile is +infinity, "beyond the profile"; otherwise it is
// the percentile with each censored value at its censoring distance (all that is known of it).
// So the maximum is beyond the profile as soon as one block left. Samples pooled over sections
// of different H are normalized value by value, each by its own section's H; the /H percentiles
// are those of the normalized sample (for one section, exactly the metre percentiles / H).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pierre/stats/censored_lognormal_fit.hpp"
#include "pierre/stats/kolmogorov_smirnov.hpp"

namespace pierre::design {

// One distance (ID or RD) of one section, or pooled over several.
struct DistanceSample {
  std::vector<double> metres;      // m; +infinity: censored
  std::vector<double> normalized;  // / H of its own section; +infinity: censored
  std::vector<double> censored_at;  // / H: the censoring threshold of each censored value
  // The largest threshold of the sections added, / H and in m: where a censored value stands
  // in a percentile, beyond every stop (design-checks.md §2: "beyond every distance"; in a
  // pool, a short floor's end can lie below another section's stops).
  double beyond = 0;
  double beyond_m = 0;
  // Appends a section's values (m) with its H and the distance where its censored values
  // were censored (the floor length, m).
  void add(std::span<const double> values_m, double height, double censor_distance);
  std::size_t size() const { return metres.size(); }
};

// KS test of the fit's log-normal against the positive values (the zeros are the fit's own
// point mass p0, their sample share: nothing to test), taken below the smallest censoring
// threshold (above it the sample's CDF is not known; a censored value counts among the n as one
// beyond it); p-value with Stephens' correction, n = the positive values, censored included.
// The fit's parameters come from the same sample: the p-value is too large (Lilliefors).
struct PositivePartKs {
  double statistic = 0;
  double p_value = 1;
  std::size_t n = 0;         // the positive values, censored ones included
  std::size_t observed = 0;  // of those, the values below `below`: the ones the test sees
  double below = 0;     // the supremum is taken for d < below (+infinity: uncensored)
};

struct DistanceStatistics {
  std::size_t count = 0, zeros = 0, censored = 0;
  double p50 = 0, p95 = 0, p99 = 0, max = 0;          // m
  double p50_h = 0, p95_h = 0, p99_h = 0, max_h = 0;  // / H
  std::optional<stats::CensoredLognormalFit> fit;  // of the /H values
  std::optional<PositivePartKs> ks;
  std::string fit_error;  // why there is no fit
};

DistanceStatistics distance_statistics(const DistanceSample& sample);

stats::Outcome<PositivePartKs> positive_part_ks(std::span<const double> sample,
                                                const stats::CensoredLognormalFit& fit,
                                                double below);

// The type-7 percentile p (0 to 100) of `values`, whose +infinity are right-censored:
// +infinity, beyond the profile, when more than (1 − p/100) of the values are censored; else the
// percentile with every censored value at `beyond` (a DistanceSample's beyond or beyond_m).
// NaN for an empty sample or a p outside [0, 100].
double censored_percentile(std::span<const double> values, double beyond, double p);
// The same for several p, sorting the sample once.
std::vector<double> censored_percentiles(std::span<const double> values, double beyond,
                                         std::span<const double> ps);

// The empirical distance (/H) exceeded with probability q: censored_percentile at 100 (1 − q)
// of the normalized sample; NaN for q outside [0, 1].
double empirical_at_exceedance(const DistanceSample& sample, double q);
// Share of the sample above d (censored values are above every d).
double empirical_exceedance(std::span<const double> sample, double d);

// Observed values of one distance: raw observations and/or printed summary values.
struct ObservedDistance {
  std::vector<double> metres;  // raw observations, m (may be empty)
  std::vector<double> heights;  // H of the section of each raw observation, m
  std::optional<double> p50, p95, max;  // printed summary values, m
  std::optional<std::size_t> count;     // number of observations behind the summary
  bool empty() const { return metres.empty() && !p50 && !p95 && !max; }
};

struct ObservedComparison {
  bool raw = false;       // from raw observations (else from printed summary values)
  std::size_t count = 0;  // observations (0 when unknown)
  double p50 = 0, p95 = 0, max = 0;          // m (NaN when unknown)
  double p50_h = 0, p95_h = 0, max_h = 0;    // / H
  // Every observation at the row's own H (one face, or summary values): the values in metres
  // are the row's as given, not p95_h · H back again (13.6, not 13.599999999999998).
  bool at_row_height = true;
  // Eq 4.1: the CDFs at the observed break points (/H): with raw observations their distinct
  // values; with summary values the printed P50, P95 and max, whose observed CDF is 0.50,
  // 0.95 and 1.
  std::vector<double> breaks_h, simulated_cdf, observed_cdf;
  std::optional<double> cdf_rmse;
  std::optional<stats::KolmogorovSmirnovTest> ks;  // two-sample, raw observations only
};

// `height` converts summary values to /H (the row's H; raw values use their own).
ObservedComparison compare_observed(const DistanceSample& simulated, const ObservedDistance& observed,
                                    double height);

struct DurationStatistics {
  std::size_t count = 0;
  double p50 = 0, p95 = 0, max = 0;  // s
};
DurationStatistics duration_statistics(std::span<const double> durations);

}  // namespace pierre::design
