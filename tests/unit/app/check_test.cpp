// `pierre check` and the barriers of `pierre run` with the real binary: exit codes (0 every
// check passes, 1 a check FAILs, 2 bad barrier input with nothing written), the check table on
// stdout, "barriers" and "checks" in summary.json.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/cli_fixture.hpp"
#include "support/tools.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kData = PIERRE_TEST_DATA "/barrier/";

using Result = pierre::test::CliResult;
using pierre::test::count_of;
using pierre::test::slurp;
using pierre::test::zip_listing;

class Check : public pierre::test::PierreCli {};

std::set<std::string> statuses(const nlohmann::json& checks) {
  std::set<std::string> s;
  for (const auto& c : checks) s.insert(c["status"].get<std::string>());
  return s;
}

// A copy of tests/data/barrier/`name` at `file`, its profile path made absolute (the copy lives
// elsewhere) and each `from` replaced by its `to`; a `from` the file lacks is the test's error.
void write_variant(const std::string& name,
                   const std::vector<std::pair<std::string, std::string>>& edits,
                   const fs::path& file) {
  std::string text = slurp(kData + name);
  std::vector<std::pair<std::string, std::string>> all{
      {"\"../small/profile.csv\"", "\"" PIERRE_TEST_DATA "/small/profile.csv\""}};
  all.insert(all.end(), edits.begin(), edits.end());
  for (const auto& [from, to] : all) {
    const auto k = text.find(from);
    if (k == std::string::npos) throw std::runtime_error(name + " has no " + from);
    text.replace(k, from.size(), to);
  }
  std::ofstream(file) << text;
}

const nlohmann::json& check(const nlohmann::json& j, const std::string& id) {
  for (const auto& c : j["checks"])
    if (c["id"] == id) return c;
  throw std::runtime_error("no check " + id);
}

TEST_F(Check, PassingCandidateExitsZero) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "pass.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("Checks"), std::string::npos);
  for (const char* col : {"subject", "id", "value", "limit", "unit", "status", "rule"})
    EXPECT_NE(r.out.find(col), std::string::npos) << col;
  const auto j = summary(out);
  ASSERT_EQ(j["checks"].size(), 11u);
  EXPECT_EQ(statuses(j["checks"]).count("FAIL"), 0u);
  EXPECT_EQ(check(j, "energy.mel")["status"], "PASS");
  EXPECT_EQ(check(j, "height.interception")["status"], "PASS");
  EXPECT_EQ(check(j, "energy.mel")["subject"], "Generous");
  // The console's last line counts every status, as the lines in summary.json have them (it
  // said only the FAILs: a WARN went unread, new-user review).
  auto lines_at = [&](const char* status) {
    return std::count_if(j["checks"].begin(), j["checks"].end(),
                         [&](const auto& c) { return c["status"] == status; });
  };
  EXPECT_NE(r.out.find(fmt::format("\n11 check lines: 0 FAIL, {} WARN, {} PASS, {} N/A\n",
                                   lines_at("WARN"), lines_at("PASS"), lines_at("N/A"))),
            std::string::npos)
      << r.out;
  EXPECT_GT(lines_at("WARN") + lines_at("N/A"), 0);  // the counts are not all in PASS
  EXPECT_EQ(j["checks_failed"], false);
  ASSERT_EQ(j["barriers"].size(), 1u);
  const auto& b = j["barriers"][0];
  EXPECT_EQ(b["name"], "Generous");
  EXPECT_EQ(b["rules"]["name"], "thesis-2015");
  // thesis-2015 checks no elongation: no γd.
  EXPECT_TRUE(b["gamma_d_MEL"].is_null() && b["gamma_d_SEL"].is_null());
  // Every barrier has a design: the list of those without is there, empty (no guard needed).
  ASSERT_TRUE(j.contains("barriers_without_design"));
  EXPECT_TRUE(j["barriers_without_design"].is_array() && j["barriers_without_design"].empty());
  // Which files the design read, for the record: the rule set and the class table it names.
  EXPECT_TRUE(fs::equivalent(b["rules"]["file"].get<std::string>(),
                             PIERRE_SOURCE_DIR "/rules/thesis-2015.toml"))
      << b["rules"];
  EXPECT_EQ(b["energy_classes"]["name"], "etag027-classes");
  EXPECT_EQ(b["energy_classes"]["title"], "ETAG 027 / EAD 340059-00-0106 energy classes");
  EXPECT_TRUE(fs::equivalent(b["energy_classes"]["file"].get<std::string>(),
                             PIERRE_SOURCE_DIR "/rules/etag027-classes.toml"))
      << b["energy_classes"];
  EXPECT_EQ(b["mode"], "check");
  // The requirement in summary.json is the limit of the check line.
  EXPECT_DOUBLE_EQ(b["MEL_req_kJ"].get<double>(), check(j, "energy.mel")["limit"].get<double>());
  EXPECT_DOUBLE_EQ(b["h_i_m"].get<double>(), check(j, "height.interception")["limit"].get<double>());
  EXPECT_DOUBLE_EQ(b["m_d_kg"].get<double>(), 1.0 * 2650 * 1.05);
  EXPECT_EQ(b["v_k_m_s"]["interval"]["resamples"], 1000);
  // Every line that is not PASS has its reason printed under the table, N/A ones too (an N/A
  // line shows a value and a limit that need not agree).
  ASSERT_GT(statuses(j["checks"]).count("N/A"), 0u);  // elongation: thesis-2015 has no γd
  for (const auto& c : j["checks"]) {
    if (c["status"] == "PASS") continue;
    const std::string line = c["status"].get<std::string>() + " " + c["subject"].get<std::string>() +
                             " " + c["id"].get<std::string>() + ": " + c["reason"].get<std::string>();
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  }
}

