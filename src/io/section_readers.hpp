// The readers of a slope section's parts, shared by the scenario reader (top-level [profile],
// [blocks], [[sources]]) and the quarry reader ([[quarries]] sections: quarries[i].profile, …):
// one format, one set of messages. Internal to the io library.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "pierre/geometry/profile.hpp"
#include "pierre/io/block_group.hpp"
#include "pierre/io/input_error.hpp"
#include "pierre/model/block.hpp"
#include "pierre/model/material.hpp"
#include "pierre/sim/scenario.hpp"
#include "text_file.hpp"
#include "toml_fields.hpp"

namespace pierre::io::detail {

// The sections of a scenario file, the keys of its root: what the scenario reader accepts there,
// and what a key typed below another section's header is recognised as (toml_fields.hpp).
inline const std::initializer_list<std::string_view> kScenarioSections = {
    "scenario", "simulation", "profile",  "materials", "blocks",
    "sources",  "observation_lines",      "barriers",  "quarries", "confirmed"};

// In the readers below `parent` is the table holding the part (the root, or one [[quarries]]
// entry) and `table_path` its path as a TOML header names it ("" for the root, "quarries"),
// used in messages: "a [quarries.profile] table".

// parent.profile: { file = CSV } or { points = [[x, z, "material"], …] }; material names from
// `materials`. A run of segments that goes back in x (an overhang, or an x typed out of order)
// adds a note to `notes`, at the first vertex that lies behind its predecessor.
geometry::Profile read_profile(const TomlTable& parent, const std::vector<model::Material>& materials,
                               std::string_view table_path, std::vector<InputNote>& notes);

// parent.blocks: the block rows as written (appended to `groups`) and the blocks they expand
// to (appended to `blocks`, a row of count n giving ids "<id>.1" … "<id>.n"). A density outside
// kRockDensityMin..Max, or a heaviest block lighter than kLightestPlausibleBlock or heavier than
// kHeaviestPlausibleBlock, add a note to `notes`: the usual unit slips (t/m³, tonnes, litres),
// which change every energy a thousandfold.
void read_blocks(const TomlTable& parent, std::vector<BlockGroup>& groups,
                 std::vector<model::Block>& blocks, std::string_view table_path,
                 std::vector<InputNote>& notes);

// The largest coordinate in size (m). Beyond a million kilometres the geometry's squares
// overflow (a segment 1e200 m long has an infinite length) and the error that followed named
// the wrong cause. No section comes near.
inline constexpr double kMaxCoordinate = 1e9;

// The expectation of a block (`what`: "a block", "a design block") heavier than the model's
// limit. Given by volume, it shows the density that made the mass (a density typed in t/m³ or
// g/cm³ times 1000 is the usual cause).
std::string block_mass_limit(std::string_view what, double volume, double density, double mass,
                             bool by_volume);

// Densities of rock (kg/m³): from porous tuff and chalk (~1500) to the heaviest ores in a quarry
// face (~4000). Outside, a density in t/m³ or g/cm³ (2.65) is far likelier than a rock.
inline constexpr double kRockDensityMin = 1500.0;
inline constexpr double kRockDensityMax = 4000.0;
// Why a density outside rock's is noted, for the value found: in t/m³ (2.65), what it would be
// in kg/m³ and what it does as typed (`effect`: "blocks 1000 times too light, and every energy
// 1000 times too small").
std::string density_slip(double density, std::string_view effect);
// When even the heaviest block is lighter than this (kg; a stone of ~4 litres), the masses were
// most likely typed in tonnes or the volumes in litres. Rockfall design blocks weigh from
// hundreds of kilograms up (the thesis's lightest, at Preg, 140 kg).
inline constexpr double kLightestPlausibleBlock = 10.0;
// And when the heaviest is heavier than this (kg; ~400 m³ of rock), volumes typed in litres or
// masses in grams are likelier than a block beyond any barrier (the largest tested: 8 000 kJ).
inline constexpr double kHeaviestPlausibleBlock = 1e6;

// parent.sources (one or more): appended to scenario.sources, each inside scenario.profile's
// horizontal extent. A source far above the ground under it, or far below the ground over it
// (kFarAboveGround), adds a note to `notes`, at its z; so does one whose ground falls towards
// the profile's first vertex, at its table.
void read_sources(const TomlTable& parent, sim::Scenario& scenario, std::string_view table_path,
                  std::vector<InputNote>& notes);

// A source is noted when it is more than this far above the ground under it and more than the
// profile's whole height (m). Higher than the whole section, its block gains more speed in the
// air than the slope drawn could give it: it is not a release from that slope. The 100 m spares
// a deliberate drop over a short section (a test bench, a small cut); 100 m of free fall already
// reaches 44 m/s at the first impact, beyond what blocks reach on talus (20-30 m/s). Either
// way the first impact governs the results, and the usual cause is a z in absolute elevations
// (m a.s.l.) over a profile in local ones.
inline constexpr double kFarAboveGround = 100.0;

// "inside the profile's horizontal extent [x0, x1] m"
std::string extent(const geometry::Profile& profile);

}  // namespace pierre::io::detail
