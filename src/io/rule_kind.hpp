// What a TOML file of rules/ is, so that a scenario naming the wrong kind ("rules = "materials""
// for a barrier) is told so at its own line, not with an unknown key deep in the other file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace pierre::io::detail {

enum class RuleFileKind { barrier, energy_classes, quarry, materials, other, unparsable };

// By its [rule_set] kind ("barrier", "energy-classes"), a quarry rule set's [toe] and
// [governing], or a materials file's preset tables; `unparsable` for a file that is not valid
// TOML (where and why in *parse_error, when given), `other` for anything else, a file that
// cannot be read included (its own loader reports that).
RuleFileKind rule_file_kind(const std::filesystem::path& file, std::string* parse_error = nullptr);

// True when the file is a rule file of another kind than `wanted`: a scenario naming it is told
// what it is. A file that is no rule file, or does not parse, is left to the loader's errors.
bool is_other_rule_kind(RuleFileKind kind, RuleFileKind wanted);

// "a barrier rule set", "an energy class table", …
std::string_view describe(RuleFileKind kind);

}  // namespace pierre::io::detail
