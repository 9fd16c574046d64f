// `pierre validate`, `run` and `check` on quarry scenarios ([[quarries]], docs/quarry.md) with
// the real binary: exit codes (0 every work area outside its danger zone, 1 one inside, 2 bad
// quarry input with nothing written), the quarry table and check lines on stdout, "quarries"
// and "checks" in summary.json, the section column of trajectories.csv, per-section seeds,
// thread-count reproducibility, the floor contacts that give ID block by block, and the shipped
// example (examples/quarry-austria).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <cstdio>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <optional>
#include <string>
#include <regex>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/cli_fixture.hpp"
#include "support/tools.hpp"
#include "support/workbook_reader.hpp"
#include "pierre/io/report_template.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kData = PIERRE_TEST_DATA "/quarry-cli/";
const std::string kExample = PIERRE_SOURCE_DIR "/examples/quarry-austria/scenario.toml";

using Result = pierre::test::CliResult;
using pierre::test::count_of;
using pierre::test::slurp;
using pierre::test::zip_listing;

class QuarryCli : public pierre::test::PierreCli {};

const nlohmann::json& check(const nlohmann::json& j, const std::string& subject,
                            const std::string& id) {
  for (const auto& c : j["checks"])
    if (c["subject"] == subject && c["id"] == id) return c;
  throw std::runtime_error("no check " + subject + " " + id);
}

