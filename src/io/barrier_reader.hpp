// The [[barriers]] entries of a scenario (docs/scenario-format.md, design-checks.md §1): each
// with its rule set, its energy class table, its candidate and its observed data, and the notes
// on values typed in the smaller unit. Internal to the io library.
#pragma once

#include "pierre/io/rules_folder.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "toml_fields.hpp"

namespace pierre::io::detail {

// Reads top's [[barriers]] into out: barriers, barrier_rules (and their files), barrier_classes,
// barrier_observed, one each per barrier, and notes. The observation lines (out.scenario.lines)
// are read already: a barrier names one.
void read_barriers(const TomlTable& top, const RulesFolder& rules_folder, LoadedScenario& out);

}  // namespace pierre::io::detail
