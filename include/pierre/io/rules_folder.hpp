// The rules folder (materials.toml, the barrier and quarry rule sets, the energy class tables)
// and how it was chosen, so that a message about a file it lacks says where the folder came
// from (--rules, $PIERRE_RULES, or the places searched), as the report layout's message does.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace pierre::io {

struct RulesFolder {
  // Implicit: a folder given as a bare path is named by its path alone.
  RulesFolder(std::filesystem::path folder, std::string how_chosen = {})  // NOLINT
      : path(std::move(folder)), how(std::move(how_chosen)) {}
  RulesFolder(const char* folder) : path(folder) {}         // NOLINT
  RulesFolder(const std::string& folder) : path(folder) {}  // NOLINT

  std::filesystem::path path;
  // How it was chosen, said after its path: "the rules folder given by --rules". May be empty.
  std::string how;

  // The folder for a message: "/x (the rules folder given by --rules)", with `more` and, when
  // there is no such folder, "no such folder" added inside the parentheses ("/x (more)" or "/x"
  // when `how` is empty).
  std::string named(std::string_view more = {}) const;
};

}  // namespace pierre::io