TEST_F(QuarryCli, WorkAreasOutsideTheZonesExitZero) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "pass.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  // The console: the table of Tables 6.2/6.3 and the check lines.
  for (const char* s : {"Quarry danger zones", "RD m", "RD/H", "ID m", "ID/H", "P50", "P95", "P99",
                        "max", "RD_gov", "ID_gov", "Checks", "zone.crusher", "zone.office"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
  // The runout from the release point pools both sections: not their RD, and said so.
  EXPECT_NE(r.out.find("Horizontal runout from the release point (m, 2 sections pooled; RD from the toe below)"),
            std::string::npos) << r.out;
  const auto j = summary(out);
  EXPECT_EQ(j["checks_failed"], false);
  EXPECT_EQ(check(j, "North", "zone.crusher")["status"], "PASS");
  EXPECT_EQ(check(j, "South", "zone.office")["status"], "PASS");
  EXPECT_EQ(check(j, "North", "bench.retention")["status"], "PASS");
  EXPECT_FALSE(j.contains("barriers"));
  // "quarries": one row per lone section, with its statistics and its section's zones.
  ASSERT_EQ(j["quarries"].size(), 2u);
  const auto& north = j["quarries"][0];
  EXPECT_EQ(north["name"], "North");
  EXPECT_EQ(north["pooled"], false);
  EXPECT_EQ(north["rules"]["name"], "quarry-thesis-2015");
  EXPECT_TRUE(fs::equivalent(north["rules"]["file"].get<std::string>(),
                             PIERRE_SOURCE_DIR "/rules/quarry-thesis-2015.toml"))
      << north["rules"];
  EXPECT_EQ(north["thrown"], 600);  // 2 blocks x 300 throws
  // The table rounds a distance as the sheets and the check lines do (0.01 m): North's RD row
  // holds its P50, P95 and P99 from summary.json to two decimals (it printed one).
  {
    const std::size_t row = r.out.find("\nNorth ");
    ASSERT_NE(row, std::string::npos) << r.out;
    const std::string line = r.out.substr(row + 1, r.out.find('\n', row + 1) - row - 1);
    for (const char* p : {"p50_m", "p95_m", "p99_m"}) {
      const double v = north["runout"][p].get<double>();
      ASSERT_TRUE(std::isfinite(v)) << p;
      EXPECT_NE(line.find(" " + fmt::format("{:.2f}", v) + " "), std::string::npos)
          << p << " " << v << "\n" << line;
    }
  }
  EXPECT_EQ(north["runout"]["count"], 600);
  // Counts are whole numbers in JSON too (956, not 956.0), and the KS test's are at most the
  // blocks that ran out beyond the toe.
  for (const char* key : {"n", "observed"}) {
    const auto& v = north["runout"]["lognormal_ks"][key];
    EXPECT_TRUE(v.is_number_unsigned()) << key << " " << v;
    EXPECT_LE(v.get<double>(), 600) << key;
  }
  EXPECT_LE(north["runout"]["lognormal_ks"]["observed"].get<double>(),
            north["runout"]["lognormal_ks"]["n"].get<double>());
  EXPECT_DOUBLE_EQ(north["height_m"].get<double>(), 20.0);
  const double rd95 = north["runout"]["p95_m"].get<double>();
  EXPECT_GT(rd95, 0.0);
  EXPECT_DOUBLE_EQ(north["RD_gov"]["value_m"].get<double>(), rd95);  // thesis rule: RD95
  EXPECT_NEAR(north["runout"]["p95_h"].get<double>(), rd95 / 20.0, 1e-12);
  const auto& sec = north["sections"][0];
  EXPECT_EQ(sec["name"], "North");
  EXPECT_EQ(sec["seed"], 11);  // [simulation].seed + 0
  EXPECT_EQ(sec["geometry"]["toe"]["origin"], "found");
  EXPECT_DOUBLE_EQ(sec["geometry"]["toe"]["x_m"].get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(sec["danger_zone_m"].get<double>(), rd95);
  EXPECT_DOUBLE_EQ(check(j, "North", "zone.crusher")["limit"].get<double>(), rd95);
  const auto& south = j["quarries"][1]["sections"][0];
  EXPECT_EQ(south["seed"], 12);  // [simulation].seed + 1
  EXPECT_EQ(south["geometry"]["toe"]["origin"], "given");
  EXPECT_EQ(j["trajectories"], 900);
  EXPECT_TRUE(j.contains("quarry_average"));
  // One trajectories.csv for both sections, each row led by its section.
  const std::string csv = slurp(out / "trajectories.csv");
  EXPECT_EQ(csv.rfind("section,trajectory,source,block_id,", 0), 0u);
  EXPECT_NE(csv.find("\nNorth,0,"), std::string::npos);
  EXPECT_NE(csv.find("\nSouth,0,"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 901);
}

TEST_F(QuarryCli, WorkAreaInsideTheZoneExitsOneAndStillWritesTheResults) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "fail.toml --out '" + out.string() + "' --quiet");
  ASSERT_EQ(r.code, 1) << r.err << r.out;
  EXPECT_NE(r.out.find("FAIL North zone.crusher"), std::string::npos) << r.out;
  const auto j = summary(out);
  EXPECT_EQ(check(j, "North", "zone.crusher")["status"], "FAIL");
  EXPECT_DOUBLE_EQ(check(j, "North", "zone.crusher")["value"].get<double>(), 2.0);
  EXPECT_EQ(check(j, "South", "zone.office")["status"], "PASS");
  EXPECT_EQ(j["checks_failed"], true);
  EXPECT_EQ(j["quarries"][0]["sections"][0]["work_areas"][0]["inside_zone"], true);
  EXPECT_TRUE(fs::exists(out / "trajectories.csv"));
  // The design report has a sheet per quarry row and their charts (the xlsx is a zip).
  ASSERT_TRUE(fs::is_regular_file(out / "report.xlsx"));
  PIERRE_NEED_PROGRAM("unzip");
  const std::string parts = zip_listing(out / "report.xlsx");
  ASSERT_FALSE(parts.empty()) << "unzip lists nothing: report.xlsx is not a zip";
  {
    const std::size_t charts = count_of(parts, "xl/charts/chart");
    EXPECT_GE(charts, 2u * 5u) << parts;  // per row: a section chart, 2 histograms, 2 CDFs
    // The data sheets hold every section's rows (there were none), led by the section's name.
    auto part = [&](const std::string& name) {
      std::string text;
      if (FILE* p = ::popen(("unzip -p '" + (out / "report.xlsx").string() + "' " + name).c_str(), "r")) {
        char buf[4096];
        for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) text.append(buf, n);
        ::pclose(p);
      }
      return text;
    };
    const std::string wb = part("xl/workbook.xml"), strings = part("xl/sharedStrings.xml");
    int index = 0, sheet = 0;
    for (auto at = wb.find("<sheet name=\""); at != std::string::npos; at = wb.find("<sheet name=\"", at + 1)) {
      ++index;
      if (wb.compare(at + 13, 13, "Trajectories\"") == 0) sheet = index;
    }
    ASSERT_GT(sheet, 0) << wb;
    const std::string rows = part("xl/worksheets/sheet" + std::to_string(sheet) + ".xml");
    const std::string csv = slurp(out / "trajectories.csv");
    const auto lines = static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n'));
    EXPECT_EQ(count_of(rows, "<row "), lines - 1 + 3);  // title, note, headings; every trajectory
    EXPECT_NE(strings.find(">Quarry section<"), std::string::npos);
    for (const char* section : {">North<", ">South<"})
      EXPECT_NE(strings.find(section), std::string::npos) << section;
  }
  // `pierre run` exits 0 whatever the checks say.
  const fs::path out2 = dir_ / "out2";
  const Result run = pierre("run " + kData + "fail.toml --out '" + out2.string() + "'");
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(check(summary(out2), "North", "zone.crusher")["status"], "FAIL");
}

