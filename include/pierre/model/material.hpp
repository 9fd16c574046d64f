// Ground material: the four calibrated PIERRE 2 parameters and the friction angle (§3.4).
#pragma once

#include <string>

#include "pierre/model/model_defaults.hpp"

namespace pierre::model {

struct Material {
  std::string name;
  std::string source;  // where the values come from (preset citation or "scenario")
  double normal_energy = 0;                                        // E_n, m³/s²
  double normal_energy_k = ModelDefaults::normal_energy_k;         // k_n,ref
  double tangential_energy = 0;                                    // E_t, m³/s²
  double tangential_energy_k = ModelDefaults::tangential_energy_k;  // k_t,ref
  double roughness = 0;                                            // θ_scale (tan scale)
  double friction_angle_deg = ModelDefaults::friction_angle_deg;    // φ, degrees
};

}  // namespace pierre::model
