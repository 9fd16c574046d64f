#include "interrupt.hpp"

#include <signal.h>

#include <cstdio>

#include <fmt/format.h>

#include "commands.hpp"

namespace pierre::app {
namespace {

// Written from a signal handler: only a lock-free atomic may be touched there.
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> g_interrupted{false};
struct sigaction g_old_int, g_old_term, g_old_hup;

extern "C" void on_interrupt(int) { g_interrupted.store(true, std::memory_order_relaxed); }

}  // namespace

InterruptGuard::InterruptGuard() {
  g_interrupted.store(false);
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;  // a second signal takes the default action: the program ends
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
  sigaction(SIGHUP, &sa, &g_old_hup);  // the terminal closed under a run
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
  sigaction(SIGHUP, &g_old_hup, nullptr);
}

const std::atomic<bool>* InterruptGuard::flag() const { return &g_interrupted; }

bool InterruptGuard::interrupted() const { return g_interrupted.load(std::memory_order_relaxed); }

int report_interrupted(const char* out) {
  std::fflush(stdout);
  fmt::print(stderr, "interrupted: the run was stopped; nothing was written to {}\n", out);
  return kExitInterrupted;
}

}  // namespace pierre::app