// --fail-on-warn gates a quarry's WARNs as a barrier's (pass.toml's rows WARN, none FAILs).
TEST_F(QuarryCli, FailOnWarnTurnsAWarningIntoExitOne) {
  const Result r = pierre("check " + kData + "pass.toml --out '" + (dir_ / "out").string() +
                          "' -q --fail-on-warn");
  EXPECT_EQ(r.code, 1) << r.err << r.out;
  const auto j = summary(dir_ / "out");
  EXPECT_EQ(j["checks_failed"], false);
  EXPECT_NE(r.err.find("Exit code 1 (--fail-on-warn): "), std::string::npos) << r.err;
}

// `check --quiet` prints the quarry table and the check lines only, starting with the table (it
// started with an empty line, meant to follow the run's table).
TEST_F(QuarryCli, QuietOutputStartsWithContent) {
  const Result r = pierre("check " + kData + "pass.toml --out '" + (dir_ / "out").string() + "' --quiet");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  ASSERT_FALSE(r.out.empty());
  EXPECT_NE(r.out.front(), '\n') << r.out;
  EXPECT_EQ(r.out.find("\n\n\n"), std::string::npos) << r.out;
}

// The "Average /H" lines are means of the rows' ratios: under the n column (counts of blocks)
// they printed the number of rows averaged. Now n is blank, and a note says why, and why P99 is.
TEST_F(QuarryCli, TheAverageLineHasNoCountOfItsOwn) {
  const Result r = pierre("check " + kData + "pass.toml --out '" + (dir_ / "out").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  std::istringstream in(r.out);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  auto at = [&](const std::string& start) {
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].rfind(start, 0) == 0) return i;
    return lines.size();
  };
  const std::size_t head = at("row "), avg = at("Average /H ");
  ASSERT_LT(head, lines.size()) << r.out;
  ASSERT_LT(avg, lines.size()) << r.out;
  // The n column: the header's "n", right-aligned; the average line has nothing under it.
  // (from the end of the label to the end of the header's "n").
  const std::size_t n_end = lines[head].find(" n ") + 2, n_begin = std::string("Average /H").size();
  ASSERT_LT(n_end, lines[avg].size());
  EXPECT_EQ(lines[avg].substr(n_begin, n_end - n_begin).find_first_not_of(' '), std::string::npos)
      << "\n" << lines[head] << "\n" << lines[avg];
  // ... and a line after the table explains the blank n and the blank P99.
  const std::size_t note = at("Average /H:");
  ASSERT_LT(note, lines.size()) << r.out;
  EXPECT_GT(note, avg);
  std::string text = lines[note] + (note + 1 < lines.size() ? lines[note + 1] : "");
  EXPECT_NE(text.find("P99"), std::string::npos) << text;
  EXPECT_NE(text.find(" n "), std::string::npos) << text;
  const auto j = summary(dir_ / "out");
  EXPECT_NE(lines[note].find(std::to_string(j["quarry_average"]["rows"].get<int>()) + " rows"),
            std::string::npos)
      << lines[note];
}

// sample.size of a quarry row gives, like a barrier's, the throws per block and source it asks
// for: the throws of the run times (half-width / tolerance)², as the trajectories.
TEST_F(QuarryCli, SampleSizeSaysTheThrowsNeeded) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "pass.toml --out '" + out.string() + "' --throws 20 -q");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const auto j = summary(out);
  const auto& l = check(j, "North", "sample.size");
  ASSERT_EQ(l["status"], "WARN") << l << " (the test needs a sample too small)";
  const std::string reason = l["reason"].get<std::string>();
  std::smatch m;
  ASSERT_TRUE(std::regex_search(reason, m, std::regex(R"(about (\d+) trajectories would be needed \((\d+) run\), i\.e\. throws = (\d+) per block and source)")))
      << reason;
  const double factor = std::pow(l["value"].get<double>() / l["limit"].get<double>(), 2);
  EXPECT_EQ(std::stoull(m[2].str()), 40u);  // 2 blocks x 20 throws
  EXPECT_NEAR(std::stod(m[1].str()), std::ceil(40 * factor), 1) << reason;
  EXPECT_NEAR(std::stod(m[3].str()), std::ceil(20 * factor), 1) << reason;
  EXPECT_NE(r.out.find(reason), std::string::npos) << r.out;  // printed under the table
}

