// Model defaults: the one place they live (model-2d.md §1, "default" column); every one can be
// overridden in a scenario, and the io layer starts from these. Beside them, the limits an
// input is validated against (InputLimits), which a scenario cannot change.
#pragma once

namespace pierre::model {

struct ModelDefaults {
  static constexpr double gravity = 9.81;                 // m/s²
  static constexpr double density = 2650.0;               // kg/m³ (thesis §4.2.1)
  static constexpr double normal_energy_k = 0.5;          // k_n,ref at E_n (Eq 6.4)
  static constexpr double tangential_energy_k = 0.95;     // k_t,ref at E_t (model-2d.md §1: why 0.95)
  static constexpr double friction_angle_deg = 30.0;      // φ (§3.4.2 defines it, no value: model-2d.md §1)
  static constexpr double shape_factor_min = 1.0;         // f range [1, 1]: shape factor off
  static constexpr double shape_factor_max = 1.0;
  static constexpr bool truncated_normal_roughness = true;  // Eq 3.5 (else uniform, Eq 3.4)
  static constexpr bool size_reduction = true;            // Eq 6.6 on
  static constexpr double roughness_mean = 0.5;           // μ of Eq 3.5 (§4.4.1)
  static constexpr double roughness_sd = 0.5;             // σ of Eq 3.5
  static constexpr double size_reduction_b = 1.36;        // Eq 6.6 / Eq 4.5
  static constexpr double size_reduction_m = 0.3;         // 1/m
  static constexpr double size_reduction_floor = 0.3;     // §3.4.1
  static constexpr double stop_head_factor = 0.25;        // H_stop = c·R (Eq 3.13, appendix B; §6.3's "of the block diameter" is not followed: model-2d.md §1)
  static constexpr double max_sliding_speed = 5.0;        // m/s (§3.2.2)
  static constexpr double max_time = 600.0;               // s of simulated time
  static constexpr long max_impacts = 100000;             // impacts (and vertex events)
};

struct InputLimits {
  static constexpr double shape_factor_lower_bound = 0.7;  // validated range (model-2d.md §3)
  static constexpr double shape_factor_upper_bound = 2.0;
  // Far beyond any rockfall, these keep every energy a finite double (a mass of 1e300 kg or a
  // speed of 1e200 m/s gave inf in the CSV files): a block of 10⁸ kg (about 40 000 m³) is a
  // rock avalanche, beyond a lumped-mass model.
  static constexpr double max_block_mass = 1e8;    // kg
  static constexpr double max_source_speed = 1e3;  // m/s, each of vx and vz
  static constexpr double max_source_spin = 1e4;   // rad/s
  // About 1000 g, beyond any geotechnical centrifuge: a gravity of 1e308 overflowed every
  // flight (no landing found, the blocks lost through the ground).
  static constexpr double max_gravity = 1e4;  // m/s²
};

}  // namespace pierre::model