// pass.toml with its blocks' density typed in t/m³ (2.65), its profile named from anywhere.
std::string density_in_tonnes() {
  std::string text = slurp(kData + "pass.toml");
  auto swap = [&](const std::string& from, const std::string& to) {
    const auto k = text.find(from);
    if (k == std::string::npos) throw std::runtime_error("pass.toml has no " + from);
    text.replace(k, from.size(), to);
  };
  swap("[blocks]\ndensity = 2650.0", "[blocks]\ndensity = 2.65");
  swap("\"../small/profile.csv\"", "\"" + kData + "../small/profile.csv\"");
  return text;
}

// `validate --json`: the verdict as one JSON object on stdout and nothing else there, for a script
// (a pre-commit hook annotating file:line): valid with its notes; an input error with its file,
// line, field, found and expected, exit 2 as without --json; --strict refusing a doubted input.
TEST_F(Check, ValidateJsonGivesTheVerdictToAScript) {
  const Result ok = pierre("validate " + kData + "pass.toml --json");
  ASSERT_EQ(ok.code, 0) << ok.err;
  const auto v = nlohmann::json::parse(ok.out);  // throws on anything but one JSON object
  EXPECT_EQ(v["valid"], true);
  EXPECT_TRUE(v["error"].is_null());
  EXPECT_EQ(v["in_doubt"], 0);
  EXPECT_GT(v["trajectories"].get<std::uint64_t>(), 0u);

  std::ofstream(dir_ / "bad.toml") << "[scenario]\nname = \"x\"\n[simulation]\nseed = 1\nthrows = 2.5\n";
  const Result bad = pierre("validate " + q(dir_ / "bad.toml") + " --json");
  EXPECT_EQ(bad.code, 2);
  const auto e = nlohmann::json::parse(bad.out);
  EXPECT_EQ(e["valid"], false);
  EXPECT_EQ(e["error"]["file"], (dir_ / "bad.toml").string());
  EXPECT_EQ(e["error"]["line"], 5);
  EXPECT_EQ(e["error"]["field"], "simulation.throws");
  EXPECT_EQ(e["error"]["found"], "2.5");
  EXPECT_EQ(e["error"]["expected"], "an integer");
  EXPECT_TRUE(e["trajectories"].is_null());
  // A path whose bytes are not UTF-8 (a Latin-1 folder name) is still one JSON object (the JSON
  // writer threw, exit 3 and nothing on stdout): the byte stands replaced.
  const fs::path latin1 = dir_ / "v\xe9";
  fs::create_directories(latin1);
  fs::copy_file(dir_ / "bad.toml", latin1 / "bad.toml");
  const Result odd = pierre("validate " + q(latin1 / "bad.toml") + " --json");
  EXPECT_EQ(odd.code, 2) << odd.err;
  EXPECT_EQ(nlohmann::json::parse(odd.out)["error"]["line"], 5);

  std::ofstream(dir_ / "slip.toml") << density_in_tonnes();
  const Result doubted = pierre("validate " + q(dir_ / "slip.toml") + " --json");
  ASSERT_EQ(doubted.code, 0) << doubted.err;
  const auto d = nlohmann::json::parse(doubted.out);
  EXPECT_EQ(d["valid"], true);
  EXPECT_EQ(d["in_doubt"], 1);
  ASSERT_EQ(d["input_notes"].size(), 1u);
  EXPECT_EQ(d["input_notes"][0]["field"], "blocks.density");
  EXPECT_EQ(d["input_notes"][0]["in_doubt"], true);
  const Result strict = pierre("validate " + q(dir_ / "slip.toml") + " --json --strict");
  EXPECT_EQ(strict.code, 2);
  const auto r = nlohmann::json::parse(strict.out);
  EXPECT_EQ(r["valid"], false);
  EXPECT_EQ(r["error"]["field"], "blocks.density");
  EXPECT_EQ(r["input_notes"].size(), 1u);  // the note that the refusal rests on
}

// A density typed in t/m³ (2.65 for 2650 kg/m³) makes the block given by volume 1000 times too
// light and the one given by mass 1000 times too large; the reader notes it, and no line of the
// run may then PASS: a pipeline gating on `check` would take a barrier checked against blocks of
// a few kilograms for a sized one. Each PASS of the same
// file with the density right is a WARN naming the input, and FAIL-free, the exit stays 0.
TEST_F(Check, NoPlainPassOnBlocksTheReaderDoubts) {
  const std::string text = density_in_tonnes();
  std::ofstream(dir_ / "slip.toml") << text;
  const Result good = pierre("check " + kData + "pass.toml --out '" + (dir_ / "good").string() + "' -q");
  ASSERT_EQ(good.code, 0) << good.err;
  const Result slip = pierre("check '" + (dir_ / "slip.toml").string() + "' --out '" +
                             (dir_ / "slip").string() + "' -q");
  EXPECT_EQ(slip.code, 0) << slip.err;
  EXPECT_NE(slip.err.find("slip.toml:24: blocks.density: the block density 2.65 kg/m³"),
            std::string::npos)
      << slip.err;
  const auto g = summary(dir_ / "good"), b = summary(dir_ / "slip");
  const std::string doubt = ", but it rests on blocks.density, noted as a likely slip (see the input notes)";
  for (const auto& c : b["checks"]) {
    SCOPED_TRACE(c.dump());
    EXPECT_NE(c["status"], "PASS");
  }
  // The candidate's lines pass with the density right, and are WARNs on the doubted one.
  for (const char* id : {"energy.mel", "energy.sel", "height.interception"}) {
    SCOPED_TRACE(id);
    EXPECT_EQ(check(g, id)["status"], "PASS");
    EXPECT_EQ(check(b, id)["status"], "WARN");
    EXPECT_NE(check(b, id)["reason"].get<std::string>().find(doubt), std::string::npos);
  }
}

