// The sub-commands of `pierre`. Each registers itself on the main CLI11 app and runs when it
// was selected; adding one (e.g. `pierre check`) means one more make_*_command() and one more
// line in main.cpp's list. `pierre check` is `pierre run` with the check exit code.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

namespace pierre::app {

// Exit codes (architecture.md): 0 ran, 1 a check failed, 2 bad input or usage, 3 internal;
// and the shell's 128 + SIGINT when a run was interrupted (nothing written).
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;
inline constexpr int kExitInput = 2;
inline constexpr int kExitInternal = 3;
inline constexpr int kExitInterrupted = 130;

class Command {
 public:
  virtual ~Command() = default;
  // Adds the sub-command and its options to `parent`; returns it.
  virtual CLI::App* add_to(CLI::App& parent) = 0;
  // Runs after a successful parse when this sub-command was chosen; returns the exit code.
  // May throw io::InputError (exit 2) or anything else (exit 3).
  virtual int run() = 0;
};

std::unique_ptr<Command> make_run_command();
std::unique_ptr<Command> make_check_command();  // `run` that exits 1 when a check fails
std::unique_ptr<Command> make_validate_command();

}  // namespace pierre::app
