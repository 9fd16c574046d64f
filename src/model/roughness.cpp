#include "pierre/model/roughness.hpp"

#include <algorithm>
#include <cmath>

namespace pierre::model {

double RoughnessModel::size_factor(double diameter) const {
  if (!size_reduction) return 1.0;
  return std::max(floor, b - m * diameter);  // Eq 6.6 with the floor of §3.4.1
}

double RoughnessModel::kept_mass() const {
  return distribution == RoughnessDistribution::truncated_normal ? normal_cdf(mean / sd) : 1.0;
}

double RoughnessModel::sample(double u, double kept) const {
  if (distribution == RoughnessDistribution::uniform) return u;  // Eq 3.4
  // Inverse CDF of N(μ, σ²) restricted to X > 0, S = Φ(μ/σ) the mass kept: z = Φ⁻¹(1 − (1 − u) S)
  // = −Φ⁻¹((1 − u) S). Written from the upper tail, S keeps its digits when μ lies well below 0
  // (Φ(−μ/σ) = 1 − S would round to 1 and every draw to +∞); 1 − u is exact for our uniforms.
  return std::max(0.0, mean - sd * normal_quantile((1.0 - u) * kept));
}

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double normal_quantile(double p) {
  // Wichura, M. J. (1988) Algorithm AS 241, Applied Statistics 37(3):477–484, PPND16.
  const double q = p - 0.5;
  if (std::abs(q) <= 0.425) {
    const double r = 0.180625 - q * q;
    return q *
           (((((((2509.0809287301226727 * r + 33430.575583588128105) * r +
                 67265.770927008700853) * r + 45921.953931549871457) * r +
               13731.693765509461125) * r + 1971.5909503065514427) * r +
             133.14166789178437745) * r + 3.387132872796366608) /
           (((((((5226.495278852545925 * r + 28729.085735721942674) * r +
                 39307.89580009271061) * r + 21213.794301586595867) * r +
               5394.1960214247511077) * r + 687.1870074920579083) * r +
             42.313330701600911252) * r + 1.0);
  }
  double r = q < 0 ? p : 1.0 - p;
  if (r <= 0) return q < 0 ? -HUGE_VAL : HUGE_VAL;
  r = std::sqrt(-std::log(r));
  double val;
  if (r <= 5.0) {
    r -= 1.6;
    val = (((((((7.7454501427834140764e-4 * r + 0.0227238449892691845833) * r +
                0.24178072517745061177) * r + 1.27045825245236838258) * r +
              3.64784832476320460504) * r + 5.7694972214606914055) * r +
            4.6303378461565452959) * r + 1.42343711074968357734) /
          (((((((1.05075007164441684324e-9 * r + 5.475938084995344946e-4) * r +
                0.0151986665636164571966) * r + 0.14810397642748007459) * r +
              0.68976733498510000455) * r + 1.6763848301838038494) * r +
            2.05319162663775882187) * r + 1.0);
  } else {
    r -= 5.0;
    val = (((((((2.01033439929228813265e-7 * r + 2.71155556874348757815e-5) * r +
                0.0012426609473880784386) * r + 0.026532189526576123093) * r +
              0.29656057182850489123) * r + 1.7848265399172913358) * r +
            5.4637849111641143699) * r + 6.6579046435011037772) /
          (((((((2.04426310338993978564e-15 * r + 1.4215117583164458887e-7) * r +
                1.8463183175100546818e-5) * r + 7.868691311456132591e-4) * r +
              0.0148753612908506148525) * r + 0.13692988092273580531) * r +
            0.59983220655588793769) * r + 1.0);
  }
  return q < 0 ? -val : val;
}

}  // namespace pierre::model
