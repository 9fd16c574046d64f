// Reads a scenario (TOML, docs/scenario-format.md) with its profile and block CSVs and the
// material presets of rules/, validates every field, and returns the simulation's Scenario
// plus what the report echoes; or, for a quarry scenario, its [[quarries]] sections (each a
// Scenario of its own). Throws InputError on bad input.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pierre/design/barrier_check.hpp"
#include "pierre/design/barrier_rules.hpp"
#include "pierre/io/block_group.hpp"
#include "pierre/io/document_control.hpp"
#include "pierre/io/input_error.hpp"
#include "pierre/io/input_files.hpp"
#include "pierre/io/quarry_reader.hpp"
#include "pierre/io/rules_folder.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::io {


struct LoadedScenario {
  sim::Scenario scenario;
  std::filesystem::path file;        // the scenario file as given
  std::string text;                  // its text, echoed in reports
  std::string description;
  DocumentControl document;
  std::vector<BlockGroup> block_groups;
  std::filesystem::path materials_file;  // where the presets came from
  // Every file read, in reading order, with its SHA-256 (summary.json "inputs").
  std::vector<InputFile> inputs;
  // What the command line set instead of the file (--seed, --throws), each with the file's
  // value: the echoed text no longer says what ran, so summary.json and the report say it.
  std::vector<std::string> overrides;
  // The line of [simulation] throws (0: not given), for a message about it after loading.
  long throws_line = 0;
  // Notes on the input, in reading order (a profile that runs back in x, a source far above
  // the ground; those of quarry sections too): printed by `run` and `validate`, never fatal.
  std::vector<InputNote> notes;

  // [[barriers]] (docs/scenario-format.md), in file order; index i of every vector below is
  // barrier i. The rule set, its class table and the observed data are loaded and checked
  // here, so that a run never starts with a barrier it cannot compute.
  std::vector<design::BarrierSpec> barriers;
  std::vector<design::BarrierRuleSet> barrier_rules;
  std::vector<std::filesystem::path> barrier_rules_files;
  std::vector<design::EnergyClassTable> barrier_classes;
  std::vector<std::optional<design::ObservedSample>> barrier_observed;

  // [[quarries]] (docs/quarry.md), in file order: a quarry scenario. Each section is its own
  // sim::Scenario (profile, blocks, sources, seed, floor_segment); `scenario` then holds only
  // the name, the [simulation] settings and the materials (no profile, blocks or sources), and
  // block_groups, lines and barriers are empty.
  std::vector<QuarrySection> quarries;
};

// `rules` holds materials.toml and the design rule sets; materials.toml is only read when a
// material names a preset and the scenario gives no `materials_file`; a barrier's rule set is
// <rules>/<name>.toml unless the scenario gives a path (relative to the scenario file). A file the
// folder lacks is said with how the folder was chosen (RulesFolder::how).
// Numbers: an integer is accepted where a float is expected (`mass = 1500`); nothing else
// converts (`throws = "5"` or `throws = 5.0` is an error). NaN and infinities are errors.
LoadedScenario load_scenario(const std::filesystem::path& scenario_file, const RulesFolder& rules);

// A scenario runs at most 2^53 trajectories, sources × blocks × throws (a count a double holds
// exactly; the 64-bit count wrapped past 2^64). Throws InputError at `field` of `file` (line 0:
// about the whole file, e.g. `--throws`, found `found`) when `s` asks for more; `what` names the
// scenario in the message when it is one of several (a quarry section), else "".
// load_scenario checks simulation.throws; a command that changes the throws checks again.
void check_trajectory_count(const sim::Scenario& s, const std::filesystem::path& file, long line,
                            const std::string& field, const std::string& found,
                            const std::string& what = "");

// "1 sources × 25 blocks × 10 throws are 250": how a scenario's count is made, for messages.
std::string trajectory_count_text(const sim::Scenario& s);

}  // namespace pierre::io
