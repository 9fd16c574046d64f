// Ctrl-C (SIGINT), SIGTERM and SIGHUP (the terminal closed) during a run. The first one asks
// the simulation to stop after the chunks under way; the command then discards its staging
// folder, so nothing half-written is left in the output folder, and exits with
// kExitInterrupted. Another one more than a second later ends the program at once; one sooner
// is taken for the same request delivered twice (timeout(1) signals the process and then its
// process group).
#pragma once

#include <atomic>

namespace pierre::app {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // puts the previous ones back
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Set by the handler; hand it to sim::RunOptions::stop.
  const std::atomic<bool>* flag() const;
  bool interrupted() const;
};

}  // namespace pierre::app

namespace pierre::app {

// Says on stderr that the run was interrupted and nothing was written to `out`; returns
// kExitInterrupted.
int report_interrupted(const char* out);

}  // namespace pierre::app
