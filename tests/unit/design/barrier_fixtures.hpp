// Rule sets and class tables for the barrier tests, written out by hand from design-checks.md
// §1 and, for the energy classes, from ETAG 027's nine classes (rules/etag027-classes.toml says
// why they differ from the spec's eight). The design tests link only pierre_design; the io tests
// load the shipped TOML files and compare them with these.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "pierre/design/barrier_check.hpp"

namespace pierre::test {

inline design::EnergyClassTable etag027() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  design::EnergyClassTable t;
  t.name = "etag027-classes";
  t.classes = {{0, nan, 100, false},   {1, 85, 250, false},    {2, 170, 500, false},
               {3, 330, 1000, false},  {4, 500, 1500, false},  {5, 660, 2000, false},
               {6, 1000, 3000, false}, {7, 1500, 4500, false}, {8, 1500, 4500, true}};
  t.residual_height = design::ResidualHeightCategories{0.5, 0.3, ""};
  return t;
}

inline design::BarrierRuleSet thesis_2015() {
  design::BarrierRuleSet r;
  r.name = "thesis-2015";
  r.percentile = 95;
  r.governing = design::Governing::weibull;
  r.design_on = design::DesignOn::both;
  r.gamma_F = {"γF", 1.16, {}, ""};
  r.gamma_M = {"γM", 1.05, {}, ""};
  r.gamma_h = {"γh", 1.0, {}, ""};
  r.gamma_E_MEL = 1.3;
  r.gamma_E_SEL = 1.0;
  r.free_board_abs = 0;
  r.free_board_rel = 0.5;
  return r;
}

inline design::FactorPart part(const char* symbol, const char* choice, const char* a, double va,
                               const char* b, double vb) {
  design::FactorPart p;
  p.symbol = symbol;
  p.choice = choice;
  p.options = {{a, va}, {b, vb}};
  return p;
}

inline design::BarrierRuleSet peila_ronco_2009() {
  design::BarrierRuleSet r;
  r.name = "peila-ronco-2009";
  r.percentile = 95;
  r.governing = design::Governing::larger;
  r.design_on = design::DesignOn::mel;
  const auto tr = part("γTr", "trajectory", "back-analysed", 1.02, "literature", 1.10);
  const auto dp = part("γDp", "topography", "high", 1.02, "low", 1.10);
  const auto vol = part("γVolF", "block_volume", "surveyed", 1.02, "estimated", 1.10);
  design::FactorPart gg;
  gg.symbol = "γγ";
  gg.value = 1.0;
  r.gamma_F = {"γF", std::nullopt, {tr, dp}, ""};
  r.gamma_M = {"γM", std::nullopt, {vol, gg}, ""};
  r.gamma_h = {"γh", std::nullopt, {tr, dp}, ""};
  r.gamma_E_MEL = 1.2;
  r.gamma_E_SEL = 1.0;
  r.free_board_abs = 0.5;
  r.free_board_rel = 0.5;
  r.gamma_d_MEL = 1.3;
  r.gamma_d_SEL = 1.5;
  return r;
}

// Deterministic uniforms in (0, 1) (splitmix64), for samples drawn by inversion.
class Uniforms {
 public:
  explicit Uniforms(std::uint64_t seed) : s_(seed) {}
  double next() {
    std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (static_cast<double>(z >> 12) + 0.5) * 0x1.0p-52;
  }

 private:
  std::uint64_t s_;
};

// n values of a Weibull(shape k, scale λ): x = λ (-ln U)^(1/k).
inline std::vector<double> weibull_sample(std::size_t n, double k, double lambda, std::uint64_t seed) {
  Uniforms u(seed);
  std::vector<double> v(n);
  for (auto& x : v) x = lambda * std::pow(-std::log(u.next()), 1.0 / k);
  return v;
}

}  // namespace pierre::test