// A value the reader doubts but the engineer means is restated under [confirmed]: the lines
// then pass again, as they would have without the note. A confirmation at another value, or
// under a misspelt name, lifts nothing and is said.
TEST_F(Check, AConfirmedValueLetsItsLinesPassAgain) {
  const std::string text = density_in_tonnes();
  struct Case {
    std::string name, confirmed;
  };
  for (const Case& c : {Case{"slip", ""}, Case{"meant", "\"blocks.density\" = 2.65"},
                        Case{"nested", "blocks.density = 2.65"},
                        Case{"other", "\"blocks.density\" = 2.7\nsimulation.gravty = 9.81"}}) {
    std::ofstream(dir_ / (c.name + ".toml"))
        << text << (c.confirmed.empty() ? "" : "\n[confirmed]\n" + c.confirmed + "\n");
    const Result r = pierre("check '" + (dir_ / (c.name + ".toml")).string() + "' --out '" +
                            (dir_ / c.name).string() + "' -q");
    ASSERT_EQ(r.code, 0) << c.name << r.err;
    if (c.name == "slip") {
      EXPECT_NE(r.err.find("If it is meant, confirm it in the scenario: [confirmed] "
                           "\"blocks.density\" = 2.65"),
                std::string::npos)
          << r.err;
    }
    if (c.name == "meant" || c.name == "nested") {
      EXPECT_NE(r.err.find("Confirmed as meant ([confirmed] \"blocks.density\" = 2.65, line "),
                std::string::npos)
          << r.err;
    }
    if (c.name == "other") {
      EXPECT_NE(r.err.find("[confirmed] gives 2.7 for it"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("confirmed.simulation.gravty: \"simulation.gravty\" confirms nothing"),
                std::string::npos)
          << r.err;
    }
  }
  const std::string doubt = ", but it rests on blocks.density, noted as a likely slip";
  const auto slip = summary(dir_ / "slip");
  std::size_t lifted = 0;
  for (const char* name : {"meant", "nested", "other"}) {
    const auto j = summary(dir_ / name);
    ASSERT_EQ(j["checks"].size(), slip["checks"].size());
    for (std::size_t i = 0; i < j["checks"].size(); ++i) {
      const auto &c = j["checks"][i], &s = slip["checks"][i];
      SCOPED_TRACE(std::string(name) + " " + c.dump());
      const std::string reason = s["reason"].get<std::string>();
      const auto k = reason.find(doubt);
      if (std::string(name) == "other" || k == std::string::npos) {
        EXPECT_EQ(c["status"], s["status"]);
        EXPECT_EQ(c["reason"], s["reason"]);
      } else {
        ++lifted;
        EXPECT_EQ(s["status"], "WARN");
        EXPECT_EQ(c["status"], "PASS");
        EXPECT_EQ(c["reason"], reason.substr(0, k));
      }
    }
  }
  EXPECT_GE(lifted, 6u);  // energy.mel, energy.sel, height.interception, twice
  // summary.json says which notes doubt their input, and counts the lines of each status.
  for (const char* name : {"slip", "meant"}) {
    const auto j = summary(dir_ / name);
    ASSERT_EQ(j["input_notes"].size(), 1u);
    EXPECT_EQ(j["input_notes"][0]["in_doubt"], std::string(name) == "slip");
    std::map<std::string, std::size_t> counted;
    for (const auto& c : j["checks"]) ++counted[c["status"].get<std::string>()];
    for (const char* st : {"PASS", "WARN", "FAIL", "N/A"}) {
      SCOPED_TRACE(st);
      EXPECT_EQ(j["check_counts"][st].get<std::size_t>(), counted[st]);
    }
  }
  // --strict refuses the doubted input before anything runs, and takes the confirmed one.
  for (const char* command : {"check", "run", "validate"}) {
    SCOPED_TRACE(command);
    const fs::path strict = dir_ / ("strict-" + std::string(command));
    const bool validate = std::string(command) == "validate";
    const std::string out = validate ? std::string() : " --out '" + strict.string() + "' -q";
    const Result r = pierre(std::string(command) + " '" + (dir_ / "slip.toml").string() + "'" +
                            out + " --strict");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("slip.toml:24: blocks.density: found 2.65, expected the value corrected, or "
                         "confirmed as meant under [confirmed] (--strict refuses an input noted as "
                         "a likely slip): the block density 2.65 kg/m³ is outside"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(strict));
    const Result ok = pierre(std::string(command) + " '" + (dir_ / "meant.toml").string() + "'" +
                             out + " --strict");
    EXPECT_EQ(ok.code, 0) << ok.err;
    if (validate) {  // its notes once, on stdout with its verdict
      EXPECT_EQ(count_of(ok.out + ok.err, "Confirmed as meant"), 1u) << ok.out << ok.err;
    }
  }
}

// A name longer than its column widens the column: the barrier table's and the check table's
// later columns stay under their headings (a 25-character name pushed them out of line).
TEST_F(Check, ALongNameWidensItsColumn) {
  const fs::path file = dir_ / "long.toml";
  const std::string name = "Generous barrier, ch. 1+250";  // 27 characters: more than 18
  write_variant("pass.toml", {{"name = \"Generous\"", "name = \"" + name + "\""}}, file);
  const Result r = pierre("check " + q(file) + " --out " + q(dir_ / "out"));
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  auto line_starting = [&](const std::string& start) {
    const auto k = r.out.find("\n" + start);
    if (k == std::string::npos) throw std::runtime_error("no line starting " + start + "\n" + r.out);
    return r.out.substr(k + 1, r.out.find('\n', k + 1) - k - 1);
  };
  // Each heading's column holds its value, one space after the widest name.
  const std::string barriers = line_starting("barrier "), row = line_starting(name + " Screen 1");
  EXPECT_EQ(barriers.find("line"), name.size() + 1) << barriers;
  EXPECT_EQ(barriers.find("rules"), row.find("thesis-2015")) << barriers << "\n" << row;
  const std::string checks = line_starting("subject "), mel = line_starting(name + " energy.mel");
  EXPECT_EQ(checks.find(" id "), name.size()) << checks;
  EXPECT_EQ(checks.find("status"), mel.find("PASS")) << checks << "\n" << mel;
}

TEST_F(Check, FailingCandidateExitsOneAndStillWritesTheResults) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "fail.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 1) << r.err << r.out;
  EXPECT_NE(r.out.find("FAIL"), std::string::npos);
  const auto j = summary(out);
  EXPECT_EQ(check(j, "energy.mel")["status"], "FAIL");
  EXPECT_EQ(check(j, "energy.sel")["status"], "FAIL");
  EXPECT_EQ(check(j, "height.interception")["status"], "FAIL");
  EXPECT_EQ(j["checks_failed"], true);
  EXPECT_TRUE(fs::exists(out / "crossings.csv"));
}

