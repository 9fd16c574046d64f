// The real `pierre` binary: exit codes, files written, CSV headers, row counts, summary.json,
// nothing written on bad input, --help examples, usage errors, reproducibility across runs and
// thread counts.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <map>
#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "pierre/model/model_defaults.hpp"

#include "support/cli_fixture.hpp"
#include "support/tools.hpp"
#include "support/workbook_reader.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kScenario = PIERRE_TEST_DATA "/small/scenario.toml";

using Result = pierre::test::CliResult;
using pierre::test::slurp;

class Cli : public pierre::test::PierreCli {};

std::size_t count_lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

// A scenario of one block (seed 1) from one source, with the parts the tests vary: the
// [profile] table's body, the material's name and body, the block's mass and the source's body.
struct OneBlock {
  std::string name;
  int throws;
  std::string profile, material, material_body;
  double mass;
  std::string source;
};
std::string one_block_scenario(const OneBlock& b) {
  return fmt::format(
      "[scenario]\nname = \"{}\"\n[simulation]\nseed = 1\nthrows = {}\n[profile]\n{}\n"
      "[materials.{}]\n{}\n[blocks]\n[[blocks.table]]\nmass = {:.1f}\n[[sources]]\n{}\n",
      b.name, b.throws, b.profile, b.material, b.material_body, b.mass, b.source);
}

TEST_F(Cli, RunWritesTheResults) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("run " + kScenario + " --out " + q(out) + " --threads 2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;  // stderr is not a terminal: no progress bar
  for (const char* f : {"trajectories.csv", "crossings.csv", "summary.json", "report.xlsx"})
    EXPECT_TRUE(fs::is_regular_file(out / f)) << f;
  EXPECT_FALSE(fs::exists(out / "impacts.csv"));
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    ++entries;
    EXPECT_EQ(e.path().filename().string().rfind(".pierre-partial", 0), std::string::npos);
  }
  EXPECT_EQ(entries, 4u);  // no staging folder left

  const std::string traj = slurp(out / "trajectories.csv");
  EXPECT_EQ(first_line(traj),
            "trajectory,source,block_id,throw,mass_kg,start_x_m,start_z_m,stop_x_m,stop_z_m,"
            "runout_m,stop_reason,duration_s,impacts,first_impact_x_m,first_impact_z_m,"
            "max_jump_height_m,max_speed_m_s,max_energy_kJ");
  EXPECT_EQ(count_lines(traj), 1u + 600u);  // header + 2 blocks × 300 throws
  const std::string cross = slurp(out / "crossings.csv");
  EXPECT_EQ(first_line(cross),
            "trajectory,line,chainage_m,block_id,mass_kg,time_s,direction,vx_m_s,vz_m_s,"
            "speed_m_s,omega_rad_s,translational_energy_kJ,rotational_energy_kJ,"
            "passing_height_m,sliding");
  EXPECT_GT(count_lines(cross), 100u);

  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(j["trajectories"], 600);
  EXPECT_EQ(j["seed"], 12345);
  EXPECT_EQ(j["throws"], 300);
  EXPECT_EQ(j["scenario"]["name"], "Small talus test");
  EXPECT_EQ(j["input_notes"], nlohmann::json::array());  // present, and empty: nothing noted
  ASSERT_EQ(j["lines"].size(), 2u);
  EXPECT_EQ(j["lines"][0]["name"], "Screen 1");
  EXPECT_EQ(j["lines"][0]["count"].get<int>() + j["lines"][0]["not_reached"].get<int>(), 600);
  int stops = 0;
  for (const auto& [k, v] : j["stop_reasons"].items()) stops += v.get<int>();
  EXPECT_EQ(stops, 600);
  EXPECT_GT(j["runout_m"]["p95"].get<double>(), j["runout_m"]["p50"].get<double>());

  // The console table names the lines, the runout percentiles and the files written.
  EXPECT_NE(r.out.find("Screen 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("speed (m/s)"), std::string::npos);
  EXPECT_NE(r.out.find("P99"), std::string::npos);
  EXPECT_NE(r.out.find((out / "trajectories.csv").string()), std::string::npos);
}

// summary.json says the model as it ran: the material of a preset with one field overridden
// has the preset's other values as rules/materials.toml gives them (read here by toml++, not
// by pierre's reader), and [simulation] has the values the file set and the model defaults
// for the rest.
TEST_F(Cli, SummaryJsonEchoesTheModelAsItRan) {
  const fs::path scenario = dir_ / "s.toml";
  std::ofstream(scenario)
      << "[scenario]\nname = \"echo\"\n[simulation]\nseed = 3\nthrows = 2\ngravity = 9.80\n"
         "roughness_distribution = \"uniform\"\nstop_head_factor = 0.3\nsize_reduction = false\n"
         "[profile]\npoints = [[0.0, 30.0, \"slope\"], [40.0, 0.0, \"slope\"], [80.0, 0.0]]\n"
         "[materials.slope]\npreset = \"talus\"\nroughness = 0.72\n[blocks]\n"
         "[[blocks.table]]\nmass = 500.0\n[[sources]]\nname = \"top\"\nx = 1.0\nz = 31.0\n";
  const fs::path out = dir_ / "out";
  const Result r = pierre("run " + q(scenario) + " --out " + q(out) + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));

  const toml::table presets = toml::parse_file(PIERRE_SOURCE_DIR "/rules/materials.toml");
  const auto talus = [&](const char* key) { return presets["talus"][key].value<double>().value(); };
  ASSERT_EQ(j["materials"].size(), 1u);
  const auto& m = j["materials"][0];
  EXPECT_EQ(m["name"], "slope");
  EXPECT_DOUBLE_EQ(m["normal_energy_m3_s2"].get<double>(), talus("normal_energy"));
  EXPECT_DOUBLE_EQ(m["normal_energy_k"].get<double>(), talus("normal_energy_k"));
  EXPECT_DOUBLE_EQ(m["tangential_energy_m3_s2"].get<double>(), talus("tangential_energy"));
  EXPECT_DOUBLE_EQ(m["tangential_energy_k"].get<double>(), talus("tangential_energy_k"));
  EXPECT_DOUBLE_EQ(m["friction_angle_deg"].get<double>(), talus("friction_angle"));
  EXPECT_DOUBLE_EQ(m["roughness"].get<double>(), 0.72);  // the override, not the preset's
  ASSERT_NE(talus("roughness"), 0.72);
  EXPECT_NE(m["source"].get<std::string>().find("talus"), std::string::npos) << m;

  using D = pierre::model::ModelDefaults;
  const auto& sim = j["simulation"];
  EXPECT_DOUBLE_EQ(sim["gravity_m_s2"].get<double>(), 9.80);
  EXPECT_EQ(sim["roughness_distribution"], "uniform");
  EXPECT_DOUBLE_EQ(sim["stop_head_factor"].get<double>(), 0.3);
  EXPECT_EQ(sim["size_reduction"], false);
  EXPECT_DOUBLE_EQ(sim["max_time_s"].get<double>(), D::max_time);
  EXPECT_EQ(sim["max_impacts"].get<long>(), D::max_impacts);
  EXPECT_DOUBLE_EQ(sim["max_sliding_speed_m_s"].get<double>(), D::max_sliding_speed);
  EXPECT_DOUBLE_EQ(sim["roughness_mean"].get<double>(), D::roughness_mean);
  EXPECT_DOUBLE_EQ(sim["roughness_sd"].get<double>(), D::roughness_sd);
  EXPECT_DOUBLE_EQ(sim["size_reduction_b"].get<double>(), D::size_reduction_b);
  EXPECT_DOUBLE_EQ(sim["size_reduction_m_per_m"].get<double>(), D::size_reduction_m);
  EXPECT_DOUBLE_EQ(sim["size_reduction_floor"].get<double>(), D::size_reduction_floor);
}

