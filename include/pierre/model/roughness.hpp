// The random roughness angle (§3.4.1): tan θ = θ_scale · X · f_size.
//   X ~ N(μ, σ²) truncated to X > 0 (Eq 3.5; the thesis redraws negatives), or U(0, 1) (Eq 3.4);
//   f_size = max(floor, b − m·D) (Eq 6.6, the published form that scales tan θ).
#pragma once

#include <cstdint>

#include "pierre/model/model_defaults.hpp"

namespace pierre::model {

enum class RoughnessDistribution : std::uint8_t { truncated_normal, uniform };

struct RoughnessModel {
  RoughnessDistribution distribution = ModelDefaults::truncated_normal_roughness
                                           ? RoughnessDistribution::truncated_normal
                                           : RoughnessDistribution::uniform;
  double mean = ModelDefaults::roughness_mean;  // μ
  double sd = ModelDefaults::roughness_sd;      // σ
  bool size_reduction = ModelDefaults::size_reduction;
  double b = ModelDefaults::size_reduction_b;
  double m = ModelDefaults::size_reduction_m;  // 1/m
  double floor = ModelDefaults::size_reduction_floor;

  // f_size for a block of diameter D (m).
  double size_factor(double diameter) const;
  // Φ(μ/σ): the probability mass the truncation keeps (X > 0); compute once, pass to sample().
  double kept_mass() const;
  // X from one uniform u in (0, 1). The truncated normal is drawn by inverting its CDF: the same
  // distribution as redrawing negatives, with exactly one uniform per impact so that every
  // implementation fed the same stream draws the same X.
  double sample(double u, double kept_mass) const;
};

// Standard normal quantile Φ⁻¹(p), p in (0, 1): Wichura's AS 241 (PPND16), relative
// accuracy about 1e-16. Hand-written: it runs once per impact and must be the same everywhere.
double normal_quantile(double p);
// Standard normal CDF Φ(x) via erfc.
double normal_cdf(double x);

}  // namespace pierre::model
