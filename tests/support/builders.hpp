// Small scenario builders for the tests: plain data in, a ready Scenario out.
#pragma once

#include <stdexcept>
#include <utility>
#include <vector>

#include "pierre/sim/scenario.hpp"

namespace pierre::test {

inline geometry::Profile make_profile(const std::vector<geometry::Vec2>& pts,
                                      std::vector<int> materials = {}) {
  if (materials.empty()) materials.assign(pts.size() > 0 ? pts.size() - 1 : 0, 0);
  std::vector<geometry::ProfileIssue> issues;
  auto p = geometry::Profile::build(pts, materials, &issues);
  if (!p) throw std::runtime_error(issues.empty() ? "bad profile" : issues.front().what);
  return *p;
}

inline model::Material make_material(double e_n, double e_t, double roughness,
                                     double friction_deg = 30.0) {
  model::Material m;
  m.name = "test";
  m.normal_energy = e_n;
  m.tangential_energy = e_t;
  m.roughness = roughness;
  m.friction_angle_deg = friction_deg;
  return m;
}

inline model::Block make_block(double mass, double f_min = 1.0, double f_max = 1.0) {
  model::Block b;
  b.id = std::string(1, 'b');  // (not = "b": GCC 12 warns falsely, -Wrestrict, once inlined)
  b.mass = mass;
  b.shape_min = f_min;
  b.shape_max = f_max;
  return b;
}

inline sim::Scenario make_scenario(geometry::Profile profile, model::Material material,
                                   std::vector<model::Block> blocks, geometry::Vec2 source,
                                   std::uint32_t throws, std::uint64_t seed = 42) {
  sim::Scenario s;
  s.name = "test";
  s.profile = std::move(profile);
  s.materials = {std::move(material)};
  s.blocks = std::move(blocks);
  s.sources = {sim::Source{"src", source, {0, 0}, 0}};
  s.settings.seed = seed;
  s.settings.throws = throws;
  return s;
}

}  // namespace pierre::test
