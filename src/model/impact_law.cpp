#include "pierre/model/impact_law.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "pierre/model/restitution.hpp"

namespace pierre::model {
namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
// v⁺·n at or below this (m/s) after an impact: the block slides (model-2d.md §3 step 7). A
// numerical tolerance of the law, not a scenario setting.
constexpr double kReboundSlidingThreshold = 1e-6;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

ImpactLaw::ImpactLaw(const RoughnessModel& roughness, double stop_head_factor, double gravity)
    : roughness_(roughness),
      stop_head_factor_(stop_head_factor),
      g_(gravity),
      kept_mass_(roughness.kept_mass()) {}

SurfaceConstants ImpactLaw::surface(const Material& m) const {
  SurfaceConstants s;
  s.a_n = hyperbola_constant(m.normal_energy, m.normal_energy_k);
  s.a_t = hyperbola_constant(m.tangential_energy, m.tangential_energy_k);
  s.tan_phi = std::tan(m.friction_angle_deg / kDeg);
  s.roughness = m.roughness;
  return s;
}

BlockConstants ImpactLaw::block(const Block& b) const {
  BlockConstants c;
  c.mass = b.mass;
  c.radius = b.radius();
  c.inertia = b.inertia();
  c.f_min = b.shape_min;
  c.f_range = b.shape_max - b.shape_min;
  c.roughness_size_factor = roughness_.size_factor(b.diameter());
  const double stop_head = stop_head_factor_ * c.radius;  // H_stop = c_stop R (Eq 3.13)
  c.stop_energy = stop_head * (c.mass * g_);
  return c;
}

ImpactSample ImpactLaw::sample(const ImpactDraws& draws, const BlockConstants& blk) const {
  ImpactSample smp;
  smp.x = roughness_.sample(draws.roughness_u, kept_mass_);  // Eq 3.5 or 3.4
  smp.f = blk.f_min + blk.f_range * draws.shape_u;        // Eq 3.9
  smp.r_eff = smp.f * blk.radius;
  smp.kappa = 1.0 + 2.5 * smp.f * smp.f;
  smp.level_sign = draws.level_sign;
  return smp;
}

ImpactOutcome ImpactLaw::resolve(Vec2 v, double omega, const geometry::Segment& seg,
                                 const SurfaceConstants& surf, const BlockConstants& blk,
                                 const ImpactDraws& draws, ImpactDetail* detail) const {
  return resolve_sampled(v, omega, seg, surf, blk, sample(draws, blk), detail);
}

ImpactOutcome ImpactLaw::resolve(Vec2 v, double omega, const geometry::Segment& seg,
                                 const SurfaceConstants& surf, const BlockConstants& blk,
                                 const ImpactSample& smp, ImpactDetail* detail) const {
  return resolve_sampled(v, omega, seg, surf, blk, smp, detail);
}

// One body for both entry points, inlined into each so that neither pays a call more.
[[gnu::always_inline]] inline ImpactOutcome ImpactLaw::resolve_sampled(
    Vec2 v, double omega, const geometry::Segment& seg, const SurfaceConstants& surf,
    const BlockConstants& blk, const ImpactSample& smp, ImpactDetail* detail) const {
  ImpactOutcome out;
  const Vec2 n = seg.n;

  // 1. Travel direction along the surface; downslope when v·d = 0, a coin on level ground.
  const double vd = dot(v, seg.d);
  double sign;
  if (vd != 0.0)
    sign = vd > 0 ? 1.0 : -1.0;
  else if (seg.d.z != 0.0)
    sign = seg.d.z < 0 ? 1.0 : -1.0;
  else
    sign = smp.level_sign ? 1.0 : -1.0;
  const Vec2 t_hat = sign * seg.d;

  // 2. Roughness angle (Eq 3.5 or 3.4, scaled by Eq 6.6): tan θ = θ_scale · X · f_size.
  const double tan_theta = surf.roughness * smp.x * blk.roughness_size_factor;
  const double cos_t = 1.0 / std::sqrt(1.0 + tan_theta * tan_theta);
  const double sin_t = tan_theta * cos_t;

  // 3. The plane tilts against the travel (Fig 3.1): n' = cos θ n − sin θ t̂, t' = cos θ t̂ + sin θ n.
  const Vec2 n_r = cos_t * n - sin_t * t_hat;
  const Vec2 t_r = cos_t * t_hat + sin_t * n;

  // 4. Components in the rotated frame; the contact point's speed from spin along t'.
  const double vn = dot(v, n_r);  // < 0 always (model-2d.md §3 step 3)
  const double vt = dot(v, t_r);
  const double r_eff = smp.r_eff;  // Eq 3.9
  const double arm = n_r.z * t_r.x - n_r.x * t_r.z;  // ±1: orientation of t' against ω
  const double u = omega * r_eff * arm;
  const double slip = vt + u;

  // 5. Hyperbolic restitution factors (Eq 6.4) at the unit deformation energy E_d = R v_n².
  const double e_d = blk.radius * vn * vn;
  const double kn = hyperbolic_factor(e_d, surf.a_n);
  const double kt = hyperbolic_factor(e_d, surf.a_t);

  // 6. Goldsmith with an effective radius (Eq 3.10–3.12 generalised, κ = 1 + 5/2 f²).
  const double kappa = smp.kappa;
  const double abs_vn = -vn;
  // Contained when tan φ ≥ tan γ = k_t |slip| / (κ (1 + k_n) |v_n|); multiplied out where the
  // denominator is positive, so that the branch does not wait for a division. (It is not when
  // θ = 0 leaves v_n at rounding noise, e.g. a sliding launch on a roughness of 0: there the
  // quotient decides, as it always did.)
  const double p = surf.tan_phi * (1.0 + kn) * abs_vn;  // friction limit of Eq 3.12
  const bool contained =
      abs_vn > 0.0 ? kappa * p >= kt * std::abs(slip)
                   : surf.tan_phi >= kt * std::abs(slip) / (kappa * (1.0 + kn) * abs_vn);
  double vt_out, u_out;
  if (contained) {  // contained slip (Eq 3.11)
    vt_out = kt * (vt - slip / kappa);
    u_out = kt * (u - (kappa - 1.0) * slip / kappa);
  } else {  // uncontained slip (Eq 3.12)
    const double sigma = slip > 0 ? 1.0 : -1.0;
    vt_out = kt * vt - sigma * p;
    u_out = kt * u - sigma * (kappa - 1.0) * p;
  }
  const double vn_out = kn * abs_vn;
  double omega_out = u_out / (r_eff * arm);

  // 7. Rebound, or sliding when it would not leave the true surface.
  Vec2 v_out = vt_out * t_r + vn_out * n_r;
  const double vn_true_out = dot(v_out, n);
  out.result = ImpactResult::rebound;
  if (vn_true_out <= kReboundSlidingThreshold) {
    v_out = v_out - vn_true_out * n;
    out.result = ImpactResult::sliding;
  }
  const Vec2 v_left = v_out;  // what the block leaves with, or would have (the record's)

  // 8. Stopping criterion (Eq 3.13): energy head E/(m g) after the impact against c_stop R,
  // compared as E against m g c_stop R so that the branch does not wait for a division.
  const double energy_out =
      0.5 * blk.mass * dot(v_out, v_out) + 0.5 * blk.inertia * omega_out * omega_out;
  if (energy_out < blk.stop_energy) {
    out.result = ImpactResult::stopped;
    v_out = {0.0, 0.0};
    omega_out = 0.0;
  }
  out.v = v_out;
  out.omega = omega_out;

  // 9. The record (§3.9), only when asked for: it costs more than the impact itself.
  if (!detail) return out;
  ImpactDetail& det = *detail;
  det.contained = contained;
  const double vn_in_true = dot(v, n), vt_in_true = dot(v, t_hat);
  det.slope_deg = std::atan2(-t_hat.z, std::abs(t_hat.x)) * kDeg + 0.0;  // + 0: level is 0, not −0
  det.roughness_deg = std::atan(tan_theta) * kDeg;
  det.r_eff = r_eff;
  det.vn_in = vn_in_true;
  det.vt_in = vt_in_true;
  // The rebound in the true frame is the one energy_out is of: after step 7, before a stop.
  det.vn_out = vn_true_out <= kReboundSlidingThreshold ? 0.0 : vn_true_out;  // sliding: along it
  det.vt_out = dot(v_left, t_hat);
  det.vn_in_rot = vn;
  det.vt_in_rot = vt;
  det.vn_out_rot = vn_out;
  det.vt_out_rot = vt_out;
  det.kn = kn;
  det.kt = kt;
  // Rebound over incident component (§3.8), where the block comes in along that axis at all: a
  // launch from sliding meets the ground with v·n a rounding from 0, and a quotient by it is
  // noise (~10¹⁵). Below the tolerance of step 7 it is undefined: NaN, an empty cell.
  det.kn_apparent = std::abs(vn_in_true) > kReboundSlidingThreshold ? -det.vn_out / vn_in_true : kNaN;
  det.kt_apparent = std::abs(vt_in_true) > kReboundSlidingThreshold ? det.vt_out / vt_in_true : kNaN;
  det.incidence_deg = std::atan2(-vn_in_true, std::abs(vt_in_true)) * kDeg;
  det.energy_in = 0.5 * blk.mass * dot(v, v) + 0.5 * blk.inertia * omega * omega;
  det.energy_out = energy_out;
  return out;
}

}  // namespace pierre::model
