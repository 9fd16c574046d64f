// Time of the statistics layer on 10^6 values (bench/README.md): empirical percentiles,
// Weibull and log-normal ML fits, one-sample KS, and a 1000-resample bootstrap of the 95th
// percentile. The sample is drawn here from a known Weibull (k = 1.37, λ = 1.55: Table D.2's
// screen-1 heights) by inversion on Philox uniforms, so every run times the same numbers.
// Usage: bench_stats [n]   (default 1000000). Wall-clock seconds on one thread.
#include <Random123/philox.h>
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "pierre/stats/bootstrap.hpp"
#include "pierre/stats/bootstrap_weibull.hpp"
#include "pierre/stats/censored_lognormal_fit.hpp"
#include "pierre/stats/empirical_cdf.hpp"
#include "pierre/stats/exceedance.hpp"
#include "pierre/stats/kolmogorov_smirnov.hpp"
#include "pierre/stats/lognormal_fit.hpp"
#include "pierre/stats/percentile.hpp"
#include "pierre/stats/resample_index_stream.hpp"
#include "pierre/stats/sample_summary.hpp"
#include "pierre/stats/weibull_fit.hpp"

namespace {

using Clock = std::chrono::steady_clock;
namespace st = pierre::stats;

template <class F>
double seconds(F&& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::vector<double> weibull_sample(std::size_t n, double k, double lambda) {
  std::vector<double> x(n);
  const r123::Philox4x32::key_type key{{2015u, 0u}};
  r123::Philox4x32 philox;
  for (std::size_t i = 0; i < n; i += 2) {
    const r123::Philox4x32::ctr_type ctr{{static_cast<std::uint32_t>(i / 2), 0u, 0u, 0u}};
    const auto b = philox(ctr, key);
    const double u[2] = {st::open_unit_interval((std::uint64_t{b[0]} << 32) | b[1]),
                         st::open_unit_interval((std::uint64_t{b[2]} << 32) | b[3])};
    for (std::size_t j = 0; j < 2 && i + j < n; ++j) {
      x[i + j] = lambda * std::pow(-std::log(u[j]), 1.0 / k);
    }
  }
  return x;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1'000'000;
  const double k = 1.37, lambda = 1.55;
  std::vector<double> x;
  const double t_draw = seconds([&] { x = weibull_sample(n, k, lambda); });
  fmt::print("bench_stats: n = {} values from Weibull(k = {}, lambda = {}), drawn in {:.3f} s\n\n",
             n, k, lambda, t_draw);

  double total = 0;
  auto row = [&](const std::string& what, double s, const std::string& result) {
    total += s;
    fmt::print("{:<44} {:>8.3f} s   {}\n", what, s, result);
  };

  // Each timing is taken before its result is formatted (argument order is unspecified).
  double p95 = 0;
  double t = seconds([&] { p95 = st::percentile(x, 95); });
  row("percentile P95 (nth_element)", t,
      fmt::format("P95 = {:.4f} (exact {:.4f})", p95, lambda * std::pow(-std::log(0.05), 1 / k)));
  const std::vector<double> ps{50, 95, 99};
  std::vector<double> pv;
  t = seconds([&] { pv = st::percentiles(x, ps); });
  row("percentiles P50, P95, P99 (one sort)", t,
      fmt::format("{:.4f} {:.4f} {:.4f}", pv[0], pv[1], pv[2]));
  st::SampleSummary sum;
  t = seconds([&] { sum = st::summarize(x); });
  row("summary (mean, sd, min, max)", t,
      fmt::format("mean {:.4f} sd {:.4f}", sum.mean, sum.standard_deviation));
  const std::vector<double> breaks{0.5, 1, 2, 3, 4};
  std::vector<double> F;
  t = seconds([&] { F = st::empirical_cdf(x, breaks); });
  row("empirical CDF at 5 breaks", t, fmt::format("F(4) = {:.5f}", F[4]));

  st::Outcome<st::WeibullFit> w;
  t = seconds([&] { w = st::fit_weibull(x); });
  row("Weibull ML fit", t,
      w ? fmt::format("k = {:.5f}, lambda = {:.5f}", w->shape, w->scale) : w.error);
  st::Outcome<st::LognormalFit> ln;
  t = seconds([&] { ln = st::fit_lognormal(x); });
  row("log-normal ML fit", t,
      ln ? fmt::format("mu = {:.5f}, sigma = {:.5f}", ln->mu, ln->sigma) : ln.error);

  if (w) {
    const st::WeibullFit fit = *w;
    st::Outcome<st::KolmogorovSmirnovTest> ks;
    t = seconds([&] { ks = st::kolmogorov_smirnov(x, [&](double v) { return st::cdf(fit, v); }); });
    row("one-sample KS vs fitted Weibull", t,
        ks ? fmt::format("D = {:.2e}, p = {:.3f}", ks->statistic, ks->p_value) : ks.error);
  }

  st::Outcome<st::BootstrapInterval> ci;
  t = seconds([&] { ci = st::bootstrap_percentile_interval(x, 95, 42); });
  row("bootstrap P95, 1000 resamples (order stats)", t,
      ci ? fmt::format("90 % CI [{:.4f}, {:.4f}]", ci->lower, ci->upper) : ci.error);
  fmt::print("{:<44} {:>8.3f} s   (goal: under 5 s)\n\n", "TOTAL", total);

  // Not in the total: the same statistics with right-censoring, and the generic bootstrap.
  std::vector<double> observed, censored;
  const double end = pv[2];  // censor the top 1 % at the P99, like a profile end
  for (double v : x) (v > end ? censored : observed).push_back(v > end ? end : v);
  st::Outcome<st::CensoredLognormalFit> cl;
  const double t_cens = seconds([&] { cl = st::fit_censored_lognormal(observed, censored); });
  fmt::print("{:<44} {:>8.3f} s   {}\n", "censored log-normal fit (1 % censored)", t_cens,
             cl ? fmt::format("mu = {:.5f}, sigma = {:.5f}", cl->positive.mu, cl->positive.sigma)
                : cl.error);
  // Type-7 P95 by nth_element in the resample buffer itself (no copy).
  const auto in_place_p95 = [](std::span<double> v) {
    const double h = static_cast<double>(v.size() - 1) * 95 / 100;
    const auto lo = static_cast<std::ptrdiff_t>(std::floor(h));
    std::nth_element(v.begin(), v.begin() + lo, v.end());
    if (static_cast<std::size_t>(lo) + 1 >= v.size()) return v[lo];
    const double a = v[lo], b = *std::min_element(v.begin() + lo + 1, v.end());
    return a + (h - static_cast<double>(lo)) * (b - a);
  };
  const std::size_t few = 10;
  st::Outcome<std::vector<double>> reps;
  const double t_generic =
      seconds([&] { reps = st::bootstrap_replicates(x, in_place_p95, 42, few); });
  fmt::print("{:<44} {:>8.3f} s   ({} resamples; x{} = {:.1f} s for 1000)\n",
             "generic bootstrap (draw n indices + P95)", t_generic, few, 1000 / few,
             t_generic * 1000 / few);

  // The barrier design's bootstrap (step 8): the Weibull-ML P95 of 1000 resamples, exact
  // (refits of every resample) at the largest n that takes that path, and binned on all n
  // values; on one thread and on every hardware thread (the same replicates either way).
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const std::vector<double> x_exact(x.begin(),
                                    x.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(
                                                    n, st::WeibullBootstrapOptions{}.exact_up_to)));
  for (const auto& [name, sample] : {std::pair{"exact", &x_exact}, std::pair{"binned", static_cast<const std::vector<double>*>(&x)}}) {
    for (unsigned threads : {1u, hw}) {
      st::WeibullBootstrapOptions o;
      o.threads = threads;
      st::Outcome<st::WeibullQuantileReplicates> wr;
      const double tw =
          seconds([&] { wr = st::bootstrap_weibull_quantile_replicates(*sample, 95, 42, o); });
      fmt::print("{:<44} {:>8.3f} s   ({} values, {} thread{}{})\n",
                 fmt::format("Weibull P95 bootstrap, 1000 resamples, {}", name), tw,
                 sample->size(), threads, threads > 1 ? "s" : "",
                 wr ? (wr->method == st::WeibullBootstrapMethod::binned ? ", binned" : ", exact")
                    : ": " + wr.error);
    }
  }
  return 0;
}