// --fail-on-warn: a pipeline that takes no advisory line gets exit 1 for a WARN, said on stderr
// (the check lines themselves say only WARN); a FAIL is a FAIL with or without it.
TEST_F(Check, FailOnWarnTurnsAWarningIntoExitOne) {
  const Result plain = pierre("check " + kData + "pass.toml --out '" + (dir_ / "a").string() + "' -q");
  ASSERT_EQ(plain.code, 0) << plain.err << plain.out;
  const auto checks = summary(dir_ / "a")["checks"];
  const auto warns = std::count_if(checks.begin(), checks.end(),
                                   [](const auto& c) { return c["status"] == "WARN"; });
  ASSERT_GT(warns, 0) << "the test needs a WARN in pass.toml";
  const Result gate =
      pierre("check " + kData + "pass.toml --out '" + (dir_ / "b").string() + "' -q --fail-on-warn");
  EXPECT_EQ(gate.code, 1) << gate.err << gate.out;
  EXPECT_NE(gate.err.find(fmt::format("Exit code 1 (--fail-on-warn): {} check line{} WARN.", warns,
                                      warns == 1 ? "" : "s")),
            std::string::npos)
      << gate.err;
  const Result fail =
      pierre("check " + kData + "fail.toml --out '" + (dir_ / "c").string() + "' -q --fail-on-warn");
  EXPECT_EQ(fail.code, 1) << fail.err;
  EXPECT_EQ(fail.err.find("--fail-on-warn"), std::string::npos) << fail.err;  // failed anyway
  // `run` has no such option: it exits 0 whatever the checks say.
  EXPECT_EQ(pierre("run " + kData + "pass.toml --out '" + (dir_ / "d").string() + "' --fail-on-warn").code, 2);
  // summary.json says which gate made the exit code, for a pipeline that reads only the file.
  using nlohmann::json;
  EXPECT_EQ(summary(dir_ / "a")["command"],
            json({{"name", "check"}, {"strict", false}, {"fail_on_warn", false}}));
  EXPECT_EQ(summary(dir_ / "b")["command"],
            json({{"name", "check"}, {"strict", false}, {"fail_on_warn", true}}));
  ASSERT_EQ(pierre("run " + kData + "pass.toml --out '" + (dir_ / "e").string() + "' -q --strict").code, 0);
  EXPECT_EQ(summary(dir_ / "e")["command"],
            json({{"name", "run"}, {"strict", true}, {"fail_on_warn", false}}));
  EXPECT_EQ(summary(dir_ / "e")["schema_version"], 1);
}

// A FAIL whose table could not be printed (a full disk, here /dev/full; a closed pipe) still
// exits 1, with the failed write said on stderr: a pipeline must see the verdict, not an alert.
TEST_F(Check, AFailStaysOneWhenStdoutCannotBeWritten) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  const fs::path e = dir_ / "stderr.txt";
  const std::string cmd = std::string("'") + PIERRE_BINARY + "' check " + kData + "fail.toml --out " +
                          q(dir_ / "out") + " >/dev/full 2>" + q(e);
  const int st = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 1) << slurp(e);
  EXPECT_NE(slurp(e).find("error: cannot write to standard output: No space left on device"),
            std::string::npos)
      << slurp(e);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "summary.json"));
}

