// `cmake --install`: the installed program reads the rules and the report layout installed
// with it (DIR/share/pierre), not those of the checkout it was built from, nor ./rules. A firm's
// pipeline running an installed copy must not follow a source tree people edit (a layout key
// added there stopped every run of a build-folder binary: automation-user review).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using pierre::test::slurp;

class Install : public pierre::test::PierreCli {
 protected:
  // Runs `command` in the test's folder; its exit status.
  int sh(const std::string& command) {
    const std::string cmd = "cd " + q(dir_) + " && " + command + " >" + q(dir_ / "log.txt") + " 2>&1";
    const int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  }
};

TEST_F(Install, TheInstalledProgramReadsTheDataInstalledWithIt) {
  const fs::path prefix = dir_ / "inst";
  // cmake --install writes the build folder's install_manifest.txt: an engineer's own install
  // keeps its record, and a build that had none is left without.
  const fs::path manifest = fs::path(PIERRE_BUILD_DIR) / "install_manifest.txt";
  const bool had_manifest = fs::exists(manifest);
  const std::string kept = had_manifest ? slurp(manifest) : std::string();
  const int installed = sh(std::string("'") + PIERRE_CMAKE + "' --install '" + PIERRE_BUILD_DIR +
                           "' --prefix " + q(prefix));
  if (had_manifest)
    std::ofstream(manifest, std::ios::binary) << kept;
  else
    fs::remove(manifest);
  ASSERT_EQ(installed, 0) << slurp(dir_ / "log.txt");
  for (const char* f : {"bin/pierre", "share/pierre/rules/materials.toml",
                        "share/pierre/templates/report.toml",
                        "share/doc/pierre/examples/quarry-preg/scenario.toml",
                        "share/doc/pierre/docs/scenario-format.md", "share/doc/pierre/README.md"})
    EXPECT_TRUE(fs::is_regular_file(prefix / f)) << f;
  // A ./rules of the working folder comes after the installed data: it is not read (it holds
  // no valid materials file, so reading it would fail).
  fs::create_directories(dir_ / "rules");
  std::ofstream(dir_ / "rules" / "materials.toml") << "this is not TOML [\n";
  ASSERT_EQ(sh("env -u PIERRE_RULES -u PIERRE_TEMPLATES inst/bin/pierre run "
               "inst/share/doc/pierre/examples/quarry-preg/scenario.toml --out out --throws 1 -q"),
            0)
      << slurp(dir_ / "log.txt");
  const auto j = nlohmann::json::parse(slurp(dir_ / "out" / "summary.json"));
  EXPECT_EQ(j["scenario"]["materials_file"], "inst/share/pierre/rules/materials.toml");
  bool layout = false;
  for (const auto& f : j["inputs"]) {
    const std::string file = f["file"];
    EXPECT_EQ(file.find(PIERRE_SOURCE_DIR), std::string::npos) << file;  // nothing from the checkout
    layout = layout || file == "inst/share/pierre/templates/report.toml";
  }
  EXPECT_TRUE(layout) << j["inputs"];
}

}  // namespace
