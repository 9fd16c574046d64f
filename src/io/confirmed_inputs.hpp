// [confirmed]: inputs that an input note doubts as a likely slip (a density in t/m³, a source
// height a.s.l. over a local profile) and that the engineer has checked and means. A note's
// doubt turns the PASS of the check lines resting on it into WARN (design::doubt_passes); a
// pipeline that runs such a value on purpose restates it here, and its lines can pass again.
// Internal to the io library.
#pragma once

#include <string>
#include <vector>

#include "pierre/io/input_error.hpp"
#include "toml_fields.hpp"

namespace pierre::io::detail {

// The key that confirms a note: the field it names ("blocks.density", "sources[1].z"), after
// the CSV's path from the scenario's folder and the line for a note on a CSV
// ("north/blocks.csv:26:mass"). `scenario_file`: the TOML file.
std::string confirmation_key(const InputNote& note, const std::filesystem::path& scenario_file);

// Reads top.confirmed (keys as confirmation_key gives them, quoted or as nested tables; each
// value the number the note names) and applies it to the notes that doubt an input: one whose
// key and value are given loses its doubt and says it was confirmed; one confirmed at another
// value keeps its doubt and says so; every other one says how to confirm it. A key that confirms
// no note is itself noted (a misspelt or stale confirmation does nothing). A value that is not a
// number is an InputError.
void apply_confirmations(const TomlTable& top, std::vector<InputNote>& notes);

}  // namespace pierre::io::detail