// --help and --version that cannot be written exit 3, as any other lost output does (they
// exited 0: a script reading the version took nothing for it, new-user review).
TEST_F(Check, HelpAndVersionLostOnTheirWayExitThree) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  for (const char* args : {"--version", "--help", "check --help"}) {
    const fs::path e = dir_ / "stderr.txt";
    const int st = std::system((std::string("'") + PIERRE_BINARY + "' " + args + " >/dev/full 2>" + q(e)).c_str());
    ASSERT_TRUE(WIFEXITED(st));
    EXPECT_EQ(WEXITSTATUS(st), 3) << args;
    EXPECT_NE(slurp(e).find("error: cannot write to standard output"), std::string::npos) << slurp(e);
    EXPECT_EQ(std::system((std::string("'") + PIERRE_BINARY + "' " + args + " >/dev/null").c_str()), 0) << args;
    // They write no result files, and do not say they did.
    EXPECT_EQ(slurp(e).find("result files"), std::string::npos) << slurp(e);
  }
  const fs::path e = dir_ / "stderr.txt";
  const int st = std::system((std::string("'") + PIERRE_BINARY + "' validate " + kData +
                              "pass.toml >/dev/full 2>" + q(e)).c_str());
  ASSERT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 3);
  EXPECT_EQ(slurp(e), "error: cannot write to standard output: No space left on device\n");
}

TEST_F(Check, RunExitsZeroWhateverTheChecksSay) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("run " + kData + "fail.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("energy.mel"), std::string::npos);  // printed after the run table
  EXPECT_LT(r.out.find("Observation lines"), r.out.find("Checks"));
  EXPECT_EQ(check(summary(out), "energy.mel")["status"], "FAIL");
}

// A scenario with nothing to check: exit 0, said in words, and the summary's check keys are
// there (empty) for a script to read.
TEST_F(Check, NothingToCheckSaysSoAndExitsZero) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " PIERRE_TEST_DATA "/small/scenario.toml --quiet --out '" +
                          out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Nothing to check"), std::string::npos) << r.out;
  EXPECT_NE(r.out.front(), '\n') << "--quiet output starts with an empty line:\n" << r.out;
  const auto j = summary(out);
  EXPECT_TRUE(j["checks"].empty());
  EXPECT_EQ(j["checks_failed"], false);
}

// `check --quiet` prints only the tables and the check lines: its output starts with the first
// of them, not an empty line (one led every block, meant to follow the run's table).
TEST_F(Check, QuietOutputStartsWithContent) {
  for (const char* scenario : {"pass.toml", "design.toml"}) {
    const fs::path out = dir_ / scenario;
    const Result r = pierre("check " + kData + scenario + " --quiet --out '" + out.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    ASSERT_FALSE(r.out.empty());
    EXPECT_NE(r.out.front(), '\n') << scenario << ":\n" << r.out;
    EXPECT_EQ(r.out.find("\n\n\n"), std::string::npos) << r.out;  // one blank line between blocks
  }
}

// The exceedance lines' value and limit are in % with the unit "%", as their reasons word them
// ("0.00524 % <= acceptable 1 %"): before, 5.243e-05 and 0.01 stood beside an empty unit. The
// value is the barrier's P(E > MEL_req) and P(h > h_i) (fractions in its Table 4.2) times 100.
TEST_F(Check, ExceedanceLinesAreInPercentLikeTheirReasons) {
  const fs::path scenario = dir_ / "exceedance.toml", out = dir_ / "out";
  write_variant("pass.toml",
                {{"free_board_diameter = 1.0\n",
                  "free_board_diameter = 1.0\nacceptable_energy_exceedance = 0.5\n"
                  "acceptable_height_exceedance = 0.25\n"}},
                scenario);
  const Result r = pierre("check '" + scenario.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const auto j = summary(out);
  const auto& table = j["barriers"][0]["exceedance"];
  for (const auto& [id, what, acceptable] :
       {std::tuple{"exceedance.energy", "P(E > MEL_req)", 0.5},
        std::tuple{"exceedance.height", "P(h > h_i)", 0.25}}) {
    const auto& c = check(j, id);
    EXPECT_EQ(c["unit"], "%") << c;
    EXPECT_DOUBLE_EQ(c["limit"].get<double>(), 100 * acceptable) << c;
    double p = -1;
    for (const auto& row : table)
      if (row["what"] == what) {
        p = row["simulated_weibull"].get<double>();
        // The table's probabilities are fractions; its unit is the threshold's (a new user read
        // "unit": "kJ" beside 3.4e-05 as the probability's).
        EXPECT_EQ(row["probability_unit"], "fraction (0 to 1)") << row;
        EXPECT_EQ(row["threshold_unit"], std::string(what).find("E >") != std::string::npos ? "kJ" : "m")
            << row;
      }
    ASSERT_GE(p, 0.0) << what << " not in the barrier's exceedance table";
    EXPECT_DOUBLE_EQ(c["value"].get<double>(), 100 * p) << c;
    // The reason's first number is the value, in %.
    const std::string reason = c["reason"].get<std::string>();
    std::size_t used = 0;
    const double in_reason = std::stod(reason, &used);
    EXPECT_EQ(reason.substr(used, 2), " %") << reason;
    EXPECT_NEAR(in_reason, c["value"].get<double>(), 0.005 * c["value"].get<double>()) << reason;
    // The console's check table shows the unit.
    std::istringstream lines(r.out);
    bool shown = false;
    for (std::string l; std::getline(lines, l);)
      if (l.find(std::string(" ") + id + " ") != std::string::npos && l.find("Generous") == 0) {
        shown = true;
        EXPECT_NE(l.find(" % "), std::string::npos) << l;
      }
    EXPECT_TRUE(shown) << id << "\n" << r.out;
  }
}

TEST_F(Check, BadBarrierInputExitsTwoAndWritesNothing) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "bad.toml --out '" + out.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.toml:54: barriers[0].data_quality.trajectory"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\"back-analysed\" or \"literature\""), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(pierre("run " + kData + "bad.toml --out '" + out.string() + "'").code, 2);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Check, DesignWithoutCandidateHasOnlyAdvisoryLines) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "design.toml --out '" + out.string() + "' --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Checks"), std::string::npos);  // check lines printed even with --quiet
  EXPECT_EQ(r.out.find("Observation lines"), std::string::npos);
  const auto j = summary(out);
  std::set<std::string> ids;
  for (const auto& c : j["checks"]) ids.insert(c["id"].get<std::string>());
  EXPECT_EQ(ids, (std::set<std::string>{"fit.v", "fit.h", "fit.E", "sample.size", "reach"}));
  const auto& b = j["barriers"][0];
  EXPECT_EQ(b["mode"], "design");
  EXPECT_EQ(b["rules"]["name"], "peila-ronco-2009");  // the default
  EXPECT_TRUE(b["energy_class"]["class"].is_number_integer());
  // How it was chosen, as the report says: on MEL (peila-ronco-2009 designs on MEL).
  EXPECT_EQ(b["energy_class"]["how"].get<std::string>().rfind("the smallest class of the ", 0), 0u)
      << b["energy_class"]["how"];
  EXPECT_NE(b["energy_class"]["how"].get<std::string>().find("meeting MEL_req (the rule set designs on MEL"),
            std::string::npos)
      << b["energy_class"]["how"];
  EXPECT_NEAR(b["gamma_F"]["value"].get<double>(), 1.10 * 1.10, 1e-12);
  // The MEL test's elongation factor (rules/peila-ronco-2009.toml: 1.3); the SEL test's is not
  // checked by a MEL design.
  EXPECT_EQ(b["gamma_d_MEL"], 1.3);
  EXPECT_TRUE(b["gamma_d_SEL"].is_null());
}

