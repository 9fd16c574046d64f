// The bootstraps' resamples shared out over threads. Every resample draws from its own
// counter-based stream (ResampleIndexStream: keyed by the seed, counted by the resample), so
// its replicate is the same number whichever thread computes it: any thread count gives the
// same replicates, bit for bit.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace pierre::stats {

// Calls work(first, last) on contiguous blocks that cover [0, count) once, one block per
// thread (at most `threads`, the calling thread among them; 0 or 1: all on the caller's). When
// no more threads can be started the remaining blocks run on the caller's thread. An exception
// from a block (bad_alloc) is rethrown once every block has ended.
template <class Work>
void for_resample_blocks(std::size_t count, unsigned threads, Work&& work) {
  const std::size_t t = std::max<std::size_t>(1, std::min<std::size_t>(threads, count));
  std::vector<std::exception_ptr> errors(t);
  const auto block = [&](std::size_t i) {
    try {
      work(count * i / t, count * (i + 1) / t);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  std::size_t started = 1;
  for (; started < t; ++started) {
    try {
      pool.emplace_back(block, started);
    } catch (const std::system_error&) {
      break;  // no thread to be had: the rest below, one after the other
    }
  }
  block(0);
  for (std::size_t i = started; i < t; ++i) block(i);
  for (std::thread& th : pool) th.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace pierre::stats