// A toe given far out on the floor, past where every block stops: no block reaches the floor,
// so there is no ID and no first-impact zone. The console says "none", not "[0, -] m", and
// "ID_gov -", not "- the profile".
TEST_F(QuarryCli, NoFirstImpactIsSaidAsNone) {
  std::string text = slurp(kData + "pass.toml");
  const std::string toe = "toe = 22.0";
  text.replace(text.find(toe), toe.size(), "toe = 85.0");
  std::ofstream(dir_ / "far-toe.toml") << text;
  const Result r = pierre("run '" + (dir_ / "far-toe.toml").string() + "' --out '" +
                          (dir_ / "out").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = summary(dir_ / "out");
  ASSERT_EQ(j["quarries"][1]["name"], "South");
  ASSERT_EQ(j["quarries"][1]["first_impact"]["count"], 0) << "the test needs no first impact";
  EXPECT_NE(r.out.find("from the toe, danger zone [0, 0.00] m, first-impact zone none (no values)"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ID_gov - (P95: no values)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("- the profile"), std::string::npos) << r.out;
}

// ID is measured from a block's first contact with the floor (design-checks.md §2), which the
// first impact (on the face) is not: trajectories.csv gives it, so ID can be recomputed block by
// block, ID = max(0, floor_contact_x_m - toe x), and it does: its ID_m and RD_m columns are
// checked against the distances recomputed from the floor contact and the stop point. Recomputed, it has the section's ID statistics
// of summary.json; the blocks without a floor contact are those it counts as not reaching the
// floor, and each of them stopped above the toe (on the bench or the face) or left the section.
TEST_F(QuarryCli, TheFloorContactColumnsGiveTheFirstImpactDistances) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("run " + kData + "floor-contact.toml --out '" + out.string() + "' -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = summary(out);

  std::istringstream csv(slurp(out / "trajectories.csv"));
  auto cells = [](const std::string& line) {  // no quoted cells in this file
    std::vector<std::string> v;
    std::string cell;
    for (std::istringstream in(line); std::getline(in, cell, ',');) v.push_back(cell);
    if (!line.empty() && line.back() == ',') v.emplace_back();
    return v;
  };
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line,
            "section,trajectory,source,block_id,throw,mass_kg,start_x_m,start_z_m,stop_x_m,"
            "stop_z_m,runout_m,stop_reason,duration_s,impacts,first_impact_x_m,first_impact_z_m,"
            "floor_contact_x_m,floor_contact_z_m,ID_m,RD_m,max_jump_height_m,max_speed_m_s,"
            "max_energy_kJ");
  const std::vector<std::string> head = cells(line);
  auto col = [&](const char* name) {
    return static_cast<std::size_t>(std::find(head.begin(), head.end(), name) - head.begin());
  };
  const std::size_t c_section = col("section"), c_fx = col("floor_contact_x_m"),
                    c_fz = col("floor_contact_z_m"), c_stop = col("stop_x_m"),
                    c_reason = col("stop_reason"), c_id = col("ID_m"), c_rd = col("RD_m");

  const double toe_x = 20.0;  // the foot of the face's lower part, as the geometry finds it
  std::vector<double> id;
  int not_reached = 0, rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    const std::vector<std::string> row = cells(line);
    ASSERT_EQ(row.size(), head.size()) << line;
    EXPECT_EQ(row[c_section], "Benched");
    const std::string &fx = row[c_fx], &fz = row[c_fz];
    EXPECT_EQ(fx.empty(), fz.empty()) << line;
    EXPECT_EQ(fx.empty(), row[c_id].empty()) << line;
    // RD from the stop point: 0 at or above the toe; inf for a block that left at the runout end.
    const double stop = std::stod(row[c_stop]);
    if (row[c_reason] == "boundary" && stop > toe_x) {
      EXPECT_EQ(row[c_rd], "inf") << line;
    } else {
      EXPECT_NEAR(std::stod(row[c_rd]), std::max(0.0, stop - toe_x), 1e-6) << line;
    }
    if (fx.empty()) {
      ++not_reached;
      // Not on the floor: stopped above the toe, or left the section.
      if (row[c_reason] != "boundary") {
        EXPECT_LE(std::stod(row[c_stop]), toe_x) << line;
      }
      continue;
    }
    EXPECT_GE(std::stod(fx), toe_x) << line;  // on the floor, past the toe
    id.push_back(std::max(0.0, std::stod(fx) - toe_x));
    EXPECT_NEAR(std::stod(row[c_id]), id.back(), 1e-6) << line;
  }
  EXPECT_EQ(rows, 200);  // 2 blocks × 100 throws

  const auto& sec = j["quarries"][0]["sections"][0];
  ASSERT_EQ(sec["name"], "Benched");
  EXPECT_DOUBLE_EQ(sec["geometry"]["toe"]["x_m"].get<double>(), toe_x);
  // The test needs both kinds of block: some held on the bench, some reaching the floor.
  ASSERT_GT(not_reached, 0);
  ASSERT_GT(id.size(), 1u);
  EXPECT_EQ(sec["not_reached_floor"], not_reached);
  EXPECT_EQ(sec["reached_floor"], id.size());
  const auto& stats = sec["first_impact"];
  EXPECT_EQ(stats["count"], id.size());
  // Type 7 percentiles (R's default), as summary.json's; within 1e-6 m of the run's doubles, as
  // the CSV has 9 significant digits.
  std::sort(id.begin(), id.end());
  auto percentile = [&](double p) {
    const double h = static_cast<double>(id.size() - 1) * p;
    const auto lo = static_cast<std::size_t>(h);
    const std::size_t hi = std::min(lo + 1, id.size() - 1);
    return id[lo] + (h - static_cast<double>(lo)) * (id[hi] - id[lo]);
  };
  EXPECT_NEAR(stats["max_m"].get<double>(), id.back(), 1e-6);
  EXPECT_NEAR(stats["p50_m"].get<double>(), percentile(0.50), 1e-6);
  EXPECT_NEAR(stats["p95_m"].get<double>(), percentile(0.95), 1e-6);
}

