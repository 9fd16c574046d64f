// Where pierre finds the reference data an engineer edits: rules/ (materials, barrier and
// quarry rule sets) and templates/ (the report's layout). Both are looked for the same way, so
// a binary that finds one finds the other.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pierre/io/report_template.hpp"

namespace pierre::app {

struct DataFolder {
  std::filesystem::path path;          // the folder to use
  std::vector<std::string> searched;   // every place looked at, in order, for error messages
};

// The rules folder: `option` (--rules) when given; else $PIERRE_RULES when set; else the first
// of <executable>/../rules, <executable>/../share/pierre/rules, ./rules and the source tree's
// rules/ (when built from source) that holds materials.toml (the last when none does).
DataFolder rules_folder(const std::string& option);

// The templates folder: $PIERRE_TEMPLATES when set; else the first of the same places (with
// templates/ for rules/) that holds report.toml (the last when none does).
DataFolder templates_folder();

// The report layout, read before anything is simulated so that a missing or broken template
// costs nothing: an io::InputError (exit 2) names the places searched when there is none.
io::ReportTemplate load_report_layout();

}  // namespace pierre::app
