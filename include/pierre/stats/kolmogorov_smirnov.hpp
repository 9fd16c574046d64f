// Kolmogorov–Smirnov statistics.
//  One sample: D = sup |F_n(x) - F(x)| against any continuous CDF F (a callable),
//    computed exactly at the order statistics: D = max_i max(i/n - F(x_(i)), F(x_(i)) - (i-1)/n).
//  Two samples: D = sup |F_a(x) - F_b(x)|, ties stepped together.
// p-values (Boost.Math's boost/math/distributions/kolmogorov_smirnov.hpp, Boost >= 1.75):
//  `p_value` is the ASYMPTOTIC one, P(K > √n_e · D), K the Kolmogorov distribution (the limit
//    of √n · D_n), n_e = n (one sample) or n_a n_b / (n_a + n_b) (two samples).
//  `p_value_stephens` applies Stephens' (1970) small-sample correction,
//    P(K > (√n_e + 0.12 + 0.11/√n_e) · D), as in Numerical Recipes' kstwo; it is closer to
//    the exact one-sample p-value for n >= ~5 and is the one to prefer for small samples.
// Caveat: when F's parameters were fitted to the same sample, both p-values are too large
// (Lilliefors): a low p-value is still evidence against the fit, a high one is weak support.
// NaN values are left out; an empty sample is an error.
#pragma once

#include <functional>
#include <span>

#include "pierre/stats/outcome.hpp"

namespace pierre::stats {

struct KolmogorovSmirnovTest {
  double statistic = 0;         // D
  double p_value = 1;           // asymptotic
  double p_value_stephens = 1;  // with Stephens' correction
  double n_effective = 0;       // n_e
};

Outcome<KolmogorovSmirnovTest> kolmogorov_smirnov(std::span<const double> sample,
                                                  const std::function<double(double)>& cdf);

Outcome<KolmogorovSmirnovTest> kolmogorov_smirnov_two_sample(std::span<const double> a,
                                                             std::span<const double> b);

// P(K > √n_e · d), the asymptotic p-value of a statistic d.
double kolmogorov_p_value(double d, double n_effective);
// P(K > (√n_e + 0.12 + 0.11/√n_e) · d).
double kolmogorov_p_value_stephens(double d, double n_effective);

}  // namespace pierre::stats