// The run's time with three significant digits, in ms below a second: 600 trajectories take
// milliseconds, which "in 0.0 s" hid.
TEST_F(Cli, TheRunTimeIsShownToThreeSignificantDigits) {
  const Result r = pierre("run " + kScenario + " --out " + q(dir_ / "out"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string line = first_line(r.out);
  std::smatch m;
  ASSERT_TRUE(std::regex_match(line, m, std::regex(R"((\d+) trajectories in ([0-9.]+) (ms|s))")))
      << line;
  EXPECT_EQ(std::stoull(m[1].str()), 600u) << line;  // 2 blocks x 300 throws
  const double v = std::stod(m[2].str());
  EXPECT_GT(v, 0.0) << line;
  if (m[3].str() == "ms")
    EXPECT_LT(v, 1000.0) << line;
  else
    EXPECT_GE(v, 1.0) << line;
  std::string digits;
  for (char c : m[2].str())
    if (c != '.' && !(digits.empty() && c == '0')) digits += c;
  EXPECT_EQ(digits.size(), 3u) << line;  // significant digits
}

TEST_F(Cli, OptionsOverrideTheScenario) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("run " + kScenario + " --out " + q(out) +
                          " --throws 3 --seed 99 --quiet --impacts --all-crossings");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;  // --quiet
  EXPECT_EQ(count_lines(slurp(out / "trajectories.csv")), 1u + 6u);
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(j["seed"], 99);
  EXPECT_EQ(j["trajectories"], 6);
  // The echoed scenario text says seed = 12345 and throws = 300: what the command line set
  // instead is recorded, with the file's values, in summary.json and on the report's Summary.
  const std::string seed_note = "--seed 99 (the scenario file's simulation.seed: 12345)";
  const std::string throws_note = "--throws 3 (the scenario file's simulation.throws: 300)";
  EXPECT_EQ(j["command_line_overrides"], nlohmann::json::array({seed_note, throws_note}));
  EXPECT_EQ(j["impacts_csv"], true);
  EXPECT_EQ(j["all_crossings_in_csv"], true);
  const std::string imp = slurp(out / "impacts.csv");
  EXPECT_EQ(imp.rfind("trajectory,impact,time_s,x_m,z_m,segment,material,result,", 0), 0u);
  EXPECT_GT(count_lines(imp), 6u);

  // A second run without --impacts into the same folder removes the stale impacts.csv.
  ASSERT_EQ(pierre("run " + kScenario + " --out " + q(out) + " --throws 3 --quiet").code, 0);
  EXPECT_FALSE(fs::exists(out / "impacts.csv"));
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "summary.json"))["command_line_overrides"],
            nlohmann::json::array({throws_note}));
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "summary.json"))["impacts_csv"], false);
  PIERRE_NEED_PROGRAM("unzip");
  const std::string strings = pierre::test::zip_entry(out / "report.xlsx", "xl/sharedStrings.xml", dir_);
  EXPECT_NE(strings.find("Set on the command line"), std::string::npos);
  EXPECT_NE(strings.find("<t>" + throws_note + "</t>"),
            std::string::npos)
      << strings.substr(0, 3000);
  EXPECT_EQ(strings.find("--seed"), std::string::npos);
}

