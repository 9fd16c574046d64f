#include "pierre/io/rules_folder.hpp"

#include <system_error>

namespace pierre::io {

std::string RulesFolder::named(std::string_view more) const {
  std::string inside = how;
  auto add = [&inside](std::string_view part) {
    if (part.empty()) return;
    if (!inside.empty()) inside += "; ";
    inside += part;
  };
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    add("no such folder");
  else if (!std::filesystem::is_directory(path, ec))
    add("a file, not a folder");
  add(more);
  return inside.empty() ? path.string() : path.string() + " (" + inside + ")";
}

}  // namespace pierre::io
