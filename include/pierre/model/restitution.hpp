// Hyperbolic restitution factors (Eq 6.4, the published form; Eq 3.7–3.8):
// k = A / (E_d + A) with A = E_ref k_ref / (1 − k_ref), so k(E_ref) = k_ref and k → 1 as
// E_d → 0. E_d = R v_n² is the unit deformation energy (m³/s²).
#pragma once

namespace pierre::model {

struct RestitutionFactors {
  double normal = 1;      // k_n
  double tangential = 1;  // k_t
};

// A of the hyperbola for a reference energy and the factor reached there.
inline double hyperbola_constant(double reference_energy, double k_ref) {
  return reference_energy * k_ref / (1.0 - k_ref);
}

inline double hyperbolic_factor(double unit_energy, double a_const) {
  return a_const / (unit_energy + a_const);
}

}  // namespace pierre::model