TEST_F(QuarryCli, BadQuarryInputExitsTwoAndWritesNothing) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "bad.toml --out '" + out.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.toml:36: quarries[1].work_areas[0].distance: found -5.0"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(pierre("run " + kData + "bad.toml --out '" + out.string() + "'").code, 2);
  EXPECT_EQ(pierre("validate " + kData + "bad.toml").code, 2);
  EXPECT_FALSE(fs::exists(out));
}

// --throws on a quarry scenario is held to the reader's limit of 2^53 trajectories a section.
// It was not: 4400 sources × 1e6 blocks × 4294967295 throws wrapped past 2^64 and the run ended
// in an "internal error" (exit 3).
TEST_F(QuarryCli, ThrowsOptionIsHeldToTheTrajectoryLimitOfASection) {
  std::string sources;
  for (int i = 0; i < 4400; ++i) sources += (i ? ", " : "") + std::string("{ x = 10.3, z = 20.5 }");
  const std::string text =
      "[scenario]\nname = \"many\"\n[simulation]\nseed = 1\nthrows = 1\n"
      "[materials.face]\npreset = \"quarry-face\"\n[materials.floor]\npreset = \"quarry-floor\"\n"
      "[[quarries]]\nname = \"North\"\n"
      "profile = { points = [[0.0, 20.0, \"floor\"], [10.0, 20.0, \"face\"], [20.0, 0.0, \"floor\"], "
      "[90.0, 0.0, \"\"]] }\n"
      "blocks = { table = [{ mass = 500.0, count = 1000000 }] }\n"
      "sources = [" + sources + "]\n";
  std::ofstream(dir_ / "many.toml") << text;
  ASSERT_EQ(pierre("validate " + q(dir_ / "many.toml")).code, 0);  // 4.4e9 trajectories
  expect_refused_before_writing(
      dir_ / "many.toml", "--throws 4294967295",
      (dir_ / "many.toml").string() +
          ": --throws: found 4294967295, expected at most 2^53 trajectories a section "
          "(quarries[0] \"North\": 4400 sources × 1000000 blocks × 4294967295 throws are 1.89e+19)");
}

// The sections run one after the other, but their statistics are kept together: --throws is held
// to what the memory holds of all their trajectories (8 bytes each at the least), even when each
// section alone would fit.
TEST_F(QuarryCli, ThrowsOptionIsHeldToTheMemoryOfAllSectionsTogether) {
  // This machine's RAM, as the program reads it (sysconf).
  const std::optional<double> memory =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  ASSERT_GT(*memory, 0);
  // pass.toml: North 2 blocks, South 1, one source each: 3 trajectories a throw.
  const auto throws = static_cast<std::uint64_t>(*memory / 8 / 3) + 1;
  if (throws > 4294967295u) GTEST_SKIP() << "a machine of more than 100 GB";
  const std::string t = std::to_string(throws);
  expect_refused_before_writing(
      kData + "pass.toml", "--throws " + t,
      kData + "pass.toml: --throws: found " + t +
          fmt::format(", expected fewer than {:.3g} trajectories, the most this machine's {:.1f} "
                      "GB of memory could hold even at the 8 bytes the statistics keep of each at "
                      "the least (its runout; a run keeps more) (quarries[0] \"North\": 1 sources "
                      "× 2 blocks × {} throws are {:.3g}; quarries[1] \"South\": 1 sources × 1 "
                      "blocks × {} throws are {:.3g}; {:.3g} in all)",
                      *memory / 8, *memory / 1e9, throws, 2.0 * throws, throws, 1.0 * throws,
                      3.0 * throws));
}

