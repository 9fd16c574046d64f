#include "rule_kind.hpp"

#include <toml++/toml.h>

namespace pierre::io::detail {

RuleFileKind rule_file_kind(const std::filesystem::path& file) {
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error&) {
    return RuleFileKind::other;
  }
  if (const toml::table* head = root["rule_set"].as_table()) {
    const auto kind = (*head)["kind"].value<std::string>();
    if (kind == "barrier") return RuleFileKind::barrier;
    if (kind == "energy-classes") return RuleFileKind::energy_classes;
    if (!kind && root.contains("toe") && root.contains("governing")) return RuleFileKind::quarry;
    return RuleFileKind::other;
  }
  bool presets = !root.empty();
  for (auto&& [k, v] : root) {
    const toml::table* t = v.as_table();
    presets = presets && t && t->contains("normal_energy");
  }
  return presets ? RuleFileKind::materials : RuleFileKind::other;
}

std::string_view describe(RuleFileKind kind) {
  switch (kind) {
    case RuleFileKind::barrier: return "a barrier rule set";
    case RuleFileKind::energy_classes: return "an energy class table";
    case RuleFileKind::quarry: return "a quarry rule set";
    case RuleFileKind::materials: return "a materials file";
    case RuleFileKind::other: break;
  }
  return "not a rule set";
}

}  // namespace pierre::io::detail
