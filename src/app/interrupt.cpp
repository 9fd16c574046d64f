#include "interrupt.hpp"

#include <signal.h>

#include <cstdint>
#include <cstdio>
#include <ctime>

#include <fmt/format.h>

#include "commands.hpp"

namespace pierre::app {
namespace {

// Written from a signal handler: only lock-free atomics may be touched there.
static_assert(std::atomic<bool>::is_always_lock_free);
static_assert(std::atomic<std::int64_t>::is_always_lock_free);
std::atomic<bool> g_interrupted{false};
std::atomic<std::int64_t> g_first_ns{0};  // when the first request came (CLOCK_MONOTONIC)
struct sigaction g_old_int, g_old_term, g_old_hup;

// A repeat this soon after the first request is the same request delivered twice: timeout(1)
// and a CI runner's cancel signal the process and then its whole process group, and a second
// signal must not turn their clean stop into an end that leaves the staging folder behind.
constexpr std::int64_t kRepeatWindowNs = 1'000'000'000;

extern "C" void on_interrupt(int sig) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe, as are signal() and raise()
  const std::int64_t ns = std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
  if (!g_interrupted.exchange(true, std::memory_order_relaxed)) {
    g_first_ns.store(ns, std::memory_order_relaxed);
    return;
  }
  if (ns - g_first_ns.load(std::memory_order_relaxed) < kRepeatWindowNs) return;
  // A second request: the default action, the program ends at once.
  signal(sig, SIG_DFL);
  raise(sig);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_interrupted.store(false);
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  // The three are blocked while the handler runs, so that it is never entered twice at once.
  sigemptyset(&sa.sa_mask);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, sig);
  sa.sa_flags = 0;
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
