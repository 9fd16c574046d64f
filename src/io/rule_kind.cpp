#include "rule_kind.hpp"

#include <toml++/toml.h>

namespace pierre::io::detail {

RuleFileKind rule_file_kind(const std::filesystem::path& file, std::string* parse_error) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return RuleFileKind::other;
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    if (parse_error)
      *parse_error = "line " + std::to_string(e.source().begin.line) + ": " +
                     std::string(e.description());
    return RuleFileKind::unparsable;
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

bool is_other_rule_kind(RuleFileKind kind, RuleFileKind wanted) {
  return kind != wanted && kind != RuleFileKind::other && kind != RuleFileKind::unparsable;
}

std::string_view describe(RuleFileKind kind) {
  switch (kind) {
    case RuleFileKind::barrier: return "a barrier rule set";
    case RuleFileKind::energy_classes: return "an energy class table";
    case RuleFileKind::quarry: return "a quarry rule set";
    case RuleFileKind::materials: return "a materials file";
    case RuleFileKind::unparsable: return "not valid TOML";
    case RuleFileKind::other: break;
  }
  return "not a rule set";
}

}  // namespace pierre::io::detail
