#include "data_folders.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "pierre/io/input_error.hpp"

namespace pierre::app {
namespace {

namespace fs = std::filesystem;

struct DataFolder {
  fs::path path;                      // the folder to use
  std::vector<std::string> searched;  // every place looked at, in order, for error messages
  bool from_env = false;              // path is the environment variable's
  bool found = false;                 // path holds the probe file (or came from the variable)
};

std::string listed(const std::vector<std::string>& places) {
  std::string s;
  for (const auto& p : places) s += (s.empty() ? "" : ", ") + p;
  return s;
}

// A folder under the working folder, named relative to it (found, given by --rules or by the
// variable, absolute or as "./rules/"): the report records the rules files' paths, and a firm
// whose pipeline runs each job in a fresh workspace (a different absolute path each time) then
// gets the same bytes from the same inputs. Anywhere else, the path as given, normalised.
fs::path as_shown(const fs::path& given) {
  fs::path p = given.lexically_normal();
  if (p.has_parent_path() && p.filename().empty()) p = p.parent_path();  // "rules/" → "rules"
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  if (ec || !p.is_absolute()) return p.empty() ? given : p;
  const fs::path rel = p.lexically_relative(cwd.lexically_normal());
  if (rel.empty() || rel == "." || *rel.begin() == "..") return p;
  return rel;
}

DataFolder find(const char* name, const char* env_var, const char* probe) {
  DataFolder f;
  if (const char* env = std::getenv(env_var); env && *env) {
    f.path = as_shown(env);
    f.searched.push_back(fmt::format("${} = {}", env_var, env));
    f.from_env = f.found = true;
    return f;
  }
  f.searched.push_back(fmt::format("${} (not set)", env_var));
  std::vector<fs::path> candidates;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path prefix = exe.parent_path().parent_path();
    candidates.push_back(prefix / name);
    candidates.push_back(prefix / "share" / "pierre" / name);
  }
  candidates.push_back(name);  // relative to the working folder: an engineer's own copy
#ifdef PIERRE_SOURCE_DIR
  candidates.push_back(fs::path(PIERRE_SOURCE_DIR) / name);  // the last resort of a built binary
#endif
  for (const fs::path& c : candidates) {
    f.searched.push_back(c.string());
    if (fs::is_regular_file(c / probe, ec)) {
      f.path = as_shown(c);
      f.found = true;
      return f;
    }
  }
  f.path = candidates.back();
  return f;
}

}  // namespace

io::RulesFolder rules_folder(const std::string& option) {
  if (!option.empty()) return {as_shown(option), "the rules folder given by --rules"};
  const DataFolder f = find("rules", "PIERRE_RULES", "materials.toml");
  if (f.from_env) return {f.path, "the rules folder given by $PIERRE_RULES"};
  if (f.found) return {f.path};
  return {f.path, fmt::format("no rules folder holds materials.toml: looked in {} (give --rules "
                              "or set PIERRE_RULES to the folder that holds it)",
                              listed(f.searched))};
}

io::ReportTemplate load_report_layout(std::FILE* notes) {
  const DataFolder f = find("templates", "PIERRE_TEMPLATES", "report.toml");
  const fs::path file = f.path / "report.toml";
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    throw io::InputError(file, 0, "file", "no such file",
                         fmt::format("the report layout report.toml in a templates folder; looked "
                                     "in {} (set PIERRE_TEMPLATES to the folder that holds it)",
                                     listed(f.searched)));
  }
  io::ReportTemplate layout = io::load_report_template(file);
  // What a firm's copy lacks (the built-in layout gives it) or holds in vain (an earlier
  // layout's key), said on stderr so that the firm brings its copy up to date.
  auto some_keys = [](const std::vector<std::string>& keys) {
    constexpr std::size_t kShown = 6;
    std::string names;
    for (std::size_t i = 0; i < std::min(keys.size(), kShown); ++i)
      names += (i ? ", " : "") + keys[i];
    if (keys.size() > kShown) names += fmt::format(" and {} more", keys.size() - kShown);
    return fmt::format("{} key{} ({})", keys.size(), keys.size() == 1 ? "" : "s", names);
  };
  if (notes && !layout.built_in_keys.empty())
    fmt::print(notes, "Note: the report layout {} leaves out {}: the layout built into pierre gives {}.\n",
               file.string(), some_keys(layout.built_in_keys),
               layout.built_in_keys.size() == 1 ? "it" : "them");
  if (notes && !layout.retired_keys.empty())
    fmt::print(notes,
               "Note: the report layout {} holds {} that this version of pierre no longer uses: "
               "{} ignored.\n",
               file.string(), some_keys(layout.retired_keys),
               layout.retired_keys.size() == 1 ? "it is" : "they are");
  return layout;
}

}  // namespace pierre::app
