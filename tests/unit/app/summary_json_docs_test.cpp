// docs/summary-json.md documents every key summary.json has: a key added to the writer without
// its line in the reference fails here, not in a firm's parser (automation-user review: the
// file had no reference but a README paragraph).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using pierre::test::slurp;

class SummaryJsonDocs : public pierre::test::PierreCli {};

// Every key of every object in `j`, at any depth (the objects in arrays too).
void keys_of(const nlohmann::json& j, std::set<std::string>& out) {
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) {
      out.insert(it.key());
      keys_of(it.value(), out);
    }
  else if (j.is_array())
    for (const auto& e : j) keys_of(e, out);
}

// The names the reference gives in backticks: `name`, or the last part of a path
// (`barriers[].v_k_m_s.value`, `runout_m.lower_bounds`).
std::set<std::string> documented_names(const std::string& doc) {
  std::set<std::string> names;
  const std::regex code("`([^`\n]+)`");
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), code); it != std::sregex_iterator(); ++it) {
    std::string span = (*it)[1].str();
    while (span.size() > 2 && span.ends_with("[]")) span.resize(span.size() - 2);
    const std::size_t dot = span.find_last_of('.');
    names.insert(dot == std::string::npos ? span : span.substr(dot + 1));
  }
  return names;
}

TEST_F(SummaryJsonDocs, EveryKeyIsDocumented) {
  const std::string doc = slurp(fs::path(PIERRE_SOURCE_DIR) / "docs" / "summary-json.md");
  ASSERT_FALSE(doc.empty());
  const std::set<std::string> documented = documented_names(doc);
  // A barrier scenario (designed and checked barriers, observation lines) and a quarry one
  // (sections, a pooled row, observed values), run as a pipeline would run them.
  std::set<std::string> keys;
  for (const char* example : {"vaujany-2d", "quarry-austria"}) {
    const fs::path out = dir_ / example;
    const auto r = pierre(std::string("check ") + PIERRE_SOURCE_DIR + "/examples/" + example +
                          "/scenario.toml --out " + q(out) + " --throws 2 -q --all-crossings");
    ASSERT_LE(r.code, 1) << r.err;
    keys_of(nlohmann::json::parse(slurp(out / "summary.json")), keys);
  }
  // `validate --json`, valid and not: its keys are in the reference too.
  for (const std::string& scenario : {std::string(PIERRE_SOURCE_DIR) + "/examples/vaujany-2d/scenario.toml",
                                      (dir_ / "missing.toml").string()}) {
    const auto r = pierre("validate " + q(scenario) + " --json");
    ASSERT_LE(r.code, 2) << r.err;
    keys_of(nlohmann::json::parse(r.out), keys);
  }
  EXPECT_GT(keys.size(), 150u);  // the runs gave the keys to check
  for (const std::string& k : keys) EXPECT_TRUE(documented.count(k)) << "`" << k << "` is not in docs/summary-json.md";
  // The version the reference states is the one written.
  EXPECT_NE(doc.find("`schema_version` (currently `" +
                     nlohmann::json::parse(slurp(dir_ / "vaujany-2d" / "summary.json"))["schema_version"].dump() +
                     "`)"),
            std::string::npos);
}

}  // namespace
