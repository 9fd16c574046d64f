// Where pierre finds the reference data an engineer edits: rules/ (materials, barrier and
// quarry rule sets) and templates/ (the report's layout). Both are looked for the same way, so
// a binary that finds one finds the other.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "pierre/io/report_template.hpp"
#include "pierre/io/rules_folder.hpp"

namespace pierre::app {

// The rules folder: `option` (--rules) when given; else $PIERRE_RULES when set; else the first
// of <executable>/../rules, <executable>/../share/pierre/rules, ./rules and the source tree's
// rules/ (when built from source) that holds materials.toml (the last when none does). A folder
// found under the working folder is named relative to it (the report records the paths). Its
// `how` says which it was (--rules, $PIERRE_RULES, or the places searched when none held
// materials.toml) for the messages about a file it lacks.
io::RulesFolder rules_folder(const std::string& option);

// The report layout, templates/report.toml, with templates/ looked for the same way
// ($PIERRE_TEMPLATES, then the same places). Read before anything is simulated, so that a
// missing or broken one costs nothing: an io::InputError (exit 2) names the places searched.
// A layout that leaves keys out (a firm's copy older than this version) is completed from the
// built-in one; a note on `notes` (when not null) names the keys.
io::ReportTemplate load_report_layout(std::FILE* notes);

}  // namespace pierre::app
