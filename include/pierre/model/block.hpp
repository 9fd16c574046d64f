// A block (boulder) as thrown: a sphere of equal volume with a shape-factor range (§3.5).
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "pierre/model/model_defaults.hpp"

namespace pierre::model {

struct Block {
  std::string id;
  double mass = 0;  // kg
  double density = ModelDefaults::density;  // kg/m³
  double shape_min = ModelDefaults::shape_factor_min;  // f_min = R_eff,min / R
  double shape_max = ModelDefaults::shape_factor_max;  // f_max

  double volume() const { return mass / density; }                               // m³
  double radius() const { return std::cbrt(3.0 * volume() / (4.0 * std::numbers::pi)); }  // R, m
  double diameter() const { return 2.0 * radius(); }                              // D, m
  double inertia() const { return 0.4 * mass * radius() * radius(); }             // I = 2/5 m R²
};

}  // namespace pierre::model
