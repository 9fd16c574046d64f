// Barrier rule sets and energy class tables as data (design-checks.md §1): rules/<name>.toml,
// whose shape is documented in the header of rules/thesis-2015.toml (rule sets) and
// rules/etag027-classes.toml (class tables). Every problem is an InputError naming the file,
// the line, the field, what was found and what was expected.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pierre/design/barrier_rules.hpp"
#include "pierre/io/input_error.hpp"

namespace pierre::io {

// A name or a path: a name (no '/' and not ending in ".toml") is rules_dir/<name>.toml; anything
// else is a path, taken as given (the scenario reader makes it relative to the scenario file).
bool names_a_path(const std::string& name_or_path);
std::filesystem::path rule_file(const std::string& name_or_path,
                                const std::filesystem::path& rules_dir);
// The same for a scenario's `rules` key: a path is relative to the scenario file.
std::filesystem::path scenario_rule_file(const std::string& name_or_path,
                                         const std::filesystem::path& scenario_file,
                                         const std::filesystem::path& rules_dir);

// Reads a barrier rule set ([rule_set] kind = "barrier"). Its name is [rule_set].name or the
// file stem.
design::BarrierRuleSet load_rule_set(const std::string& name_or_path,
                                     const std::filesystem::path& rules_dir);
design::BarrierRuleSet load_rule_set_file(const std::filesystem::path& file);

// Reads an energy class table ([rule_set] kind = "energy-classes").
design::EnergyClassTable load_energy_classes(const std::string& name_or_path,
                                             const std::filesystem::path& rules_dir);
design::EnergyClassTable load_energy_classes_file(const std::filesystem::path& file);

// The names of the barrier rule sets in rules_dir (files whose [rule_set] kind is "barrier"),
// sorted; for messages. The .toml files that do not parse, each "name.toml (line N: why)", go to
// *unparsable when given.
std::vector<std::string> barrier_rule_set_names(const std::filesystem::path& rules_dir,
                                                std::vector<std::string>* unparsable = nullptr);

// What rules_dir holds, for messages: "its barrier rule sets: \"a\", \"b\"" or "it holds no
// barrier rule set", and the .toml files passed over because they do not parse, with where.
std::string barrier_rule_sets_held(const std::filesystem::path& rules_dir);

}  // namespace pierre::io
