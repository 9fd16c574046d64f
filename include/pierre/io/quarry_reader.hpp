// The quarry part of a scenario (docs/quarry.md): one or more [[quarries]] sections, each with
// its own profile, blocks, sources, optional toe/crest/height, work areas, bench width, observed
// values, pooling group and rule set; throws, seed and model settings come from [simulation]
// and materials from [materials]. Also the loading of a quarry rule set (rules/<name>.toml).
// Every problem is an InputError naming the file, the line, the field, what was found and
// what was expected.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "pierre/design/quarry_geometry.hpp"
#include "pierre/design/quarry_rules.hpp"
#include "pierre/design/quarry_zones.hpp"
#include "pierre/io/block_group.hpp"
#include "pierre/io/input_error.hpp"
#include "pierre/io/rules_folder.hpp"
#include "pierre/model/material.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::io {

// A quarry section ready to run: its Scenario (floor_segment set to the floor's first segment,
// its own seed), what the procedure needs, and what the report echoes.
struct QuarrySection {
  sim::Scenario scenario;
  design::QuarrySpec spec;
  design::QuarryRuleSet rules;
  design::QuarryGeometry geometry;
  design::QuarryObserved observed;
  std::vector<BlockGroup> block_groups;  // the block rows as written
  std::filesystem::path rules_file;
  bool seed_given = false;  // `seed` was written (else [simulation].seed + the section's index)
  std::vector<InputNote> notes;  // on its profile and sources while read; load_scenario moves
                                 // them into LoadedScenario::notes
};

// The seed of section `index` that gives none: the run's seed + index, wrapped into 0 to 2^63 − 1
// so that every seed a report shows can be given back (TOML and --seed stop at 2^63 − 1).
inline std::uint64_t section_seed(std::uint64_t run_seed, std::size_t index) {
  return (run_seed + index) & 0x7FFF'FFFF'FFFF'FFFFull;
}

// How a message names section `index`: quarries[1] "North".
std::string section_label(std::size_t index, const std::string& name);

// How the sections' trajectories are counted, for a message about their sum: each section's
// trajectory_count_text, and the sum. (The sections run one after the other, but their
// statistics are kept together: the memory must hold all their trajectories.)
std::string sections_count_text(const std::vector<QuarrySection>& sections);

// A rule set by name ("quarry-thesis-2015" → rules_dir/quarry-thesis-2015.toml) or by path (a
// value ending in ".toml" or holding a '/'; used as given).
design::QuarryRuleSet load_quarry_rules(const std::string& name_or_path,
                                        const std::filesystem::path& rules_dir);

// Reads root's [[quarries]] (empty when there is none). `file` is the scenario file (messages,
// relative paths); `materials` the scenario's [materials] (indices shared by every section);
// `settings` its [simulation] (each section gets a copy with its own seed and floor_segment).
std::vector<QuarrySection> read_quarries(const toml::table& root, const std::filesystem::path& file,
                                         const RulesFolder& rules,
                                         const std::vector<model::Material>& materials,
                                         const sim::SimulationSettings& settings);

}  // namespace pierre::io