// A barrier on a line that (almost) no block reaches has no design: its "reach" line WARNs (the
// spec's status for too few crossings, so `check` exits 0), and summary.json lists it under
// "barriers_without_design" with the line's own crossing count, so that a pipeline reading
// "barriers" alone is not left to think it was never asked for.
TEST_F(Check, BarrierWithoutDesignIsListedInTheSummary) {
  const fs::path scenario = dir_ / "far.toml", out = dir_ / "out";
  write_variant("design.toml", {{"x = 105.0", "x = 199.5"}}, scenario);  // 0.5 m from the end
  const Result r = pierre("check '" + scenario.string() + "' --out '" + out.string() + "' --quiet");
  const auto j = summary(out);
  ASSERT_EQ(j["lines"][1]["name"], "Road");
  const auto reached = j["lines"][1]["count"].get<std::uint64_t>();
  ASSERT_LT(reached, 2u) << "the test needs a line that fewer than two blocks reach";
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(check(j, "reach")["status"], "WARN");
  EXPECT_EQ(j["checks_failed"], false);
  EXPECT_TRUE(j["barriers"].empty());
  ASSERT_EQ(j["barriers_without_design"].size(), 1u);
  const auto& b = j["barriers_without_design"][0];
  EXPECT_EQ(b["name"], "Design");
  EXPECT_EQ(b["line"], "Road");
  EXPECT_EQ(b["chainage_m"], 199.5);
  // Its rule set recorded as a designed barrier's is (name, title, source, file read).
  EXPECT_EQ(b["rules"]["name"], "peila-ronco-2009");
  EXPECT_TRUE(fs::equivalent(b["rules"]["file"].get<std::string>(),
                             PIERRE_SOURCE_DIR "/rules/peila-ronco-2009.toml"))
      << b["rules"];
  EXPECT_NE(b["rules"]["source"].get<std::string>().find("Peila"), std::string::npos) << b["rules"];
  EXPECT_EQ(b["crossings"].get<std::uint64_t>(), reached);
  EXPECT_EQ(b["check_line"], "reach");
  EXPECT_NE(b["reason"].get<std::string>().find("fewer than two"), std::string::npos) << b["reason"];

  // The console's barrier table has its row too, with why there are no values.
  const Result shown = pierre("check '" + scenario.string() + "' --out '" + (dir_ / "out2").string() + "'");
  ASSERT_EQ(shown.code, 0) << shown.err;
  std::istringstream text(shown.out);
  std::string row;
  while (std::getline(text, row) && row.rfind("Barriers (ETAG 027", 0) != 0) {
  }
  ASSERT_TRUE(std::getline(text, row)) << shown.out;  // the column headings
  ASSERT_TRUE(std::getline(text, row)) << shown.out;
  EXPECT_EQ(row.rfind("Design ", 0), 0u) << row;
  EXPECT_NE(row.find(" Road "), std::string::npos) << row;
  EXPECT_NE(row.find("peila-ronco-2009"), std::string::npos) << row;
  EXPECT_NE(row.find("no design: " + b["reason"].get<std::string>()), std::string::npos) << row;
}

// A candidate on a line that no block reaches has nothing to be checked against: besides the
// advisory reach WARN it gets a FAIL line ("candidate"), so that `check` exits 1. Before, it
// said "0 FAIL" and exited 0, and a pipeline gating on the exit code passed a barrier nobody
// had compared with anything.
TEST_F(Check, ACandidateThatCouldNotBeCheckedFails) {
  const fs::path scenario = dir_ / "far.toml", out = dir_ / "out";
  write_variant("pass.toml", {{"line = \"Screen 1\"", "line = \"Road\""}, {"x = 105.0", "x = 199.5"}},
                scenario);
  const Result r = pierre("check '" + scenario.string() + "' --out '" + out.string() + "' --quiet");
  const auto j = summary(out);
  ASSERT_LT(j["lines"][1]["count"].get<std::uint64_t>(), 2u) << "the test needs a line no design comes from";
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_EQ(check(j, "reach")["status"], "WARN");
  const auto& c = check(j, "candidate");
  EXPECT_EQ(c["status"], "FAIL");
  EXPECT_EQ(c["subject"], "Generous");
  EXPECT_NE(c["reason"].get<std::string>().find("not checked: the line gave no design"), std::string::npos)
      << c["reason"];
  EXPECT_EQ(j["checks_failed"], true);
  EXPECT_NE(r.out.find("FAIL"), std::string::npos) << r.out;
}

