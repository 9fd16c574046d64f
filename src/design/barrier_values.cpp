// Steps 3–6 of design-checks.md §1: design values from the characteristic ones.
//   v_d = v_k γF;  m_d = ρ Vol_b γM;  E_d = ½ m_d v_d² (kJ);
//   MEL_req = γE,MEL E_d;  SEL_req = γE,SEL E_d;  the smallest class meeting design_on;
//   h_d = h_k γh;  f = max(f_abs, f_rel D_f);  h_i = h_d + f.
#include <algorithm>

#include "pierre/design/barrier_check.hpp"

namespace pierre::design {

double design_energy_kJ(double v_k, double gamma_F, double m_d) {
  const double v_d = v_k * gamma_F;
  return 0.5 * m_d * v_d * v_d / 1000.0;
}

double interception_height(double h_k, double gamma_h, double free_board) {
  return h_k * gamma_h + free_board;
}

stats::Outcome<DesignValues> design_values(const BarrierRuleSet& rules,
                                           const EnergyClassTable& classes,
                                           const DesignInputs& in) {
  using Out = stats::Outcome<DesignValues>;
  DesignValues d;
  const auto gF = resolve_factor(rules.gamma_F, in.data_quality);
  if (!gF) return Out::failure(gF.error);
  const auto gM = resolve_factor(rules.gamma_M, in.data_quality);
  if (!gM) return Out::failure(gM.error);
  const auto gh = resolve_factor(rules.gamma_h, in.data_quality);
  if (!gh) return Out::failure(gh.error);
  d.gamma_F = *gF;
  d.gamma_M = *gM;
  d.gamma_h = *gh;
  d.gamma_E_MEL = rules.gamma_E_MEL;
  d.gamma_E_SEL = rules.gamma_E_SEL;

  d.v_d = in.v_k * d.gamma_F.value;
  d.m_d = in.density * in.volume * d.gamma_M.value;
  d.E_d_kJ = design_energy_kJ(in.v_k, d.gamma_F.value, d.m_d);
  d.MEL_req_kJ = d.gamma_E_MEL * d.E_d_kJ;
  d.SEL_req_kJ = d.gamma_E_SEL * d.E_d_kJ;
  d.energy_class = select_energy_class(classes, rules.design_on, d.MEL_req_kJ, d.SEL_req_kJ);

  d.h_d = in.h_k * d.gamma_h.value;
  d.free_board = std::max(rules.free_board_abs, rules.free_board_rel * in.free_board_diameter);
  d.h_i = interception_height(in.h_k, d.gamma_h.value, d.free_board);
  return Out::success(d);
}

}  // namespace pierre::design