// A work area typed in cm (6500 for 65 m) lies far past the section's floor: the reader notes
// it, and its zone line, which passes on it, is a WARN naming the input; the other section's
// lines are untouched.
TEST_F(QuarryCli, AWorkAreaTheReaderDoubtsDoesNotPass) {
  std::string text = slurp(kData + "pass.toml");
  const std::string right = "distance = 65.0";
  ASSERT_NE(text.find(right), std::string::npos);
  text.replace(text.find(right), right.size(), "distance = 6500.0");
  std::ofstream(dir_ / "cm.toml") << text;
  const fs::path good = dir_ / "good", slip = dir_ / "slip";
  ASSERT_EQ(pierre("check " + kData + "pass.toml --out '" + good.string() + "' -q").code, 0);
  const Result r = pierre("check '" + (dir_ / "cm.toml").string() + "' --out '" + slip.string() + "' -q");
  EXPECT_EQ(r.code, 0) << r.err;
  const auto g = summary(good), b = summary(slip);
  ASSERT_EQ(g["checks"].size(), b["checks"].size());
  std::size_t doubted = 0;
  for (std::size_t i = 0; i < b["checks"].size(); ++i) {
    const auto& c = b["checks"][i];
    SCOPED_TRACE(c.dump());
    const bool area = c["subject"] == "North" && c["id"].get<std::string>().starts_with("zone.");
    if (!area) {
      EXPECT_EQ(c["status"], g["checks"][i]["status"]);
      continue;
    }
    ++doubted;
    EXPECT_EQ(g["checks"][i]["status"], "PASS");
    EXPECT_EQ(c["status"], "WARN");
    EXPECT_NE(c["reason"].get<std::string>().find(", but it rests on quarries[0].work_areas[0].distance, "
                                                  "noted as a likely slip"),
              std::string::npos);
  }
  EXPECT_EQ(doubted, 1u);
}

// A mass in tonnes in one section's blocks bears on that section's lines only: the other
// section is simulated from its own blocks. Pooled in one group, the slip reaches every line,
// since the group's row and each of its sections take their zones from the pooled blocks.
TEST_F(QuarryCli, ASectionsSlipDoubtsItsOwnLinesAndItsGroupsOnly) {
  const std::string text = slurp(kData + "pass.toml");
  const std::string right = "id = \"C\", mass = 1000.0";  // the second section's one block
  ASSERT_NE(text.find(right), std::string::npos);
  std::string slipped = text;
  slipped.replace(slipped.find(right), right.size(), "id = \"C\", mass = 1.0");  // in tonnes
  auto pooled = [](std::string t) {
    for (const char* name : {"name = \"North\"", "name = \"South\""}) {
      const auto k = t.find(name);
      if (k == std::string::npos) throw std::runtime_error(name);
      t.insert(k + std::string(name).size(), "\ngroup = \"Both\"");
    }
    return t;
  };
  struct Case {
    std::string name, text;
  };
  for (const Case& c : {Case{"lone", text}, Case{"lone-slip", slipped}, Case{"pooled", pooled(text)},
                        Case{"pooled-slip", pooled(slipped)}}) {
    std::ofstream(dir_ / (c.name + ".toml")) << c.text;
    const Result r = pierre("check '" + (dir_ / (c.name + ".toml")).string() + "' --out '" +
                            (dir_ / c.name).string() + "' -q");
    ASSERT_EQ(r.code, 0) << c.name << r.err;
    if (c.name.ends_with("slip")) {
      EXPECT_NE(r.err.find("quarries[1].blocks.table[0].mass: the heaviest block, \"C\", weighs 1 kg"),
                std::string::npos)
          << r.err;
    }
  }
  const std::string doubt =
      ", but it rests on quarries[1].blocks.table[0].mass, noted as a likely slip";
  auto doubted = [&](const nlohmann::json& c) {
    return c["reason"].get<std::string>().find(doubt) != std::string::npos;
  };
  // Apart: North's lines are those of the run without the slip; South's cannot pass.
  const auto g = summary(dir_ / "lone"), b = summary(dir_ / "lone-slip");
  ASSERT_EQ(g["checks"].size(), b["checks"].size());
  std::size_t north = 0, south_doubted = 0;
  for (std::size_t i = 0; i < b["checks"].size(); ++i) {
    const auto& c = b["checks"][i];
    SCOPED_TRACE(c.dump());
    if (c["subject"] == "North") {
      ++north;
      EXPECT_EQ(c["status"], g["checks"][i]["status"]);
      EXPECT_EQ(c["reason"], g["checks"][i]["reason"]);
    } else {
      EXPECT_NE(c["status"], "PASS");
      south_doubted += doubted(c);
    }
  }
  EXPECT_GT(north, 0u);
  EXPECT_GT(south_doubted, 0u);
  // Pooled: North's lines passed without the slip and rest on it now.
  const auto gp = summary(dir_ / "pooled"), bp = summary(dir_ / "pooled-slip");
  std::size_t north_passed = 0;
  for (const auto& c : gp["checks"]) north_passed += c["subject"] == "North" && c["status"] == "PASS";
  EXPECT_GT(north_passed, 0u);
  std::size_t north_doubted = 0;
  for (const auto& c : bp["checks"]) {
    SCOPED_TRACE(c.dump());
    EXPECT_NE(c["status"], "PASS");
    north_doubted += c["subject"] == "North" && doubted(c);
  }
  EXPECT_GT(north_doubted, 0u);
}

