// What a TOML file of rules/ is, so that a scenario naming the wrong kind ("rules = "materials""
// for a barrier) is told so at its own line, not with an unknown key deep in the other file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace pierre::io::detail {

enum class RuleFileKind { barrier, energy_classes, quarry, materials, other };

// By its [rule_set] kind ("barrier", "energy-classes"), a quarry rule set's [toe] and
// [governing], or a materials file's preset tables; `other` for anything else, a file that
// cannot be read or parsed included (its own loader reports that).
RuleFileKind rule_file_kind(const std::filesystem::path& file);

// "a barrier rule set", "an energy class table", …
std::string_view describe(RuleFileKind kind);

}  // namespace pierre::io::detail