// The barrier table marks each characteristic value W (the Weibull quantile) or E (the empirical
// percentile): a Weibull v_k below the line table's P95 is the fit's, not a slip. thesis-2015
// governs on the Weibull; peila-ronco-2009 on the larger of the two, whichever that is here.
TEST_F(Check, TheBarrierTableSaysWhichValueGoverns) {
  for (const std::string rules : {"thesis-2015", "peila-ronco-2009"}) {
    const fs::path file = dir_ / ("pass-" + rules + ".toml");
    write_variant("pass.toml",
                  {{"rules = \"thesis-2015\"",
                    "rules = \"" + rules + "\"" +
                        (rules == "thesis-2015"
                             ? ""  // it asks no data-quality questions; Peila-Ronco does
                             : "\ndata_quality = { trajectory = \"back-analysed\", topography "
                               "= \"low\", block_volume = \"surveyed\" }")}},
                  file);
    const fs::path out = dir_ / ("out-" + rules);
    const Result r = pierre("run '" + file.string() + "' --out '" + out.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const auto j = summary(out);
    const auto& b = j["barriers"][0];
    std::istringstream text(r.out);
    std::string row;
    while (std::getline(text, row) && row.rfind("Generous ", 0) != 0) {
    }
    ASSERT_EQ(row.rfind("Generous ", 0), 0u) << r.out;
    for (const char* key : {"v_k_m_s", "h_k_m"}) {
      const double w = b[key]["weibull"], e = b[key]["empirical"], v = b[key]["value"];
      ASSERT_NE(w, e) << key;  // else the mark says nothing
      const bool weibull = rules == "thesis-2015" || w > e;
      EXPECT_EQ(v, weibull ? w : e) << rules << " " << key;
      const std::string cell = fmt::format("{:.2f} {}", v, weibull ? "W" : "E");  // m/s, m
      EXPECT_NE(row.find(" " + cell + " "), std::string::npos) << rules << ": " << cell << "\n" << row;
    }
    EXPECT_NE(r.out.find("v_k, h_k: W the Weibull quantile, E the empirical percentile"),
              std::string::npos);
  }
}

// design-checks.md §1 step 1: the energy a barrier is designed on is the translational energy
// ½ m v² of each first crossing, with the block's own mass (not the rotational energy, nor their
// sum). Recomputed here from crossings.csv (mass and speed, 9 significant digits): the mean over
// the barrier's line equals the mean of the design's energy sample. (Feeding the barrier the
// rotational energies passed every test.)
TEST_F(Check, TheBarrierEnergySampleIsHalfMVSquaredOfTheCrossings) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "pass.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const auto j = summary(out);
  const auto& b = j["barriers"][0];
  const std::string line = b["line"].get<std::string>();
  std::istringstream csv(slurp(out / "crossings.csv"));
  std::string row;
  std::getline(csv, row);  // the header: trajectory,line,chainage_m,block_id,mass_kg,time_s,
                           // direction,vx_m_s,vz_m_s,speed_m_s,...
  ASSERT_EQ(row.rfind("trajectory,line,chainage_m,block_id,mass_kg,time_s,direction,vx_m_s,vz_m_s,speed_m_s,", 0), 0u) << row;
  double sum = 0;
  std::size_t n = 0;
  while (std::getline(csv, row)) {
    std::vector<std::string> f;
    std::stringstream ss(row);
    for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
    ASSERT_GE(f.size(), 10u) << row;
    if (f[1] != line) continue;
    const double mass = std::stod(f[4]), speed = std::stod(f[9]);
    sum += 0.5 * mass * speed * speed / 1000.0;
    ++n;
  }
  ASSERT_EQ(n, b["crossings"].get<std::size_t>());
  ASSERT_GT(n, 100u);
  const double mean = b["fits"]["translational_energy_kJ"]["mean"].get<double>();
  EXPECT_NEAR(mean, sum / static_cast<double>(n), 1e-7 * mean);
}

TEST_F(Check, SameSeedSameChecks) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(pierre("check " + kData + "pass.toml --out '" + a.string() + "' -q --threads 1").code, 0);
  ASSERT_EQ(pierre("check " + kData + "pass.toml --out '" + b.string() + "' -q --threads 3").code, 0);
  auto ja = summary(a), jb = summary(b);
  ja.erase("threads");
  jb.erase("threads");
  EXPECT_EQ(ja["barriers"], jb["barriers"]);
  EXPECT_EQ(ja["checks"], jb["checks"]);
}