TEST_F(QuarryCli, ValidateListsTheSections) {
  const Result r = pierre("validate " + kData + "pass.toml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("a quarry scenario of 2 sections"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("quarry section \"North\": 4 vertices"), std::string::npos) << r.out;
  // The blocks' masses and density, where a unit slip would show (pass.toml's rows: A 500 kg,
  // B 2000 kg at 2650 kg/m³; C 1000 kg).
  EXPECT_NE(r.out.find("2 blocks in 2 groups (500 to 2000 kg, density 2650 kg/m³)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1 block in 1 group (1000 kg, density 2650 kg/m³)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("toe x = 20.00 m (found)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("toe x = 22.00 m (given)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("H = 20.00 m (found)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("600 trajectories"), std::string::npos) << r.out;
  // The work areas by name and distance (pass.toml: crusher 65 m, office 60 m).
  EXPECT_NE(r.out.find("1 work area (crusher 65 m from the toe)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 work area (office 60 m from the toe)"), std::string::npos) << r.out;
}

TEST_F(QuarryCli, SameSeedSameResultsWhateverTheThreads) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(pierre("check " + kData + "pass.toml --out '" + a.string() + "' -q --threads 1").code, 0);
  ASSERT_EQ(pierre("check " + kData + "pass.toml --out '" + b.string() + "' -q --threads 2").code, 0);
  auto ja = summary(a), jb = summary(b);
  EXPECT_EQ(ja["threads"], 1);
  EXPECT_EQ(jb["threads"], 2);
  ja.erase("threads");
  jb.erase("threads");
  EXPECT_EQ(ja, jb);
  EXPECT_EQ(slurp(a / "trajectories.csv"), slurp(b / "trajectories.csv"));
}

TEST_F(QuarryCli, SeedOptionMovesEverySectionWithoutItsOwnSeed) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(pierre("run " + kData + "pass.toml --out '" + out.string() + "' -q --seed 500 --throws 20").code, 0);
  const auto j = summary(out);
  EXPECT_EQ(j["seed"], 500);
  EXPECT_EQ(j["quarries"][0]["sections"][0]["seed"], 500);
  EXPECT_EQ(j["quarries"][1]["sections"][0]["seed"], 501);
  EXPECT_EQ(j["quarries"][0]["thrown"], 40);
}