TEST_F(Cli, BadInputExitsTwoAndCreatesNothing) {
  std::string text = slurp(kScenario);
  text.replace(text.find("throws = 300"), 12, "throws = \"300\"");
  std::ofstream(dir_ / "bad.toml") << text;
  fs::copy_file(PIERRE_TEST_DATA "/small/profile.csv", dir_ / "profile.csv");
  const fs::path out = dir_ / "out";
  const Result r = pierre("run " + q(dir_ / "bad.toml") + " --out " + q(out));
  EXPECT_EQ(r.code, 2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(r.err.find((dir_ / "bad.toml").string() + ":9: simulation.throws: found \"300\", expected"),
            std::string::npos)
      << r.err;

  // An existing output folder is left as it was.
  fs::create_directories(out);
  EXPECT_EQ(pierre("run " + q(dir_ / "bad.toml") + " --out " + q(out)).code, 2);
  EXPECT_TRUE(fs::is_empty(out));

  const Result v = pierre("validate " + q(dir_ / "bad.toml"));
  EXPECT_EQ(v.code, 2);
  EXPECT_NE(v.err.find("simulation.throws"), std::string::npos);
}

// A run never replaces a file it read (new-user review: a profile CSV named crossings.csv, with
// --out at the scenario's folder, was overwritten by the run that had just read it, exit 0),
// and never removes a file by a result's name that pierre did not write (a user's impacts.csv
// was deleted by a run without --impacts).
TEST_F(Cli, AResultNeverReplacesAnInputOrRemovesAFileOfTheUsers) {
  std::string text = slurp(kScenario);
  text.replace(text.find("\"profile.csv\""), 13, "\"crossings.csv\"");
  std::ofstream(dir_ / "scenario.toml") << text;
  fs::copy_file(PIERRE_TEST_DATA "/small/profile.csv", dir_ / "crossings.csv");
  const std::string profile = slurp(dir_ / "crossings.csv");
  const Result r = pierre("run " + q(dir_ / "scenario.toml") + " --out " + q(dir_) + " --throws 1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--out: found " + dir_.string() + ", where the result crossings.csv would "
                       "replace " + (dir_ / "crossings.csv").string() + ", an input of this run"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(slurp(dir_ / "crossings.csv"), profile);
  for (const auto& e : fs::directory_iterator(dir_)) {  // nothing written but the test's own
    const std::string n = e.path().filename().string();
    EXPECT_TRUE(n == "scenario.toml" || n == "crossings.csv" || n == "stdout.txt" ||
                n == "stderr.txt")
        << n;
  }
  // The same folder reached by another path, and `check`.
  const fs::path other = dir_ / "sub" / "..";
  fs::create_directories(dir_ / "sub");
  EXPECT_EQ(pierre("check " + q(dir_ / "scenario.toml") + " --out " + q(other) + " --throws 1").code, 2);
  EXPECT_EQ(slurp(dir_ / "crossings.csv"), profile);

  // The profile by its own name: the run goes ahead; a field record called impacts.csv stays.
  fs::rename(dir_ / "crossings.csv", dir_ / "profile.csv");
  std::ofstream(dir_ / "scenario.toml") << slurp(kScenario);
  const std::string mine = "my field survey of impacts\nx,z\n1,2\n";
  std::ofstream(dir_ / "impacts.csv") << mine;
  const Result ok = pierre("run " + q(dir_ / "scenario.toml") + " --out " + q(dir_) + " --throws 1 -q");
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_EQ(slurp(dir_ / "impacts.csv"), mine);
  EXPECT_NE(ok.err.find("Note: " + (dir_ / "impacts.csv").string() + " is left as it is: pierre did "
                        "not write it"),
            std::string::npos)
      << ok.err;
  // pierre's own impacts.csv is still taken away by a later run without --impacts.
  ASSERT_EQ(pierre("run " + q(dir_ / "scenario.toml") + " --out " + q(dir_ / "o") + " --throws 1 -q --impacts").code, 0);
  ASSERT_TRUE(fs::exists(dir_ / "o" / "impacts.csv"));
  const Result again = pierre("run " + q(dir_ / "scenario.toml") + " --out " + q(dir_ / "o") + " --throws 1 -q");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_FALSE(fs::exists(dir_ / "o" / "impacts.csv"));
  EXPECT_EQ(again.err.find("Note:"), std::string::npos) << again.err;
}

// --throws is held to the reader's limit of 2^53 trajectories (simulation.throws is). It was
// not: 4400 sources × 1e6 blocks × 4294967295 throws wrapped past 2^64 and the run ended in an
// "internal error" (exit 3); a count between 2^53 and 2^64 started a run of that many.
TEST_F(Cli, ThrowsOptionIsHeldToTheTrajectoryLimitBeforeAnythingIsWritten) {
  std::string text =
      "[scenario]\nname = \"many\"\n[simulation]\nseed = 1\nthrows = 1\n[profile]\n"
      "file = \"profile.csv\"\n[materials.talus]\npreset = \"talus\"\n[materials.road]\n"
      "preset = \"talus\"\n[blocks]\n[[blocks.table]]\nmass = 500.0\ncount = 1000000\n";
  for (int i = 0; i < 4400; ++i) text += "[[sources]]\nx = 5.0\nz = 67.5\n";
  std::ofstream(dir_ / "many.toml") << text;
  fs::copy_file(PIERRE_TEST_DATA "/small/profile.csv", dir_ / "profile.csv");
  ASSERT_EQ(pierre("validate " + q(dir_ / "many.toml")).code, 0);  // 4.4e9 trajectories
  expect_refused_before_writing(
      dir_ / "many.toml", "--throws 4294967295",
      (dir_ / "many.toml").string() +
          ": --throws: found 4294967295, expected at most 2^53 trajectories in all "
          "(4400 sources × 1000000 blocks × 4294967295 throws are 1.89e+19)");
}

// A count this machine cannot hold (each trajectory keeps at least its runout, 8 bytes, for the
// percentiles) is refused before the run, not after hours of running: a throws with zeros too
// many, in the file or on the command line. The file itself is valid (another machine may run
// it): validate notes it, and --throws brings the run within reach.
TEST_F(Cli, AThrowsThisMachineCannotHoldIsRefusedBeforeTheRun) {
  // This machine's RAM, as the program reads it (sysconf).
  const std::optional<double> memory =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  ASSERT_GT(*memory, 0);
  // 1000 blocks from one source: the throws that ask for just more than memory / 8 trajectories.
  const auto throws = static_cast<std::uint64_t>(std::ceil(*memory / 8 / 1000)) + 1;
  if (throws > 4294967295u) GTEST_SKIP() << "a machine of more than 34 TB";
  const std::string head =
      "[scenario]\nname = \"many\"\n[simulation]\nseed = 1\nthrows = ";
  const std::string rest =
      "\n[profile]\nfile = \"profile.csv\"\n[materials.talus]\npreset = \"talus\"\n"
      "[materials.road]\npreset = \"talus\"\n[blocks]\n[[blocks.table]]\nmass = 500.0\n"
      "count = 1000\n[[sources]]\nx = 5.0\nz = 67.5\n";
  fs::copy_file(PIERRE_TEST_DATA "/small/profile.csv", dir_ / "profile.csv");
  std::ofstream(dir_ / "few.toml") << head + "1" + rest;
  std::ofstream(dir_ / "many.toml") << head + std::to_string(throws) + rest;
  const std::string expected = fmt::format(
      "expected fewer than {:.3g} trajectories, the most this machine's {:.1f} GB of memory could "
      "hold even at the 8 bytes the statistics keep of each at the least (its runout; a run keeps "
      "more) (1 sources × 1000 blocks × {} throws are {:.3g})",
      *memory / 8, *memory / 1e9, throws, throws * 1000.0);
  const Result v = pierre("validate " + q(dir_ / "many.toml"));
  EXPECT_EQ(v.code, 0) << v.err;
  EXPECT_NE(v.out.find("Note: " + (dir_ / "many.toml").string() + ":5: simulation.throws: found " +
                       std::to_string(throws) + ", " + expected + " (pierre run refuses it on this machine)\n"),
            std::string::npos)
      << v.out;
  // validate --strict refuses what run would (new-user review: a CI pre-check passed it).
  const Result vs = pierre("validate --strict " + q(dir_ / "many.toml"));
  EXPECT_EQ(vs.code, 2);
  EXPECT_NE(vs.err.find((dir_ / "many.toml").string() + ":5: simulation.throws: found " +
                        std::to_string(throws) + ", " + expected),
            std::string::npos)
      << vs.err;
  EXPECT_EQ(pierre("validate --strict " + q(dir_ / "few.toml")).code, 0);
  expect_refused_before_writing(dir_ / "many.toml", "",
                                (dir_ / "many.toml").string() + ":5: simulation.throws: found " +
                                    std::to_string(throws) + ", " + expected);
  expect_refused_before_writing(dir_ / "few.toml", "--throws " + std::to_string(throws),
                                (dir_ / "few.toml").string() + ": --throws: found " +
                                    std::to_string(throws) + ", " + expected);
  // Between the least (8 bytes) and the likely need (here 16 bytes: the runout and its growth;
  // no lines), validate says the run may run out of memory; run would go ahead.
  const auto likely = static_cast<std::uint64_t>(std::ceil(*memory / 16 / 1000)) + 1;
  std::ofstream(dir_ / "likely.toml") << head + std::to_string(likely) + rest;
  const Result lv = pierre("validate " + q(dir_ / "likely.toml"));
  EXPECT_EQ(lv.code, 0) << lv.err;
  EXPECT_NE(lv.out.find(fmt::format("Note: {} trajectories may need about {:.1f} GB of memory",
                                    likely * 1000, likely * 1000 * 16.0 / 1e9)),
            std::string::npos)
      << lv.out;
  EXPECT_NE(lv.out.find("if the run runs out of memory, lower simulation.throws\n"), std::string::npos) << lv.out;
  // The file's count is no fault once --throws lowers it.
  const Result lowered = pierre("run " + q(dir_ / "many.toml") + " --throws 1 -q --out " + q(dir_ / "o"));
  EXPECT_EQ(lowered.code, 0) << lowered.err;
  EXPECT_EQ(summary(dir_ / "o")["trajectories"], 1000);
}

// A run that runs out of memory all the same (here under a limit on the address space) says so,
// with how far it got and the throws to lower, exits 2 and leaves nothing behind. It was an
// "internal error: writing the results failed: std::bad_alloc" (exit 3).
TEST_F(Cli, ARunOutOfMemoryExitsTwoNamingTheThrows) {
  const fs::path out = dir_ / "out";
  // The program runs the test scenario in under 40 MB of address space here (measured); 60 MB
  // hold some 3·10⁵ of its trajectories (each keeps ~70 bytes for its lines and runout, more while
  // a vector grows), not 2·10⁶. One thread: each thread's malloc arena reserves 64 MB of its own.
  // A build that needs more (sanitizers, another libc) cannot show it under this limit.
  const std::string limit = "ulimit -v 60000;";
  if (pierre_with_env(limit, "run " + kScenario + " --quiet --threads 1 --out " + q(dir_ / "small")).code != 0)
    GTEST_SKIP() << "this build does not run the test scenario in 60 MB of address space";
  const Result r = pierre_with_env(
      limit, "run " + kScenario + " --quiet --threads 1 --throws 1000000 --out " + q(out));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("error: out of memory after about "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" of 2000000 trajectories; nothing was written to " + out.string() +
                       ". A run keeps every trajectory's runout"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("run fewer trajectories, lowering --throws 1000000\n"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, MissingScenarioExitsTwo) {
  const Result r = pierre("run " + q(dir_ / "none.toml") + " --out " + q(dir_ / "out"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(Cli, ValidatePrintsASummary) {
  const Result r = pierre("validate " + kScenario);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("valid"), std::string::npos);
  EXPECT_NE(r.out.find("5 vertices"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 materials"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("600 trajectories"), std::string::npos) << r.out;
  // The masses, where a unit slip shows: 500 kg given, and 1.2 m³ × 2650 kg/m³ = 3180 kg.
  EXPECT_NE(r.out.find("\n  2 blocks from 2 rows: 500 to 3180 kg, density 2650 kg/m³\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("Note:"), std::string::npos) << r.out;
}

// A profile listed from the toe end: valid, but its blocks travel against the vertex order and
// no line would count them. validate and run say so at the source's table (run on stderr),
// and summary.json keeps it.
TEST_F(Cli, AProfileListedFromTheToeEndIsNoted) {
  std::ofstream(dir_ / "p.csv") << "x,z,material\n0,38,t\n100,40,t\n150,70,t\n200,100,\n";
  std::ofstream(dir_ / "s.toml") << one_block_scenario(
      {"from the toe", 2, "file = \"p.csv\"", "t", "preset = \"talus\"", 1000,
       "name = \"crest\"\nx = 199.0\nz = 101.0"});
  const std::string note =
      "Note: " + (dir_ / "s.toml").string() +
      ":13: sources[0]: the ground under source \"crest\" (x = 199 m) falls towards the "
      "profile's first vertex, so its blocks travel against the vertex order, in which "
      "observation lines count first crossings. List the profile's vertices from the source end, "
      "with x mirrored to rise downhill (x' = 200 - x, for the sources and observation lines "
      "too). If it is meant, confirm it in the scenario: [confirmed] \"sources[0].x\" = 199\n";
  const Result v = pierre("validate " + q(dir_ / "s.toml"));
  EXPECT_EQ(v.code, 0) << v.err;
  EXPECT_NE(v.out.find(note), std::string::npos) << v.out;
  const Result r = pierre("run " + q(dir_ / "s.toml") + " --out " + q(dir_ / "o"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find(note), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find(note), std::string::npos) << r.out;
  const Result quiet = pierre("run " + q(dir_ / "s.toml") + " -q --out " + q(dir_ / "o"));
  EXPECT_TRUE(quiet.out.empty()) << quiet.out;
  EXPECT_NE(quiet.err.find(note), std::string::npos) << quiet.err;
  const auto j = nlohmann::json::parse(slurp(dir_ / "o" / "summary.json"));
  ASSERT_EQ(j["input_notes"].size(), 1u) << j["input_notes"].dump();
  EXPECT_EQ(j["input_notes"][0]["field"], "sources[0]");
  EXPECT_EQ(j["input_notes"][0]["line"], 13);
  // A likely slip that every result rests on (no crossing counted, distances from the wrong
  // end): --strict refuses it, unless confirmed (new-user review: it doubted nothing, and a
  // barrier on such a profile got no design while `check --strict` exited 0).
  EXPECT_EQ(j["input_notes"][0]["in_doubt"], true);
  EXPECT_EQ(pierre("validate --strict " + q(dir_ / "s.toml")).code, 2);
  // validate's first line says so, for a reader who stops at "valid".
  EXPECT_NE(v.out.find(": valid, 1 input in doubt (see the notes below).\n"), std::string::npos) << v.out;
  std::ofstream(dir_ / "s.toml", std::ios::app) << "[confirmed]\n\"sources[0].x\" = 199.0\n";
  EXPECT_EQ(pierre("validate --strict " + q(dir_ / "s.toml")).code, 0);
  EXPECT_NE(pierre("validate " + q(dir_ / "s.toml")).out.find(": valid.\n"), std::string::npos);
}

// The reader's notes (a profile x out of order read as an overhang, a source far above the
// ground): validate and run print them with file, line and field and still exit 0; validate
// with its verdict on stdout, run on stderr, quiet or not, where a pipeline's log keeps them
// (they went to stdout unless --quiet: a wrapper watching stderr missed them). A quarry
// scenario too.
TEST_F(Cli, TheReadersNotesAreSaidByValidateAndRun) {
  std::ofstream(dir_ / "p.csv") << "x,z,material\n0,130,t\n30,122,t\n20,106,t\n150,40,t\n200,38,\n";
  std::ofstream(dir_ / "s.toml") << one_block_scenario(
      {"typos", 2, "file = \"p.csv\"", "t", "preset = \"talus\"", 1000,
       "name = \"crest\"\nx = 1.0\nz = 5000.0"});
  const std::string overhang =
      "Note: " + (dir_ / "p.csv").string() +
      ":4: x: profile segment 1 (line 3 → line 4, x 30 → 20 m) runs back in x: it is read as an "
      "overhang (the air below it); check the x values if the slope has none\n";
  const std::string high = "Note: " + (dir_ / "s.toml").string() +
                           ":16: sources[0].z: source \"crest\" is 4870 m above the ground under it";
  const Result v = pierre("validate " + q(dir_ / "s.toml"));
  EXPECT_EQ(v.code, 0) << v.err;
  EXPECT_NE(v.out.find(overhang), std::string::npos) << v.out;
  EXPECT_NE(v.out.find(high), std::string::npos) << v.out;
  const Result r = pierre("run " + q(dir_ / "s.toml") + " --out " + q(dir_ / "o"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find(overhang), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(high), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("Note: " + (dir_ / "p.csv").string()), std::string::npos) << r.out;
  const Result quiet = pierre("run " + q(dir_ / "s.toml") + " -q --out " + q(dir_ / "o"));
  EXPECT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_TRUE(quiet.out.empty()) << quiet.out;
  EXPECT_NE(quiet.err.find(overhang), std::string::npos) << quiet.err;
  EXPECT_NE(quiet.err.find(high), std::string::npos) << quiet.err;
  // The notes are kept in summary.json too, for a pipeline that reads only that file.
  const auto j = nlohmann::json::parse(slurp(dir_ / "o" / "summary.json"));
  ASSERT_EQ(j["input_notes"].size(), 2u) << j["input_notes"].dump();
  EXPECT_EQ(j["input_notes"][0]["file"], (dir_ / "p.csv").string());
  EXPECT_EQ(j["input_notes"][0]["line"], 4);
  EXPECT_EQ(j["input_notes"][0]["field"], "x");
  EXPECT_EQ("Note: " + (dir_ / "p.csv").string() + ":4: x: " +
                j["input_notes"][0]["note"].get<std::string>() + "\n",
            overhang);
  EXPECT_EQ(j["input_notes"][1]["field"], "sources[0].z");
  EXPECT_EQ(j["input_notes"][1]["line"], 16);

  std::ofstream(dir_ / "pit.toml")
      << "[scenario]\nname = \"pit\"\n[simulation]\nseed = 1\nthrows = 1\n"
         "[materials.face]\npreset = \"quarry-face\"\n[[quarries]]\nname = \"East\"\n"
         "profile = { points = [[0.0, 20.0, \"face\"], [10.0, 20.0, \"face\"], [20.0, 0.0, "
         "\"face\"], [90.0, 0.0, \"\"]] }\nblocks = { table = [{ id = \"A\", mass = 500.0 }] }\n"
         "sources = [{ x = 10.3, z = 500.0 }]\n";
  const std::string pit_note = "Note: " + (dir_ / "pit.toml").string() +
                               ":12: quarries[0].sources[0].z: source \"S1\" is 481 m above";
  const Result pv = pierre("validate " + q(dir_ / "pit.toml"));
  EXPECT_EQ(pv.code, 0) << pv.err;
  EXPECT_NE(pv.out.find(pit_note), std::string::npos) << pv.out;
  const Result pq = pierre("run " + q(dir_ / "pit.toml") + " -q --out " + q(dir_ / "po"));
  EXPECT_EQ(pq.code, 0) << pq.err;
  EXPECT_NE(pq.err.find(pit_note), std::string::npos) << pq.err;
  const auto pj = nlohmann::json::parse(slurp(dir_ / "po" / "summary.json"));
  ASSERT_EQ(pj["input_notes"].size(), 1u) << pj["input_notes"].dump();
  EXPECT_EQ(pj["input_notes"][0]["field"], "quarries[0].sources[0].z");
}

// A source given in absolute elevations over a profile in local ones lands far inside the rock:
// placed on the ground, as the thesis has it, but noted at its z. A source a little inside the
// rock (a release point given roughly) is not.
TEST_F(Cli, ASourceFarBelowTheGroundIsNoted) {
  std::ofstream(dir_ / "s.toml") << one_block_scenario(
      {"deep", 2, "points = [[0.0, 100.0, \"t\"], [200.0, 0.0, \"\"]]", "t",
       "preset = \"talus\"", 1000, "name = \"deep\"\nx = 50.0\nz = -300.0"});
  const Result v = pierre("validate " + q(dir_ / "s.toml"));
  EXPECT_EQ(v.code, 0) << v.err;
  // The ground at x = 50 m is at 75 m: 375 m above the source; the profile is 100 m high.
  EXPECT_NE(v.out.find("Note: " + (dir_ / "s.toml").string() +
                       ":16: sources[0].z: source \"deep\" is 375 m below the ground over it "
                       "(z = -300 m; the ground at x = 50 m is at 75.0 m), more than 100 m and "
                       "more than the profile's whole height (100.0 m, z from 0.0 to 100.0 m)"),
            std::string::npos)
      << v.out;
  std::ofstream(dir_ / "near.toml") << one_block_scenario(
      {"near", 2, "points = [[0.0, 100.0, \"t\"], [200.0, 0.0, \"\"]]", "t",
       "preset = \"talus\"", 1000, "name = \"near\"\nx = 50.0\nz = 70.0"});
  const Result n = pierre("validate " + q(dir_ / "near.toml"));
  EXPECT_EQ(n.code, 0) << n.err;
  EXPECT_EQ(n.out.find("Note:"), std::string::npos) << n.out;
}

// A material that no segment uses is noted at its table (it changes nothing; often one left
// over); the used one is not. In a quarry scenario a material is unused when no section's profile
// uses it (a section listed from the floor end is an error there: no toe past the crest).
TEST_F(Cli, AMaterialNoSegmentUsesIsNoted) {
  std::ofstream(dir_ / "s.toml") << one_block_scenario(
      {"spare material", 2, "points = [[0.0, 100.0, \"t\"], [200.0, 0.0, \"\"]]", "t",
       "preset = \"talus\"\n[materials.spare]\npreset = \"talus\"", 1000,
       "x = 1.0\nz = 101.0"});
  const Result v = pierre("validate " + q(dir_ / "s.toml"));
  EXPECT_EQ(v.code, 0) << v.err;
  EXPECT_NE(v.out.find("Note: " + (dir_ / "s.toml").string() +
                       ":10: materials.spare: material \"spare\" is defined but no segment of "
                       "the profile uses it\n"),
            std::string::npos)
      << v.out;
  EXPECT_EQ(v.out.find("material \"t\" is defined"), std::string::npos) << v.out;

  std::ofstream(dir_ / "pit.toml")
      << "[scenario]\nname = \"pit\"\n[simulation]\nseed = 1\nthrows = 1\n"
         "[materials.face]\npreset = \"quarry-face\"\n[materials.floor]\npreset = \"quarry-floor\"\n"
         "[materials.spare]\npreset = \"talus\"\n"
         "[[quarries]]\nname = \"East\"\n"
         "profile = { points = [[0.0, 20.0, \"face\"], [10.0, 20.0, \"face\"], [20.0, 0.0, "
         "\"face\"], [90.0, 0.0, \"\"]] }\nblocks = { table = [{ id = \"A\", mass = 500.0 }] }\n"
         "sources = [{ x = 10.3, z = 20.0 }]\n"
         "[[quarries]]\nname = \"West\"\n"
         "profile = { points = [[0.0, 20.0, \"face\"], [10.0, 20.0, \"face\"], [20.0, 0.0, "
         "\"floor\"], [90.0, 0.0, \"\"]] }\nblocks = { table = [{ id = \"A\", mass = 500.0 }] }\n"
         "sources = [{ x = 10.3, z = 20.0 }]\n";
  const Result pv = pierre("validate " + q(dir_ / "pit.toml"));
  EXPECT_EQ(pv.code, 0) << pv.err;
  EXPECT_NE(pv.out.find("Note: " + (dir_ / "pit.toml").string() +
                        ":10: materials.spare: material \"spare\" is defined but no segment of "
                        "any section's profile uses it\n"),
            std::string::npos)
      << pv.out;
  EXPECT_EQ(pv.out.find("material \"floor\" is defined"), std::string::npos) << pv.out;
  EXPECT_EQ(pv.out.find("falls towards"), std::string::npos) << pv.out;
}

// Two quarry sections on one seed draw the same random numbers: not independent samples, so
// pooled they count twice what one shows (new-user review: a section's own seed met another's
// [simulation] seed + index without a word). Noted by validate and run, for the seeds run.
TEST_F(Cli, QuarrySectionsOnOneSeedAreNoted) {
  std::string text = slurp(PIERRE_TEST_DATA "/quarry-cli/pass.toml");
  text.replace(text.find("name = \"North\"\n"), 15, "name = \"North\"\nseed = 12\n");
  std::ofstream(dir_ / "s.toml") << text;
  const std::string note = "Note: " + (dir_ / "s.toml").string() +
                           ": quarries[1].seed: sections \"North\" (its own) and \"South\" "
                           "([simulation] seed + its index) both run with seed 12: their blocks "
                           "draw the same random numbers";
  const Result v = pierre("validate " + q(dir_ / "s.toml"));
  EXPECT_EQ(v.code, 0) << v.err;
  EXPECT_NE(v.out.find(note), std::string::npos) << v.out;
  const Result r = pierre("run " + q(dir_ / "s.toml") + " --throws 1 -q --out " + q(dir_ / "o"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find(note), std::string::npos) << r.err;
  // --seed 5 gives South 6: no longer North's 12. --seed 11 gives it 12 again.
  const Result other = pierre("run " + q(dir_ / "s.toml") + " --seed 5 --throws 1 -q --out " + q(dir_ / "o"));
  EXPECT_EQ(other.err.find("both run with seed"), std::string::npos) << other.err;
  EXPECT_EQ(pierre("validate " + q(PIERRE_TEST_DATA "/quarry-cli/pass.toml")).out.find("both run with seed"),
            std::string::npos);
}

TEST_F(Cli, HelpShowsExamplesAndExitsZero) {
  for (const char* args : {"--help", "run --help", "validate --help"}) {
    const Result r = pierre(args);
    EXPECT_EQ(r.code, 0) << args;
    EXPECT_NE(r.out.find("Example"), std::string::npos) << args << "\n" << r.out;
  }
  const Result run_help = pierre("run --help");
  EXPECT_NE(run_help.out.find("--out"), std::string::npos);
  EXPECT_NE(run_help.out.find("--all-crossings"), std::string::npos);
}

// The output of a shell command, its last newline dropped; empty when it fails.
std::string shell_output(const std::string& cmd) {
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    if (::pclose(p) != 0) return "";
  }
  if (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

// --version names the version and the commit built; summary.json records the same build, so a
// firm tells which build made a report when the version number stayed the same.
TEST_F(Cli, VersionNamesTheBuildThatSummaryJsonRecords) {
  const Result r = pierre("--version");
  EXPECT_EQ(r.code, 0);
  const std::string prefix = std::string("pierre ") + PIERRE_VERSION + " (build ";
  ASSERT_EQ(r.out.rfind(prefix, 0), 0u) << r.out;
  const std::size_t close = r.out.find(")\n", prefix.size());
  ASSERT_NE(close, std::string::npos) << r.out;
  const std::string build = r.out.substr(prefix.size(), close - prefix.size());
  ASSERT_EQ(pierre("run " + kScenario + " --quiet --throws 1 --out " + q(dir_ / "out")).code, 0);
  EXPECT_EQ(summary(dir_ / "out")["pierre_build"], build);
  // Built from a git checkout (as CI and the README's commands do), it names a commit of it.
  const std::string git = "git -C '" + std::string(PIERRE_SOURCE_DIR) + "' ";
  if (shell_output(git + "rev-parse --git-dir 2>/dev/null").empty())
    GTEST_SKIP() << "the source is not a git checkout: the build is " << build;
  const std::string commit = build.substr(0, build.find("-dirty"));
  EXPECT_EQ(commit.size(), 12u) << build;
  EXPECT_EQ(shell_output(git + "rev-parse --short=12 " + commit + "^{commit} 2>/dev/null"), commit)
      << build << " is not a commit of " << PIERRE_SOURCE_DIR;
}

TEST_F(Cli, UsageErrorsExitTwo) {
  const std::string run = "run " + kScenario + " --out " + q(dir_ / "x");
  for (const std::string& args : {run + " --bogus",
                                  "run " + kScenario,  // --out missing
                                  run + " --throws 0", run + " --seed -1", run + " --threads x",
                                  std::string("frobnicate"), std::string()}) {
    const Result r = pierre(args);
    EXPECT_EQ(r.code, 2) << "pierre " << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  EXPECT_FALSE(fs::exists(dir_ / "x"));
  // Arguments a command does not take are named in the order they were typed (CLI11 reversed
  // them: "foo --out").
  EXPECT_NE(pierre("validate " + kScenario + " --out foo").err.find(
                "pierre validate: found --out foo: --out is not an option of pierre validate"),
            std::string::npos);
  EXPECT_NE(pierre("validate " + kScenario + " foo").err.find(
                "pierre validate: found foo, expected no more arguments"),
            std::string::npos);
  // A misspelt option is named with the nearest one (new-user review: --rule for --rules), and
  // an output folder typed without --out is pointed at; an option's value, or the scenario
  // after options, is not taken for one.
  EXPECT_NE(pierre(run + " --rule " + q(dir_)).err.find(
                "--rule is not an option of pierre run; did you mean --rules? (pierre run --help)"),
            std::string::npos);
  EXPECT_EQ(pierre("run " + kScenario + " outdir").err,
            "pierre run: found no --out, expected --out DIR, the folder the results go to; outdir "
            "stands alone: did you mean --out outdir? (pierre run --help)\n");
  EXPECT_NE(pierre("run --seed 3 " + kScenario + " outdir").err.find("did you mean --out outdir?"),
            std::string::npos);
  // After a flag, or an option with its value attached, a word is no option's value either.
  for (const char* before : {"--strict", "-q", "--throws=3"})
    EXPECT_NE(pierre("run " + kScenario + " " + before + " outdir").err.find("did you mean --out outdir?"),
              std::string::npos)
        << before;
  EXPECT_EQ(pierre("run " + kScenario + " --throws 3").err.find("did you mean"), std::string::npos);
  EXPECT_EQ(pierre(run + " ---").code, 2);  // all dashes: no option to compare (it threw, exit 3)
  EXPECT_EQ(pierre("run --seed 3 " + kScenario).err,
            "pierre run: found no --out, expected --out DIR, the folder the results go to (pierre "
            "run --help)\n");
  EXPECT_FALSE(fs::exists(dir_ / "x"));
  // Words after "--" are named too (it said "found , expected ...").
  const Result after_dashes = pierre("run " + kScenario + " --out " + q(dir_ / "x") + " -- foo");
  EXPECT_EQ(after_dashes.code, 2);
  EXPECT_NE(after_dashes.err.find("pierre run: found foo, expected no more arguments"),
            std::string::npos)
      << after_dashes.err;
  // A long option typed with one dash is refused by name: CLI11 would read "-out" as "-o ut"
  // and put the results in ./ut without a word.
  const Result one_dash = pierre("run " + kScenario + " -out --threads 1 --quiet");
  EXPECT_EQ(one_dash.code, 2) << one_dash.err;
  EXPECT_NE(one_dash.err.find("found -out, expected --out: long options take two dashes"),
            std::string::npos)
      << one_dash.err;
  EXPECT_FALSE(fs::exists("ut"));
  EXPECT_EQ(pierre("run " + kScenario + " --out " + q(dir_ / "x") + " -seed=3").code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "x"));
  // A misspelt command is named, with the commands there are.
  EXPECT_NE(pierre("chek " + kScenario).err.find("chek: not a command; expected run, check or validate"),
            std::string::npos);
  // An option of no command is named too (it was "found no command").
  const Result dash_v = pierre("-v");
  EXPECT_EQ(dash_v.code, 2);
  EXPECT_EQ(dash_v.err, "pierre: found -v: not an option of pierre; expected a command (run, "
                        "check or validate), --help or --version (pierre --help)\n");
  // `pierre help [command]` is the help it names; --version after a command is the program's.
  const Result help = pierre("help"), help_run = pierre("help run"), run_help = pierre("run --help");
  EXPECT_EQ(help.code, 0) << help.err;
  EXPECT_EQ(help.out, pierre("--help").out);
  EXPECT_EQ(help_run.code, 0) << help_run.err;
  EXPECT_EQ(help_run.out, run_help.out);
  EXPECT_NE(help_run.out.find("Usage: pierre run"), std::string::npos) << help_run.out;
  // What `help` does not know is said as a misspelt command is, exit 2 (not the program's help).
  for (const char* word : {"nonsense", "-v", "help", "--"}) {
    const Result r = pierre(std::string("help ") + word);
    EXPECT_EQ(r.code, 2) << word;
    EXPECT_EQ(r.err, std::string("pierre help: found ") + word +
                         ", expected a command: run, check or validate\n");
  }
  // A command after "--" is no command (CLI11 said "found no A subcommand").
  EXPECT_EQ(pierre("-- run").err, "pierre: found no command, expected run, check or validate (pierre --help)\n");
  const Result version = pierre("--version"), run_version = pierre("run --version");
  EXPECT_EQ(run_version.code, 0) << run_version.err;
  EXPECT_EQ(run_version.out, version.out);
  EXPECT_EQ(version.out.rfind("pierre ", 0), 0u) << version.out;
  // What is missing is said as every other error (CLI11 said "--out is required"), exit 2.
  const std::pair<std::string, std::string> missing[] = {
      {"run " + kScenario, "pierre run: found no --out, expected --out DIR, the folder the results go to (pierre run --help)\n"},
      {"validate", "pierre validate: found no scenario, expected the scenario file (TOML) to read (pierre validate --help)\n"},
      {"", "pierre: found no command, expected run, check or validate (pierre --help)\n"}};
  for (const auto& [args, said] : missing) {
    const Result r = pierre(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err, said) << args;
  }
  // A seed is a whole number from 0 to 2^63 - 1, said in whole numbers (not as 1.8e308 written
  // out in full); a larger one is refused, not clamped to the largest (two seeds, one run).
  for (const char* seed : {"-1", "9223372036854775808", "18446744073709551615", "1e3", "12x"}) {
    const Result r = pierre(run + " --seed " + seed);
    EXPECT_EQ(r.code, 2) << seed;
    EXPECT_NE(r.err.find(std::string("--seed: found ") + seed +
                         ", expected a whole number from 0 to 9223372036854775807"),
              std::string::npos)
        << r.err;
  }
  // --throws and --threads the same way: a fraction is not a whole number (CLI11 called 1.5
  // "not in range 1 to 4294967295").
  for (const auto& [option, value, range] :
       {std::tuple{"--throws", "1.5", "1 to 4294967295"}, std::tuple{"--throws", "0", "1 to 4294967295"},
        std::tuple{"--threads", "abc", "0 to 4096"}, std::tuple{"--threads", "4097", "0 to 4096"}}) {
    const Result r = pierre(run + " " + option + " " + value);
    EXPECT_EQ(r.code, 2) << option << " " << value;
    EXPECT_NE(r.err.find(std::string(option) + ": found " + value + ", expected a whole number from " + range),
              std::string::npos)
        << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "x"));
}

TEST_F(Cli, SameSeedSameFiles) {
  ASSERT_EQ(pierre("run " + kScenario + " --quiet --out " + q(dir_ / "a")).code, 0);
  ASSERT_EQ(pierre("run " + kScenario + " --quiet --out " + q(dir_ / "b")).code, 0);
  for (const char* f : {"trajectories.csv", "crossings.csv", "summary.json"})
    EXPECT_EQ(slurp(dir_ / "a" / f), slurp(dir_ / "b" / f)) << f;
  ASSERT_EQ(pierre("run " + kScenario + " --quiet --seed 1 --out " + q(dir_ / "c")).code, 0);
  EXPECT_NE(slurp(dir_ / "a" / "trajectories.csv"), slurp(dir_ / "c" / "trajectories.csv"));
}

// The SHA-256 of a file as coreutils' sha256sum gives it: an independent hash to check ours by.
std::string sha256sum(const fs::path& file) {
  std::string out;
  if (FILE* p = ::popen(("sha256sum '" + file.string() + "'").c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    ::pclose(p);
  }
  return out.substr(0, 64);
}

// summary.json names every file the run read, each with its SHA-256 as sha256sum gives it, so a
// pipeline sees which input made a change (an edited block table changed only statistics);
// an edit of one CSV changes that file's hash alone.
TEST_F(Cli, SummaryNamesEveryInputWithItsHash) {
  fs::copy(fs::path(kScenario).parent_path(), dir_ / "in", fs::copy_options::recursive);
  const std::string scenario = (dir_ / "in" / "scenario.toml").string();
  const auto inputs = [&](const fs::path& out) {
    const Result r = pierre("run " + q(scenario) + " --quiet --throws 2 --out " + q(out));
    EXPECT_EQ(r.code, 0) << r.err;
    return summary(out)["inputs"];
  };
  const auto before = inputs(dir_ / "o1");
  // The scenario, the materials, the profile, and the report layout that shaped report.xlsx.
  ASSERT_EQ(before.size(), 4u) << before;
  EXPECT_EQ(before[0]["file"], scenario);
  EXPECT_EQ(before[2]["file"], (dir_ / "in" / "profile.csv").string());
  EXPECT_EQ(fs::path(before[1]["file"].get<std::string>()).filename(), "materials.toml");
  EXPECT_EQ(fs::path(before[3]["file"].get<std::string>()).filename(), "report.toml");
  for (const auto& f : before) {
    const fs::path file = f["file"].get<std::string>();
    EXPECT_EQ(f["sha256"], sha256sum(file)) << file;
    EXPECT_EQ(f["bytes"].get<std::uintmax_t>(), fs::file_size(file)) << file;
  }
  std::ofstream(dir_ / "in" / "profile.csv", std::ios::app) << "# edited\n";
  const auto after = inputs(dir_ / "o2");
  ASSERT_EQ(after.size(), 4u);
  EXPECT_EQ(after[0], before[0]);
  EXPECT_EQ(after[1], before[1]);
  EXPECT_EQ(after[3], before[3]);
  EXPECT_NE(after[2]["sha256"], before[2]["sha256"]);
  EXPECT_EQ(after[2]["sha256"], sha256sum(dir_ / "in" / "profile.csv"));
}

// A firm's pipeline runs each job in a fresh workspace that holds pierre, its rules and
// templates and the scenario, from the workspace's root: two workspaces at different absolute
// paths give the same bytes, because the rules files are recorded relative to the working
// folder. (They were recorded by absolute path, so no two jobs' reports were the same.)
TEST_F(Cli, TwoWorkspacesGiveTheSameReport) {
  // The rules folder found, or named as CI scripts name it: by the workspace's absolute path
  // ($PWD/rules), through PIERRE_RULES, or as ./rules/. Each is recorded as rules/.
  const std::pair<const char*, std::string> jobs[] = {
      {"job-1", ""},
      {"job-22", ""},
      {"job-3", " --rules \"$PWD/rules\""},
      {"job-44", " --rules ./rules/"},
      {"job-5", "env"}};
  for (const auto& [job, rules] : jobs) {
    const fs::path ws = dir_ / job;
    fs::create_directories(ws / "bin");
    fs::copy_file(PIERRE_BINARY, ws / "bin" / "pierre");
    fs::permissions(ws / "bin" / "pierre", fs::perms::owner_all);
    for (const char* d : {"rules", "templates"})
      fs::copy(fs::path(PIERRE_SOURCE_DIR) / d, ws / d, fs::copy_options::recursive);
    fs::copy(fs::path(kScenario).parent_path(), ws / "input", fs::copy_options::recursive);
    const std::string cmd = "cd " + q(ws) + " && SOURCE_DATE_EPOCH=1700000000 " +
                            (rules == "env" ? "PIERRE_RULES=\"$PWD/rules\" " : "") +
                            "bin/pierre run input/scenario.toml --quiet --throws 20 --out out" +
                            (rules == "env" ? "" : rules) + " 2>" + q(ws / "err.txt");
    const int st = std::system(cmd.c_str());
    ASSERT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 0) << slurp(ws / "err.txt");
    const auto j = nlohmann::json::parse(slurp(ws / "out" / "summary.json"));
    EXPECT_EQ(j["scenario"]["materials_file"], "rules/materials.toml") << job;
  }
  for (const char* f : {"summary.json", "report.xlsx", "trajectories.csv"})
    for (const char* other : {"job-22", "job-3", "job-44", "job-5"})
      EXPECT_EQ(slurp(dir_ / "job-1" / "out" / f), slurp(dir_ / other / "out" / f)) << f << " " << other;
}

// A rerun that cannot replace one result (here a folder by its name; a report held open in
// Excel on Windows fails the same way) exits 2, names the file, and leaves every earlier result
// as it was. It exited 3 with some files of the new run and some of the old.
TEST_F(Cli, ARerunThatCannotReplaceAResultLeavesTheEarlierOne) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(pierre("run " + kScenario + " --quiet --seed 1 --out " + q(out)).code, 0);
  const std::string trajectories = slurp(out / "trajectories.csv");
  const std::string crossings = slurp(out / "crossings.csv");
  fs::remove(out / "summary.json");
  fs::create_directory(out / "summary.json");
  const Result r = pierre("run " + kScenario + " --quiet --seed 2 --out " + q(out));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("summary.json: it is not a file"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(out / "trajectories.csv"), trajectories);
  EXPECT_EQ(slurp(out / "crossings.csv"), crossings);
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_NE(e.path().filename().string().rfind(".pierre-partial-", 0), 0u) << e.path();
}

// A run that cannot write its results (a full disk; here a file size limit, which fails a
// write the same way without filling the disk) exits 2, names the result and the reason, and
// leaves the earlier results as they were. It exited 3 as an internal error; and where a
// report's sheet was cut short, libxlsxwriter closed the workbook without an error, so a corrupt
// report replaced the good one with exit 0.
TEST_F(Cli, ARunThatCannotWriteItsResultsLeavesTheEarlierOnes) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(pierre("run " + kScenario + " --quiet --seed 1 --out " + q(out)).code, 0);
  std::map<std::string, std::string> before;
  for (const auto& e : fs::directory_iterator(out))
    before[e.path().filename().string()] = slurp(e.path());
  ASSERT_GT(fs::file_size(out / "trajectories.csv"), 60'000u);
  ASSERT_GT(fs::file_size(out / "crossings.csv"), 100'000u);
  ASSERT_GT(fs::file_size(out / "report.xlsx"), 500'000u);
  // ulimit -f counts blocks of 512 bytes (dash) or 1024 (bash): 40 blocks stop the first CSV,
  // 400 let both CSVs (< 200 kB) through and stop the report's largest sheet (> 1 MB unzipped).
  const struct {
    int blocks;
    std::string result, reason;
  } cases[] = {{40, "trajectories.csv: ", "File too large"},
               {400, "report.xlsx: ", "came out cut short"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.blocks);
    const Result r = pierre_with_env("trap '' XFSZ; ulimit -f " + std::to_string(c.blocks) + ";",
                                     "run " + kScenario + " --quiet --seed 2 --out " + q(out));
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("cannot write " + (out / c.result).string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.reason), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no result was replaced"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    std::map<std::string, std::string> after;
    for (const auto& e : fs::directory_iterator(out))
      after[e.path().filename().string()] = slurp(e.path());
    EXPECT_TRUE(after == before) << "the earlier results changed, or a staging folder was left";
  }
}

// A run whose stderr is not a terminal (a CI job's log) logs its progress every
// $PIERRE_PROGRESS_SECONDS (default 60: a short run logs nothing, as the other tests see), then
// the steps after the simulation; quiet too, so that a long job does not look hung. A bad value
// is bad input, said before anything is written.
TEST_F(Cli, ARunLogsItsProgressWhenStderrIsNotATerminal) {
  const std::string vaujany = PIERRE_SOURCE_DIR "/examples/vaujany-2d/scenario.toml";
  const Result r = pierre_with_env(
      "PIERRE_PROGRESS_SECONDS=0.01",
      "run '" + vaujany + "' --quiet --threads 1 --throws 1000 --out " + q(dir_ / "out"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  std::vector<double> shares;
  std::istringstream lines(r.err);
  std::string line, last;
  const std::string lead = "pierre: ", of = " % of 100000 trajectories, ";
  while (std::getline(lines, line)) {
    if (line.rfind(lead, 0) != 0) continue;
    last = line;
    const auto at = line.find(of);
    if (at == std::string::npos) continue;  // a step after the simulation
    shares.push_back(std::stod(line.substr(lead.size(), at - lead.size())));
    EXPECT_NE(line.find(" trajectories/s, ETA "), std::string::npos) << line;
  }
  // 100 000 trajectories take a good fraction of a second: lines every 10 ms, the last at 100 %.
  ASSERT_GE(shares.size(), 2u) << r.err;
  EXPECT_TRUE(std::is_sorted(shares.begin(), shares.end())) << r.err;
  EXPECT_EQ(shares.back(), 100.0) << r.err;
  EXPECT_EQ(last, "pierre: writing summary.json and report.xlsx ...") << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / "report.xlsx"));

  const Result bad = pierre_with_env("PIERRE_PROGRESS_SECONDS=soon",
                                     "run '" + vaujany + "' --quiet --out " + q(dir_ / "bad"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("PIERRE_PROGRESS_SECONDS: found \"soon\", expected a number of seconds > 0"),
            std::string::npos)
      << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad"));
}

// SOURCE_DATE_EPOCH fixes the report's date. One in milliseconds (a common slip) or not a
// number is bad input, said before the run (it was an internal error, exit 3, after it).
TEST_F(Cli, ABadSourceDateEpochIsRefusedBeforeTheRun) {
  const fs::path out = dir_ / "out";
  struct Env {
    explicit Env(const char* v) { ::setenv("SOURCE_DATE_EPOCH", v, 1); }
    ~Env() { ::unsetenv("SOURCE_DATE_EPOCH"); }
  };
  for (const char* bad : {"1700000000000", "253402300800", "17e8", "-1", "today"}) {
    Env env(bad);
    for (const char* cmd : {"run ", "validate "}) {
      const Result r = pierre(cmd + kScenario +
                              (std::string(cmd) == "run " ? " --quiet --out " + q(out) : std::string()));
      EXPECT_EQ(r.code, 2) << cmd << bad << ": " << r.err;
      EXPECT_NE(r.err.find("SOURCE_DATE_EPOCH: found \"" + std::string(bad) + "\""), std::string::npos)
          << r.err;
      EXPECT_FALSE(fs::exists(out));
    }
  }
  Env env("253402300799");  // the last second of 9999: the date a workbook still holds
  const Result r = pierre("run " + kScenario + " --quiet --out " + q(out));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(out / "report.xlsx").size(), 0u);
}

TEST_F(Cli, ThreadCountDoesNotChangeResults) {
  ASSERT_EQ(pierre("run " + kScenario + " --quiet --impacts --threads 1 --out " + q(dir_ / "t1")).code, 0);
  ASSERT_EQ(pierre("run " + kScenario + " --quiet --impacts --threads 2 --out " + q(dir_ / "t2")).code, 0);
  for (const char* f : {"trajectories.csv", "crossings.csv", "impacts.csv"})
    EXPECT_EQ(slurp(dir_ / "t1" / f), slurp(dir_ / "t2" / f)) << f;
  auto j1 = nlohmann::json::parse(slurp(dir_ / "t1" / "summary.json"));
  auto j2 = nlohmann::json::parse(slurp(dir_ / "t2" / "summary.json"));
  EXPECT_EQ(j1["threads"], 1);
  EXPECT_EQ(j2["threads"], 2);  // 600 trajectories = two chunks of 512: two workers really ran
  j1.erase("threads");
  j2.erase("threads");
  EXPECT_EQ(j1, j2);
  // Eight threads on enough trajectories for each to take chunks (2 × 2600 = 5200 trajectories,
  // eleven chunks of 512): the same files as one thread, byte for byte (model-2d.md §7 test 9).
  const std::string many = " --quiet --impacts --throws 2600 --out ";
  ASSERT_EQ(pierre("run " + kScenario + many + q(dir_ / "m1") + " --threads 1").code, 0);
  ASSERT_EQ(pierre("run " + kScenario + many + q(dir_ / "m8") + " --threads 8").code, 0);
  EXPECT_EQ(summary(dir_ / "m8")["threads"], 8);
  for (const char* f : {"trajectories.csv", "crossings.csv", "impacts.csv"})
    EXPECT_EQ(slurp(dir_ / "m1" / f), slurp(dir_ / "m8" / f)) << f;
}


// A block on a smooth slope reaches the maximum sliding speed (5 m/s) and is launched, but a
// roughness of 1e-9 tilts the plane too little to lift it: it slides on at the same instant
// and is launched again, until the impact limit. Its stop point is then where it first reached
// 5 m/s from rest, s = v² / (2 a) along the slope with a = g (sin β − cos β tan φ), plus a drift:
// each launch's uncontained slip costs it P = tan φ (1 + k_n) v sin θ ≤ 2 · 0.58 · 5 · 3.2e-9 m/s
// (tan θ = 1e-9 X f_size with X < 3, f_size ≈ 1.05), regained over v P / a ≤ 5e-7 m: at most
// 0.05 m in 100 000 launches. Before, the report's
// sample paths (20 of 200 000 points) overflowed the Profile sheet and the run ended with
// exit 3 after the simulation.
TEST_F(Cli, BlocksCutOffByTheImpactLimitAreReportedAndDrawn) {
  const fs::path scenario = dir_ / "smooth.toml";
  std::ofstream(scenario) << one_block_scenario(
      {"smooth slope", 20,
       R"(points = [[0.0, 100.0, "smooth"], [100.0, 40.0, "smooth"], [200.0, 30.0, ""]])",
       "smooth",
       "normal_energy = 15.0\ntangential_energy = 50.0\nroughness = 1e-9\nfriction_angle = 30.0",
       1500, "x = 1.0\nz = 99.4"});
  const fs::path out = dir_ / "out";
  const Result r = pierre("run " + q(scenario) + " --out " + q(out));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(out / "report.xlsx"));
  const auto j = summary(out);
  EXPECT_EQ(j["stop_reasons"]["impact-limit"], 20) << j["stop_reasons"];
  EXPECT_NE(r.out.find("Note: 20 trajectories were cut off by simulation.max_impacts"),
            std::string::npos)
      << r.out;
  const double tan_b = 0.6, cos_b = 1 / std::sqrt(1 + tan_b * tan_b), sin_b = tan_b * cos_b;
  const double a = 9.81 * (sin_b - cos_b * std::tan(30.0 * std::acos(-1.0) / 180));
  const double runout = 25.0 / (2 * a) * cos_b;  // ≈ 56.26 m
  // Every block was cut off while moving: each runout statistic is a lower bound, "≥" on the
  // console and in summary.json.
  EXPECT_EQ(j["runout_m"]["lower_bounds"], nlohmann::json::array({"p50", "p95", "p99", "max"}));
  EXPECT_NE(r.out.find("P50 ≥ "), std::string::npos) << r.out;
  for (const char* q : {"p50", "max"}) {
    const double x = j["runout_m"][q].get<double>();
    EXPECT_GE(x, runout - 1e-9) << q;         // it cannot stop before reaching 5 m/s
    EXPECT_LE(x, runout + 0.05 * cos_b) << q;  // nor drift further than the bound above
  }
  // One trajectory: the note in the singular throughout.
  const Result one = pierre("run " + q(scenario) + " --throws 1 --out " + q(dir_ / "one"));
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_NE(one.out.find("Note: 1 trajectory was cut off by simulation.max_impacts"), std::string::npos)
      << one.out;
  EXPECT_NE(one.out.find("its stop point and runout are where it was cut off."), std::string::npos)
      << one.out;
  // Quiet, the note goes to stderr, where a pipeline's log keeps it (it was dropped).
  const Result quiet = pierre("run " + q(scenario) + " --throws 1 --quiet --out " + q(dir_ / "q"));
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_TRUE(quiet.out.empty()) << quiet.out;
  EXPECT_EQ(quiet.err.rfind("Note: 1 trajectory was cut off by simulation.max_impacts", 0), 0u)
      << quiet.err;
}


// rules/ and templates/ are found the same way: a binary copied out of the build tree finds
// both (before, it found the rules through the source path compiled in and not the template,
// and failed only after the whole simulation). A template that cannot be found stops the run
// before anything is simulated or written, naming the places searched.
TEST_F(Cli, RulesAndTemplatesAreFoundTheSameWayAndCheckedFirst) {
  fs::create_directories(dir_ / "bin");
  fs::copy_file(PIERRE_BINARY, dir_ / "bin" / "pierre");
  fs::permissions(dir_ / "bin" / "pierre", fs::perms::owner_exec, fs::perm_options::add);
  const std::string copy = q(dir_ / "bin" / "pierre");
  const std::string quiet = " >/dev/null 2>&1";
  EXPECT_EQ(std::system((copy + " run " + kScenario + " --quiet --out " + q(dir_ / "a") + quiet).c_str()), 0);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "a" / "report.xlsx"));

  fs::create_directories(dir_ / "empty");
  const std::string env = "PIERRE_TEMPLATES=" + q(dir_ / "empty") + " ";
  for (const std::string& cmd : {"run " + kScenario + " --out " + q(dir_ / "b"),
                                "validate " + kScenario}) {
    const fs::path err = dir_ / "err.txt";
    const int st = std::system((env + "'" PIERRE_BINARY "' " + cmd + " >/dev/null 2>" + q(err)).c_str());
    EXPECT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 2) << cmd;
    const std::string msg = slurp(err);
    EXPECT_NE(msg.find((dir_ / "empty" / "report.toml").string() + ": file: found no such file"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("$PIERRE_TEMPLATES = " + (dir_ / "empty").string()), std::string::npos) << msg;
  }
  EXPECT_FALSE(fs::exists(dir_ / "b"));

  // $PIERRE_RULES is where the presets are read from.
  const fs::path err = dir_ / "err.txt";
  const int st = std::system(("PIERRE_RULES=" + q(dir_ / "empty") + " '" PIERRE_BINARY "' validate " +
                              kScenario + " >/dev/null 2>" + q(err)).c_str());
  EXPECT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 2);
  EXPECT_NE(slurp(err).find((dir_ / "empty" / "materials.toml").string()), std::string::npos)
      << slurp(err);
}


// A firm's restyled layout made before a key was added still works: the key comes from the
// built-in layout, and the run says which keys it took, on stderr and even with --quiet (a
// pipeline's run is quiet, and its firm is the one to tell).
TEST_F(Cli, AnOlderRestyledLayoutIsCompletedAndNoted) {
  std::string layout = slurp(PIERRE_SOURCE_DIR "/templates/report.toml");
  for (const std::string key : {"verdict = ", "no_checks = "}) {
    const auto at = layout.find("\n" + key);
    ASSERT_NE(at, std::string::npos) << key;
    layout.erase(at, layout.find('\n', at + 1) - at);
  }
  fs::create_directories(dir_ / "firm");
  std::ofstream(dir_ / "firm" / "report.toml") << layout;
  const std::string env = "PIERRE_TEMPLATES=" + q(dir_ / "firm") + " ";
  const fs::path out = dir_ / "out.txt";
  const int st = std::system((env + "'" PIERRE_BINARY "' run " + kScenario +
                              " --quiet --throws 1 --out " + q(dir_ / "r") + " 2>" + q(out))
                                 .c_str());
  EXPECT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 0) << slurp(out);
  EXPECT_NE(slurp(out).find("Note: the report layout " + (dir_ / "firm" / "report.toml").string() +
                            " leaves out 2 keys (labels.no_checks, labels.verdict): the layout "
                            "built into pierre gives them."),
            std::string::npos)
      << slurp(out);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "r" / "report.xlsx"));
}

// A firm's layout holding headings an earlier version used (the Summary's old observation-line
// columns): the run works and says which keys it ignores, so that the firm can drop them.
TEST_F(Cli, ARestyledLayoutsRetiredKeysAreIgnoredAndNoted) {
  std::string layout = slurp(PIERRE_SOURCE_DIR "/templates/report.toml");
  const auto at = layout.find("\nmax = \"Max\"\n");
  ASSERT_NE(at, std::string::npos);
  layout.insert(at + 1, "speed_mean = \"Mean speed (m/s)\"\n");
  fs::create_directories(dir_ / "firm");
  std::ofstream(dir_ / "firm" / "report.toml") << layout;
  const fs::path out = dir_ / "out.txt";
  const int st = std::system(("PIERRE_TEMPLATES=" + q(dir_ / "firm") + " '" PIERRE_BINARY "' run " +
                              kScenario + " --quiet --throws 1 --out " + q(dir_ / "r") + " 2>" + q(out))
                                 .c_str());
  EXPECT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 0) << slurp(out);
  EXPECT_NE(slurp(out).find("Note: the report layout " + (dir_ / "firm" / "report.toml").string() +
                            " holds 1 key (headings.lines.speed_mean) that this version of pierre "
                            "no longer uses: it is ignored."),
            std::string::npos)
      << slurp(out);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "r" / "report.xlsx"));
}

// Blocks that run off a profile too short for them: their runouts (where they left it) bias the
// percentiles low, and the summary says so with the count from the stop reasons.
TEST_F(Cli, BlocksLeavingTheProfileAreNoted) {
  const fs::path scenario = dir_ / "short.toml";
  std::ofstream(scenario) << one_block_scenario(
      {"short slope", 20, R"(points = [[0.0, 100.0, "t"], [60.0, 60.0, ""]])", "t",
       "normal_energy = 15.0\ntangential_energy = 50.0\nroughness = 0.65", 1000,
       "x = 1.0\nz = 101.0"});
  const Result r = pierre("run " + q(scenario) + " --out " + q(dir_ / "out"));
  ASSERT_EQ(r.code, 0) << r.err;
  const int left = summary(dir_ / "out")["stop_reasons"]["boundary"].get<int>();
  ASSERT_GT(left, 0) << "the slope is meant to be too short for some blocks";
  const std::string note = "Note: " + std::to_string(left) +
                           (left == 1 ? " trajectory left the profile; its runout is where it left"
                                      : " trajectories left the profile; their runout is where they left");
  EXPECT_NE(r.out.find(note), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("cut off by"), std::string::npos) << r.out;  // no limit was reached
}

// An --out that cannot be a folder is named, with why, before anything is simulated; the file in
// the way is left as it was.
TEST_F(Cli, AnOutputPathThatCannotBeAFolderIsRefusedByName) {
  const fs::path file = dir_ / "afile";
  std::ofstream(file) << "mine\n";
  const std::pair<std::string, std::string> cases[] = {
      {q(file), "--out: found " + file.string() + ", a file, expected a folder"},
      {q(file / "sub"), "--out: found " + (file / "sub").string() + ", under the file " +
                            file.string() + ", expected a folder"},
      {"''", "--out: found an empty path, expected a folder"}};
  for (const auto& [out, message] : cases) {
    const Result r = pierre("run " + kScenario + " --quiet --out " + out);
    EXPECT_EQ(r.code, 2) << out;
    EXPECT_EQ(r.err, message + "\n");  // as the other input errors: no "error:" before it
  }
  EXPECT_EQ(slurp(file), "mine\n");
}

// A verdict that never reached stdout (a full disk, here /dev/full) is not a success: exit 3
// and a message on stderr saying so, not 0 with the output lost, nor an "internal error" (the
// run's table, printed by fmt, failed by an exception that was reported as one).
TEST_F(Cli, OutputThatCannotBeWrittenIsAnError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  const fs::path e = dir_ / "stderr.txt";
  for (const std::string& args : {"validate " + q(kScenario),
                                 "run " + q(kScenario) + " --throws 2 --out " + q(dir_ / "r")}) {
    const std::string cmd = std::string("'") + PIERRE_BINARY + "' " + args + " >/dev/full 2>" + q(e);
    const int st = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(st)) << args;
    EXPECT_EQ(WEXITSTATUS(st), 3) << args;
    EXPECT_NE(slurp(e).find("error: cannot write to standard output: No space left on device"),
              std::string::npos)
        << args << ": " << slurp(e);
    EXPECT_EQ(slurp(e).find("internal error"), std::string::npos) << args << ": " << slurp(e);
  }
  // The same command into a file that can be written: 0.
  EXPECT_EQ(pierre("validate " + q(kScenario)).code, 0);
}

// A reader that closed the pipe (`pierre check … | head -1` after its line) is a failed write
// too: exit 3 and the message, not a silent death by SIGPIPE (exit 141). The pipe's read end
// is closed before pierre starts, so that the first write fails whatever the timing.
TEST_F(Cli, AClosedPipeIsAFailedWriteNotADeath) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  close(fds[0]);
  const fs::path e = dir_ / "stderr.txt";
  posix_spawn_file_actions_t acts;
  posix_spawn_file_actions_init(&acts);
  posix_spawn_file_actions_adddup2(&acts, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&acts, STDERR_FILENO, e.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = {PIERRE_BINARY, "validate", kScenario};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, PIERRE_BINARY, &acts, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&acts);
  close(fds[1]);
  int st = 0;
  ASSERT_EQ(waitpid(pid, &st, 0), pid);
  ASSERT_TRUE(WIFEXITED(st)) << "killed by signal " << (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
  EXPECT_EQ(WEXITSTATUS(st), 3);
  EXPECT_NE(slurp(e).find("error: cannot write to standard output: Broken pipe"), std::string::npos)
      << slurp(e);
}

}  // namespace
