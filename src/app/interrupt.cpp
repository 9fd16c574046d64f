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
  // A signal ignored when pierre started stays ignored (nohup, a background job of a script).
  auto take = [&](int sig, struct sigaction* old) {
    sigaction(sig, nullptr, old);
    if (old->sa_handler != SIG_IGN) sigaction(sig, &sa, nullptr);
  };
  take(SIGINT, &g_old_int);
  take(SIGTERM, &g_old_term);
  take(SIGHUP, &g_old_hup);  // the terminal closed under a run
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
  // fputs: after a hang-up stderr may be gone, and this must not throw.
  std::fputs(fmt::format("interrupted: the run was stopped; nothing was written to {}\n", out).c_str(),
             stderr);
  return kExitInterrupted;
}

}  // namespace pierre::app
