// Reads a scenario (TOML, docs/scenario-format.md) with its profile and block CSVs and the
// material presets of rules/, validates every field, and returns the simulation's Scenario
// plus what the report echoes. Throws InputError on bad input.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pierre/io/input_error.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::io {

struct BlockGroup {  // a row of the block table or CSV, as written
  std::string id;
  double mass = 0;     // kg
  double volume = 0;   // m³
  double density = 0;  // kg/m³
  double shape_min = 1, shape_max = 1;
  unsigned count = 1;
};

struct LoadedScenario {
  sim::Scenario scenario;
  std::filesystem::path file;        // the scenario file as given
  std::string text;                  // its text, echoed in reports
  std::string description;
  std::vector<BlockGroup> block_groups;
  std::filesystem::path materials_file;  // where the presets came from
};

// `rules_dir` holds materials.toml (and, later, design rule sets); it is only read when a
// material names a preset and the scenario gives no `materials_file`.
// Numbers: an integer is accepted where a float is expected (`mass = 1500`); nothing else
// converts (`throws = "5"` or `throws = 5.0` is an error). NaN and infinities are errors.
LoadedScenario load_scenario(const std::filesystem::path& scenario_file,
                             const std::filesystem::path& rules_dir);

// The rules/ folder when the caller has none: $PIERRE_RULES if set and not empty; else
// `<executable's folder>/../rules` or `<executable's folder>/../share/pierre/rules` when it holds
// materials.toml (a build folder inside the source tree, or an installation); else "rules"
// (relative to the working folder). The io library has no compiled-in source path: the
// `pierre` program passes its own (--rules, $PIERRE_RULES, then the source tree's rules/).
std::filesystem::path default_rules_dir();

}  // namespace pierre::io
