// The PIERRE 2 impact (§3.4–§3.7, Eq 3.4–3.13; model-2d.md §3): roughness tilts the plane,
// hyperbolic restitution factors, Goldsmith's collinear impact with an effective radius, the
// rebound or sliding decision and the energy stopping criterion.
#pragma once

#include "pierre/geometry/profile.hpp"
#include "pierre/model/block.hpp"
#include "pierre/model/material.hpp"
#include "pierre/model/roughness.hpp"

namespace pierre::model {

using geometry::Vec2;

// A material prepared for impacts: the hyperbola constants and tan φ.
struct SurfaceConstants {
  double a_n = 0;  // A_n = E_n k_n,ref / (1 − k_n,ref), m³/s²
  double a_t = 0;  // A_t
  double tan_phi = 0;
  double roughness = 0;  // θ_scale
};

// A block prepared for impacts.
struct BlockConstants {
  double mass = 0, radius = 0, inertia = 0;
  double f_min = 1, f_range = 0;
  double roughness_size_factor = 1;  // f_size of Eq 6.6
  double stop_energy = 0;            // m g H_stop with H_stop = c_stop R, J: below it the block stops
};

// The random numbers one impact uses, all from one draw of the trajectory's stream.
struct ImpactDraws {
  double roughness_u = 0.5;  // in (0, 1): X of the roughness distribution
  double shape_u = 0.5;      // in (0, 1): R_eff = R (f_min + (f_max − f_min) u), Eq 3.9
  bool level_sign = false;   // travel sign when v·d = 0 on level ground
};

// The random part of one impact made ready before the impact is met: X of the roughness
// distribution (Eq 3.4/3.5), the shape factor f and what follows from it (Eq 3.9, κ of
// Eq 3.10–3.12). None of it depends on the block's state, so a trajectory can make the next
// impact's sample while it is still in flight, off the impact's chain of dependent operations.
struct ImpactSample {
  double x = 0.5;          // X, before θ_scale and f_size
  double f = 1;            // shape factor
  double r_eff = 0;        // f R, m
  double kappa = 3.5;      // 1 + 5/2 f²
  bool level_sign = false;
};

enum class ImpactResult : unsigned char { rebound, sliding, stopped };

// Everything the thesis's TR file records about one impact (§3.9; model-2d.md §3 step 9).
struct ImpactDetail {
  double slope_deg = 0;      // β: the true surface's descent angle in the travel direction
  double roughness_deg = 0;  // θ
  double r_eff = 0;          // effective radius, m
  // True n–t frame (t along travel). The rebound is the velocity the block leaves with, after
  // step 7 (a sliding block's vn_out is 0), the one energy_out is of; for a stopped block, the
  // one the stopping criterion found too weak.
  double vt_in = 0, vn_in = 0, vt_out = 0, vn_out = 0;
  double vt_in_rot = 0, vn_in_rot = 0, vt_out_rot = 0, vn_out_rot = 0;  // rotated n'–t': Goldsmith's own
  double kn = 0, kt = 0;                // true factors (n'–t')
  // Rebound over incident in n–t (§3.8); NaN where the incident component is within the
  // rebound-or-slide tolerance of 0 (a launch from sliding: no approach along n).
  double kn_apparent = 0, kt_apparent = 0;
  double incidence_deg = 0;  // α_in between the incident velocity and the true surface
  bool contained = false;    // contained slip (Eq 3.11) or not (Eq 3.12)
  double energy_in = 0, energy_out = 0;  // kinetic energy (translational + rotational), J
};

struct ImpactOutcome {
  ImpactResult result = ImpactResult::rebound;
  Vec2 v;            // rebound velocity (tangential only when sliding, zero when stopped)
  double omega = 0;  // rebound angular velocity, rad/s (counter-clockwise positive)
};

class ImpactLaw {
 public:
  ImpactLaw(const RoughnessModel& roughness, double stop_head_factor, double gravity);

  SurfaceConstants surface(const Material& m) const;
  BlockConstants block(const Block& b) const;

  // The sample one impact of block `blk` takes from its draws.
  ImpactSample sample(const ImpactDraws& draws, const BlockConstants& blk) const;

  // Resolves an impact of a block with velocity v and spin omega on segment `seg`; fills
  // `detail` (the TR record) when it is not null.
  ImpactOutcome resolve(Vec2 v, double omega, const geometry::Segment& seg,
                        const SurfaceConstants& surf, const BlockConstants& blk,
                        const ImpactSample& smp, ImpactDetail* detail = nullptr) const;
  ImpactOutcome resolve(Vec2 v, double omega, const geometry::Segment& seg,
                        const SurfaceConstants& surf, const BlockConstants& blk,
                        const ImpactDraws& draws, ImpactDetail* detail = nullptr) const;

  const RoughnessModel& roughness() const { return roughness_; }
  double gravity() const { return g_; }

 private:
  ImpactOutcome resolve_sampled(Vec2 v, double omega, const geometry::Segment& seg,
                                const SurfaceConstants& surf, const BlockConstants& blk,
                                const ImpactSample& smp, ImpactDetail* detail) const;
  RoughnessModel roughness_;
  double stop_head_factor_;
  double g_;
  double kept_mass_;  // Φ(μ/σ): the part of the roughness normal above 0
};

}  // namespace pierre::model
