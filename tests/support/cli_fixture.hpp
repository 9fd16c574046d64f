// Running the real `pierre` binary from a test: a fresh temporary folder per test, stdout and
// stderr captured, and small readers for what the binary writes. Shared by the app tests.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace pierre::test {

namespace fs = std::filesystem;

struct CliResult {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The part names of an xlsx (a zip), read with the unzip program (installed by the test
// set-up); empty when unzip is missing.
inline std::string zip_listing(const fs::path& xlsx) {
  const std::string cmd = "unzip -Z1 '" + xlsx.string() + "' 2>/dev/null";
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    ::pclose(p);
  }
  return out;
}

inline std::size_t count_of(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

class PierreCli : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> n{0};
    dir_ = fs::temp_directory_path() /
           ("pierre-cli-test-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `pierre ARGS` with stdout and stderr captured in files.
  CliResult pierre(const std::string& args) { return pierre_with_env("", args); }
  // The same with `env` ("NAME=value ...", quoted as the shell needs) set for the run.
  CliResult pierre_with_env(const std::string& env, const std::string& args) {
    const fs::path o = dir_ / "stdout.txt", e = dir_ / "stderr.txt";
    const std::string cmd = env + (env.empty() ? "'" : " '") + PIERRE_BINARY + "' " + args +
                            " >'" + o.string() + "' 2>'" + e.string() + "'";
    const int st = std::system(cmd.c_str());
    CliResult r;
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.out = slurp(o);
    r.err = slurp(e);
    return r;
  }
  static std::string q(const fs::path& p) {  // (built by appends: GCC 12 warns falsely on "'" + s)
    std::string s(1, '\'');
    s += p.string();
    s += '\'';
    return s;
  }
  // `pierre run` and `pierre check` of `scenario` with `options` both stop with exit 2, say
  // `message` on stderr, and leave no output folder.
  void expect_refused_before_writing(const fs::path& scenario, const std::string& options,
                                     const std::string& message) {
    const fs::path out = dir_ / "out";
    for (const char* command : {"run", "check"}) {
      const CliResult r =
          pierre(std::string(command) + " " + q(scenario) + " --out " + q(out) + " " + options);
      EXPECT_EQ(r.code, 2) << command << "\n" << r.err;
      EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(out)) << command;
    }
  }
  nlohmann::json summary(const fs::path& out) {
    return nlohmann::json::parse(slurp(out / "summary.json"));
  }

  fs::path dir_;
};

}  // namespace pierre::test