// A rules folder of one's own (--rules, or $PIERRE_RULES) that lacks a file the scenario needs:
// the error names the rule file's line of `classes = ` (it named no line), and says where the
// folder came from, as the report layout's message names $PIERRE_TEMPLATES.
TEST_F(Check, AFileTheRulesFolderLacksIsSaidWithItsLineAndTheFoldersOrigin) {
  const fs::path rules = dir_ / "rules";
  fs::create_directories(rules);
  for (const char* f : {"materials.toml", "thesis-2015.toml"})
    fs::copy_file(fs::path(PIERRE_SOURCE_DIR) / "rules" / f, rules / f);
  // The line of `classes =` in the copied rule set, read from it.
  long classes_line = 0;
  {
    std::ifstream in(rules / "thesis-2015.toml");
    std::string text;
    for (long n = 1; std::getline(in, text) && !classes_line; ++n)
      if (text.rfind("classes =", 0) == 0) classes_line = n;
  }
  ASSERT_GT(classes_line, 0);
  // Refused by validate, run and check with the folder given by --rules (nothing written), and
  // by validate with $PIERRE_RULES: `message` then ends with how the folder was chosen.
  auto said = [&](const fs::path& folder, const std::string& message, const std::string& more) {
    const std::string by_option = message + " (the rules folder given by --rules" + more + ")\n";
    const Result v = pierre("validate " + kData + "pass.toml --rules " + q(folder));
    EXPECT_EQ(v.code, 2) << v.err;
    EXPECT_EQ(v.err, by_option);
    expect_refused_before_writing(kData + "pass.toml", "--rules " + q(folder), by_option);
    const Result env = pierre_with_env("PIERRE_RULES=" + q(folder), "validate " + kData + "pass.toml");
    EXPECT_EQ(env.code, 2) << env.err;
    EXPECT_EQ(env.err, message + " (the rules folder given by $PIERRE_RULES" + more + ")\n");
  };
  said(rules,
       (rules / "thesis-2015.toml").string() + ":" + std::to_string(classes_line) +
           ": rule_set.classes: found \"etag027-classes\", expected an energy class table "
           "etag027-classes.toml beside the rule set or in " + rules.string(),
       "");
  const fs::path none = dir_ / "nonexistent";
  said(none,
       (none / "materials.toml").string() +
           ": file: found no such file, expected a readable materials file (TOML) in " +
           none.string(),
       "; no such folder");
}

TEST_F(Check, HelpShowsTheExitCodes) {
  const Result r = pierre("check --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("1 when one FAILs"), std::string::npos) << r.out;
  for (const char* cmd : {"check --help", "run --help"})
    EXPECT_NE(pierre(cmd).out.find("130 when interrupted"), std::string::npos) << cmd;
}

// validate says what each barrier's design will stand on besides the crossings: the design
// block and D_f. design.toml: blocks of 500 kg and 1.2 m³ at 2650 kg/m³, the default rule (the
// largest), no D_f (the mean equivalent diameter: 0.7116 and 1.3184 m by hand).
TEST_F(Check, ValidateSaysTheDesignBlockAndFreeBoardDiameter) {
  const Result v = pierre("validate " + kData + "design.toml");
  EXPECT_EQ(v.code, 0) << v.err;
  EXPECT_NE(v.out.find("a design (no candidate); design block 1.2 m³ × 2650 kg/m³ = 3180 kg (the "
                       "largest block thrown, by mass; density the heaviest block's), D_f = 1.015 m (the "
                       "mean equivalent diameter of the blocks thrown)\n"),
            std::string::npos)
      << v.out;
  const Result given = pierre("validate " + kData + "pass.toml");
  EXPECT_NE(given.out.find("design block 1 m³ × 2650 kg/m³ = 2650 kg (the design block, given; "
                           "density given with the design block), D_f = 1 m (given)"),
            std::string::npos)
      << given.out;
}

// A design's notes reach the console as well as the report and summary.json: here observed
// values at the line, three speeds and three heights, fewer than the 30 crossings thesis-2015
// asks of a simulated line.
TEST_F(Check, ADesignsNotesAreOnTheConsole) {
  write_variant("pass.toml",
                {{"free_board_diameter = 1.0\n", "free_board_diameter = 1.0\nobserved = \"obs.csv\"\n"}},
                dir_ / "s.toml");
  std::ofstream(dir_ / "obs.csv") << "speed_m_s,height_m\n10,1\n12,\n,2\n15,3\n";
  const Result r = pierre("run '" + (dir_ / "s.toml").string() + "' --out '" + (dir_ / "o").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = summary(dir_ / "o");
  ASSERT_EQ(j["barriers"][0]["notes"].size(), 1u) << j["barriers"][0]["notes"].dump();
  const std::string note = j["barriers"][0]["notes"][0];
  EXPECT_EQ(note.rfind("the observed Weibull fits rest on few values (3 speeds, 3 passing heights;", 0), 0u)
      << note;
  // Wrapped before 100 columns: compare word by word.
  const auto at = r.out.find("Note: Generous: ");
  ASSERT_NE(at, std::string::npos) << r.out;
  std::istringstream words(r.out.substr(at + 16, note.size() * 2)), expected(note);
  for (std::string w, e; expected >> e;) {
    ASSERT_TRUE(words >> w) << r.out;
    EXPECT_EQ(w, e);
  }
}

}  // namespace

TEST_F(Check, WritesTheDesignReportWithABarrierSheetAndItsCharts) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "fail.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 1) << r.err << r.out;
  ASSERT_TRUE(fs::is_regular_file(out / "report.xlsx"));
  PIERRE_NEED_PROGRAM("unzip");
  const std::string parts = zip_listing(out / "report.xlsx");
  ASSERT_FALSE(parts.empty()) << "unzip lists nothing: report.xlsx is not a zip";
  // Summary, Inputs, Blocks, Profile, Trajectories, Crossings and one sheet for the one barrier.
  EXPECT_EQ(count_of(parts, "xl/worksheets/sheet"), 7u) << parts;
  // Six charts on the barrier sheet (3 histograms, 3 CDFs) and the profile.
  EXPECT_EQ(count_of(parts, "xl/charts/chart"), 7u) << parts;
}
