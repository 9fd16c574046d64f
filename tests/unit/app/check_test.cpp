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
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

const std::string kData = PIERRE_TEST_DATA "/barrier/";

struct Result {
  int code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class Check : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> n{0};
    dir_ = fs::temp_directory_path() /
           ("pierre-check-test-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Result pierre(const std::string& args) {
    const fs::path o = dir_ / "stdout.txt", e = dir_ / "stderr.txt";
    const std::string cmd = std::string("'") + PIERRE_BINARY + "' " + args + " >'" + o.string() +
                            "' 2>'" + e.string() + "'";
    const int st = std::system(cmd.c_str());
    Result r;
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.out = slurp(o);
    r.err = slurp(e);
    return r;
  }
  nlohmann::json summary(const fs::path& out) { return nlohmann::json::parse(slurp(out / "summary.json")); }

  fs::path dir_;
};

std::set<std::string> statuses(const nlohmann::json& checks) {
  std::set<std::string> s;
  for (const auto& c : checks) s.insert(c["status"].get<std::string>());
  return s;
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
  EXPECT_EQ(j["checks_failed"], false);
  ASSERT_EQ(j["barriers"].size(), 1u);
  const auto& b = j["barriers"][0];
  EXPECT_EQ(b["name"], "Generous");
  EXPECT_EQ(b["rules"]["name"], "thesis-2015");
  EXPECT_EQ(b["mode"], "check");
  // The requirement in summary.json is the limit of the check line.
  EXPECT_DOUBLE_EQ(b["MEL_req_kJ"].get<double>(), check(j, "energy.mel")["limit"].get<double>());
  EXPECT_DOUBLE_EQ(b["h_i_m"].get<double>(), check(j, "height.interception")["limit"].get<double>());
  EXPECT_DOUBLE_EQ(b["m_d_kg"].get<double>(), 1.0 * 2650 * 1.05);
  EXPECT_EQ(b["v_k_m_s"]["interval"]["resamples"], 1000);
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

TEST_F(Check, RunExitsZeroWhateverTheChecksSay) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("run " + kData + "fail.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("energy.mel"), std::string::npos);  // printed after the run table
  EXPECT_LT(r.out.find("Observation lines"), r.out.find("Checks"));
  EXPECT_EQ(check(summary(out), "energy.mel")["status"], "FAIL");
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
  EXPECT_NEAR(b["gamma_F"]["value"].get<double>(), 1.10 * 1.10, 1e-12);
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

TEST_F(Check, HelpShowsTheExitCodes) {
  const Result r = pierre("check --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("1 when one FAILs"), std::string::npos) << r.out;
}

}  // namespace

namespace {
// The part names of an xlsx (a zip), read with the unzip program (installed by the test set-up).
std::string zip_listing(const fs::path& xlsx) {
  const std::string cmd = "unzip -Z1 '" + xlsx.string() + "' 2>/dev/null";
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    ::pclose(p);
  }
  return out;
}
std::size_t count_of(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST_F(Check, WritesTheDesignReportWithABarrierSheetAndItsCharts) {
  const fs::path out = dir_ / "out";
  const Result r = pierre("check " + kData + "fail.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.code, 1) << r.err << r.out;
  ASSERT_TRUE(fs::is_regular_file(out / "report.xlsx"));
  const std::string parts = zip_listing(out / "report.xlsx");
  if (parts.empty()) GTEST_SKIP() << "the unzip program is missing";
  // Summary, Inputs, Profile, Trajectories, Crossings and one sheet for the one barrier.
  EXPECT_EQ(count_of(parts, "xl/worksheets/sheet"), 6u) << parts;
  // Six charts on the barrier sheet (3 histograms, 3 CDFs) and the profile.
  EXPECT_EQ(count_of(parts, "xl/charts/chart"), 7u) << parts;
}
