// `pierre run` with stderr on a terminal (a pseudo-terminal here): the progress bar is drawn,
// the steps after the simulation say what they do, and the line is erased before the results;
// with --quiet, or when stderr is not a terminal (cli_test), nothing is drawn.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "support/cli_fixture.hpp"

namespace {

namespace fs = std::filesystem;

struct TerminalRun {
  int code = -1;
  std::string terminal;  // what pierre wrote to stderr, the terminal
  std::string out;       // stdout, sent to a file
};

class Terminal : public pierre::test::PierreCli {
 protected:
  TerminalRun run_on_terminal(std::vector<std::string> args) {
    const fs::path out_file = dir_ / "stdout.txt";
    args.insert(args.begin(), PIERRE_BINARY);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    TerminalRun r;
    int master = -1;
    const pid_t pid = ::forkpty(&master, nullptr, nullptr, nullptr);
    if (pid < 0) return r;
    if (pid == 0) {  // the child: stdin and stderr the terminal, stdout a file
      const int fd = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd < 0 || ::dup2(fd, 1) < 0) ::_exit(126);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    char buf[4096];
    for (;;) {  // until the child closes the terminal (EIO) or ends
      const ssize_t n = ::read(master, buf, sizeof buf);
      if (n <= 0) break;
      r.terminal.append(buf, static_cast<std::size_t>(n));
    }
    ::close(master);
    int status = 0;
    ::waitpid(pid, &status, 0);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = pierre::test::slurp(out_file);
    return r;
  }
};

const std::string kVaujany = PIERRE_SOURCE_DIR "/examples/vaujany-2d/scenario.toml";

TEST_F(Terminal, TheBarAndTheStepsAfterTheSimulationAreShownThenErased) {
  const TerminalRun r = run_on_terminal(
      {"run", kVaujany, "--out", (dir_ / "out").string(), "--throws", "20", "--threads", "1"});
  ASSERT_EQ(r.code, 0) << r.terminal << r.out;
  // The bar is drawn at least once, when the last chunk is in.
  EXPECT_NE(r.terminal.find("100.0%"), std::string::npos) << r.terminal;
  EXPECT_NE(r.terminal.find("trajectories/s  ETA"), std::string::npos) << r.terminal;
  // vaujany-2d has barriers: their bootstraps, then the files.
  const auto stats = r.terminal.find("\rstatistics and the barriers' bootstraps ...");
  const auto files = r.terminal.find("\rwriting summary.json and report.xlsx ...");
  ASSERT_NE(stats, std::string::npos) << r.terminal;
  ASSERT_NE(files, std::string::npos) << r.terminal;
  EXPECT_LT(r.terminal.find("100.0%"), stats);
  EXPECT_LT(stats, files);
  // Erased at the end: the last thing on the terminal is a blank line with the cursor at its
  // start, so the results on stdout begin on a clean line.
  const std::string blank = "\r" + std::string(79, ' ') + "\r";
  ASSERT_GE(r.terminal.size(), blank.size());
  EXPECT_EQ(r.terminal.substr(r.terminal.size() - blank.size()), blank);
  EXPECT_NE(r.out.find("trajectories in"), std::string::npos) << r.out;
}

TEST_F(Terminal, QuietDrawsNothing) {
  const TerminalRun r = run_on_terminal({"run", kVaujany, "--out", (dir_ / "out").string(),
                                         "--throws", "20", "--threads", "1", "--quiet"});
  ASSERT_EQ(r.code, 0) << r.terminal;
  // No bar, no steps: only the run's notes, which quiet sends to stderr (Vaujany's energy stops
  // on talus steeper than its friction angle), each line ended by the terminal's CR LF.
  EXPECT_EQ(r.terminal.find("%"), std::string::npos) << r.terminal;
  EXPECT_EQ(r.terminal.find(" ..."), std::string::npos) << r.terminal;
  EXPECT_EQ(r.terminal.rfind("Note: ", 0), 0u) << r.terminal;
  for (std::size_t at = r.terminal.find('\r'); at != std::string::npos; at = r.terminal.find('\r', at + 1))
    EXPECT_EQ(r.terminal.compare(at, 2, "\r\n"), 0) << "a CR that draws over a line, at " << at;
  EXPECT_EQ(r.out, "");
}

}  // namespace
