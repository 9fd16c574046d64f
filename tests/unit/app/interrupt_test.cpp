// Ctrl-C during a run: the real `pierre` binary, started in the background and sent SIGINT
// (or SIGTERM, SIGHUP) while it simulates, exits 130 and leaves the output folder as it found it.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/cli_fixture.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const std::string kScenario = PIERRE_TEST_DATA "/small/scenario.toml";

class Interrupt : public pierre::test::PierreCli {
 protected:
  // Starts `pierre run` on the small scenario with enough throws to run for a long while and
  // waits until its staging folder exists (the run is under way). The signals start at their
  // default actions and unblocked, as from a terminal, whatever this test program inherited (a
  // CI job started in the background ignores SIGINT, and pierre rightly keeps a signal ignored
  // that it was started ignoring), except `ignored`, when given, which starts ignored (nohup).
  pid_t start_run(const fs::path& out, const std::string& scenario = kScenario,
                  const char* throws = "5000000", int ignored = 0) {
    const std::string bin = PIERRE_BINARY, err = (dir_ / "stderr.txt").string();
    std::vector<std::string> args{bin, "run", scenario, "--out", out.string(),
                                  "--throws", throws, "--threads", "2"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t defaults, none;
    sigemptyset(&defaults);
    for (const int s : {SIGINT, SIGTERM, SIGHUP})
      if (s != ignored) sigaddset(&defaults, s);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    // An ignored action is inherited through exec: ignore it here for the spawn only.
    struct sigaction ign {}, old {};
    ign.sa_handler = SIG_IGN;
    if (ignored) ::sigaction(ignored, &ign, &old);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, bin.c_str(), &fa, &attr, argv.data(), environ);
    if (ignored) ::sigaction(ignored, &old, nullptr);
    posix_spawnattr_destroy(&attr);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) return -1;
    // Its staging folder (a name of its own: .pierre-partial-XXXXXX).
    auto staging = [&] {
      std::error_code ec;
      for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().filename().string().rfind(".pierre-partial-", 0) == 0) return true;
      return false;
    };
    for (int i = 0; i < 3000 && !staging(); ++i) std::this_thread::sleep_for(10ms);
    staged_ = staging();
    std::this_thread::sleep_for(200ms);  // into the simulation
    return pid;
  }

  // Sends `sig` and returns the exit status, or -1 when it did not end within `wait`
  // (killed then).
  static int signal_and_wait(pid_t pid, int sig, std::chrono::milliseconds wait = 30s) {
    ::kill(pid, sig);
    int status = 0;
    for (auto waited = 0ms; waited < wait; waited += 10ms) {
      if (::waitpid(pid, &status, WNOHANG) == pid)
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      std::this_thread::sleep_for(10ms);
    }
    return -1;
  }
  static void kill_and_reap(pid_t pid) {
    int status = 0;
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }

  int run_and_signal(const fs::path& out, int sig, const std::string& scenario = kScenario,
                     const char* throws = "5000000") {
    const pid_t pid = start_run(out, scenario, throws);
    if (pid < 0) return -2;
    const int code = signal_and_wait(pid, sig);
    if (code == -1) kill_and_reap(pid);
    return code;
  }
  bool staged_ = false;
};

TEST_F(Interrupt, CtrlCOrAHangUpExits130AndRemovesTheFolderItCreated) {
  for (const int sig : {SIGINT, SIGHUP}) {
    const fs::path out = dir_ / ("out-" + std::to_string(sig));
    const int code = run_and_signal(out, sig);
    ASSERT_TRUE(staged_) << "the run never started";
    EXPECT_EQ(code, 130) << sig;
    EXPECT_FALSE(fs::exists(out)) << sig;
    const std::string err = pierre::test::slurp(dir_ / "stderr.txt");
    EXPECT_NE(err.find("interrupted: the run was stopped; nothing was written to " + out.string()),
              std::string::npos)
        << err;
  }
}

// A quarry scenario runs its sections one after the other, each a run of its own: a signal
// during one of them ends the whole and leaves nothing either.
TEST_F(Interrupt, AQuarryRunStopsAsWell) {
  const fs::path out = dir_ / "quarry";
  const int code = run_and_signal(out, SIGINT,
                                  PIERRE_SOURCE_DIR "/examples/quarry-austria/scenario.toml", "500000");
  ASSERT_TRUE(staged_) << "the run never started";
  EXPECT_EQ(code, 130);
  EXPECT_FALSE(fs::exists(out));
  const std::string err = pierre::test::slurp(dir_ / "stderr.txt");
  EXPECT_NE(err.find("interrupted: the run was stopped; nothing was written to " + out.string()),
            std::string::npos)
      << err;
}

TEST_F(Interrupt, SigtermLeavesAnExistingFolderAsItWas) {
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "mine\n";
  const int code = run_and_signal(out, SIGTERM);
  ASSERT_TRUE(staged_) << "the run never started";
  EXPECT_EQ(code, 130);
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(out)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"notes.txt"});
  EXPECT_EQ(pierre::test::slurp(out / "notes.txt"), "mine\n");
}

// timeout(1), and a CI runner cancelling a job, send SIGTERM to the process and then to its
// process group: the same request twice, a moment apart. It must still stop cleanly (before,
// the second one took the default action and left the staging folder behind).
TEST_F(Interrupt, ASigtermDeliveredTwiceAtOnceStillStopsCleanly) {
  const fs::path out = dir_ / "out";
  const pid_t pid = start_run(out);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(staged_) << "the run never started";
  ::kill(pid, SIGTERM);
  // A millisecond apart: the first has been handled (the two did not merge into one pending
  // signal) and the stop is under way.
  std::this_thread::sleep_for(1ms);
  const int code = signal_and_wait(pid, SIGTERM);
  if (code == -1) kill_and_reap(pid);
  EXPECT_EQ(code, 130);
  EXPECT_FALSE(fs::exists(out));
}

// Started under nohup (SIGHUP ignored), a run goes on when its terminal closes; Ctrl-C or
// SIGTERM still stops it.
TEST_F(Interrupt, ARunStartedUnderNohupIgnoresAHangUp) {
  const fs::path out = dir_ / "out";
  const pid_t pid = start_run(out, kScenario, "5000000", SIGHUP);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(staged_) << "the run never started";
  const int after_hangup = signal_and_wait(pid, SIGHUP, 500ms);
  EXPECT_EQ(after_hangup, -1) << "a hang-up ended a run started under nohup";
  const int code = after_hangup == -1 ? signal_and_wait(pid, SIGTERM) : after_hangup;
  if (code == -1) kill_and_reap(pid);
  EXPECT_EQ(code, 130);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