// The report's Inputs sheet of a quarry scenario: a table of the sections' inputs (the work
// areas and their distances, the bench width, the rule set) and no "Observation lines" heading
// over an empty table (a quarry scenario has no observation lines).
TEST_F(QuarryCli, TheInputsSheetListsTheSectionsAndNoEmptyLineTable) {
  PIERRE_NEED_PROGRAM("soffice");
  const fs::path out = dir_ / "out";
  ASSERT_EQ(pierre("run " + kData + "pass.toml --out '" + out.string() + "' --throws 5 -q").code, 0);
  const auto e = pierre::test::export_sheets(out / "report.xlsx", dir_);
  ASSERT_EQ(e.exec.status, 0) << e.exec.output;
  ASSERT_TRUE(e.sheets.count("Inputs"));
  const pierre::test::Sheet& s = e.sheets.at("Inputs");
  const pierre::io::ReportTemplate tpl = pierre::io::load_report_template(PIERRE_SOURCE_DIR "/templates/report.toml");
  EXPECT_FALSE(pierre::test::find_row(s, 0, tpl.get("titles", "observation_lines")))
      << "an Observation lines table in a quarry scenario";
  const auto title = pierre::test::find_row(s, 0, tpl.get("titles", "quarry_inputs"));
  ASSERT_TRUE(title);
  const auto j = summary(out);
  for (const auto& row : j["quarries"])
    for (const auto& sec : row["sections"]) {
      const std::string name = sec["name"].get<std::string>();
      const auto k = pierre::test::find_row(s, 0, name, *title);
      ASSERT_TRUE(k) << name;
      EXPECT_EQ(s[*k][2].text, row["rules"]["name"].get<std::string>()) << name;
      for (const auto& w : sec["work_areas"]) {
        const std::string areas = s[*k][10].text;
        EXPECT_NE(areas.find(w["name"].get<std::string>()), std::string::npos) << areas;
      }
    }
  const auto north = pierre::test::find_row(s, 0, "North", *title);
  ASSERT_TRUE(north);
  const auto bench = pierre::test::number(s, *north, 9);
  ASSERT_TRUE(bench) << pierre::test::dump(s, *north);
  EXPECT_EQ(*bench, 40.0);  // bench_width of pass.toml
  EXPECT_NE(s[*north][10].text.find("crusher 65 m"), std::string::npos) << s[*north][10].text;
}

// The README's example of `pierre check` on examples/quarry-austria names every line that FAILs
// (it named one of three).
TEST_F(QuarryCli, TheReadmeNamesEveryFailOfTheAustrianExample) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check '" + kExample + "' --out '" + out.string() + "' -q");
  ASSERT_EQ(r.code, 1) << r.err;
  const std::string readme = slurp(PIERRE_SOURCE_DIR "/README.md");
  const auto begin = readme.find("pierre check examples/quarry-austria/scenario.toml");
  ASSERT_NE(begin, std::string::npos);
  const std::string paragraph = readme.substr(begin, readme.find("\n\n", begin) - begin);
  int fails = 0;
  const auto j = summary(out);
  for (const auto& c : j["checks"]) {
    if (c["status"] != "FAIL") continue;
    ++fails;
    for (const char* key : {"subject", "id"})
      EXPECT_NE(paragraph.find(c[key].get<std::string>()), std::string::npos)
          << c[key] << " of a FAIL line is not in the README's paragraph:\n" << paragraph;
  }
  EXPECT_GT(fails, 0);
}

TEST_F(QuarryCli, TheAustrianExampleValidatesAndRuns) {
  const Result v = pierre("validate '" + kExample + "'");
  ASSERT_EQ(v.code, 0) << v.err;
  EXPECT_NE(v.out.find("a quarry scenario of 7 sections"), std::string::npos) << v.out;
  EXPECT_NE(v.out.find("quarry section \"Pauliberg B\" (group \"Pauliberg\")"), std::string::npos);
  const fs::path out = dir_ / "out";
  const Result r = pierre("run '" + kExample + "' --out '" + out.string() + "' --throws 2 -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = summary(out);
  ASSERT_EQ(j["quarries"].size(), 6u);  // Pauliberg A and B pooled into one row
  EXPECT_EQ(j["quarries"][1]["name"], "Pauliberg");
  EXPECT_EQ(j["quarries"][1]["pooled"], true);
  EXPECT_EQ(j["quarries"][1]["sections"].size(), 2u);
  EXPECT_EQ(j["quarries"][0]["thrown"], 97 * 2);
  EXPECT_EQ(j["quarry_average"]["rows"], 6);
  EXPECT_TRUE(j["quarries"][0]["observed"]["runout"]["p95_m"].is_number());
  // Per section and pooled (design-checks.md §2): each section's own counts add up to the row's,
  // and its maximum is at most the pooled one.
  const auto& pooled = j["quarries"][1];
  int n = 0;
  for (const auto& sec : pooled["sections"]) {
    n += sec["runout"]["count"].get<int>();
    EXPECT_LE(sec["runout"]["max_m"].get<double>(), pooled["runout"]["max_m"].get<double>());
  }
  EXPECT_EQ(n, pooled["runout"]["count"].get<int>());
  EXPECT_EQ(j["quarries"][0]["sections"][0]["runout"], j["quarries"][0]["runout"]);  // alone
}

}  // namespace
