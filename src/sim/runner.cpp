#include "pierre/sim/runner.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <new>
#include <map>
#include <mutex>
#include <system_error>
#include <thread>

#include "pierre/sim/trajectory.hpp"

namespace pierre::sim {

// The summaries' final size is known: one allocation instead of a doubling vector that copies
// everything it holds each time it grows (about a tenth of a million-trajectory run's time).
// The crossings are left to grow: their count is not known, and a bound reserved up front cost
// more than the growth it saved (measured).
void ResultCollector::expect(std::uint64_t n) { trajectories.reserve(trajectories.size() + n); }

void ResultCollector::consume(ChunkResult&& c) {
  trajectories.insert(trajectories.end(), c.trajectories.begin(), c.trajectories.end());
  crossings.insert(crossings.end(), c.crossings.begin(), c.crossings.end());
  impacts.insert(impacts.end(), c.impacts.begin(), c.impacts.end());
}

RunReport run_simulation(const Scenario& scenario, const RunOptions& options, ResultSink& sink,
                         const Progress& progress) {
  if (auto fault = scenario_fault(scenario)) {
    RunReport r;
    r.error = "the scenario cannot be simulated: " + *fault;
    return r;
  }
  const TrajectoryModel model(scenario);
  const std::uint64_t total = scenario.trajectory_count();
  const std::uint32_t throws = scenario.settings.throws;
  const auto n_blocks = static_cast<std::uint32_t>(scenario.blocks.size());
  const std::uint64_t chunk = std::max<std::uint32_t>(1, options.chunk_size);
  const std::uint64_t n_chunks = (total + chunk - 1) / chunk;
  unsigned threads = options.threads ? options.threads : std::thread::hardware_concurrency();
  threads = static_cast<unsigned>(std::clamp<std::uint64_t>(threads, 1, std::max<std::uint64_t>(1, n_chunks)));
  // Finished chunks wait here until every earlier one is delivered; a worker does not start a
  // chunk more than `window` ahead of delivery, so memory stays bounded.
  const std::uint64_t window = 4ull * threads;

  std::mutex mu;
  std::condition_variable cv;
  std::map<std::uint64_t, ChunkResult> pending;
  std::uint64_t next_claim = 0, next_deliver = 0, impacts = 0, delivered = 0;
  bool failed = false, delivering = false, out_of_memory = false;
  std::optional<std::string> error;

  auto stopped = [&] { return options.stop && options.stop->load(std::memory_order_relaxed); };
  auto worker = [&] {
    ObservationTally tally(scenario.lines, scenario.profile, options.all_crossings);
    while (true) {
      std::uint64_t c;
      {
        std::unique_lock lock(mu);
        cv.wait(lock, [&] {
          return failed || stopped() || next_claim < next_deliver + window || next_claim >= n_chunks;
        });
        if (failed || stopped() || next_claim >= n_chunks) return;
        c = next_claim++;
      }
      ChunkResult res;
      res.first = c * chunk;
      const std::uint64_t end = std::min(total, res.first + chunk);
      res.trajectories.resize(end - res.first);
      tally.output(&res.crossings);
      std::uint64_t n_imp = 0;
      // The key of trajectory i, stepped along rather than divided out of i every time.
      TrajectoryKey key = trajectory_key(scenario, res.first);
      for (std::uint64_t i = res.first; i < end; ++i) {
        TrajectorySummary& t = res.trajectories[i - res.first];
        simulate_trajectory(model, i, key, tally, options.record_impacts ? &res.impacts : nullptr, t);
        n_imp += t.impacts;
        if (++key.throw_index == throws) {
          key.throw_index = 0;
          if (++key.block == n_blocks) {
            key.block = 0;
            ++key.source;
          }
        }
      }
      sink.prepare(res);
      std::unique_lock lock(mu);
      impacts += n_imp;
      pending.emplace(c, std::move(res));
      // One worker at a time delivers, in chunk order, and does it without the lock: the sink
      // writes files, and the others go on simulating meanwhile instead of waiting for it.
      if (!delivering) {
        delivering = true;
        while (!failed && !pending.empty() && pending.begin()->first == next_deliver) {
          ChunkResult ready = std::move(pending.begin()->second);
          const std::uint64_t ready_size = ready.trajectories.size();
          pending.erase(pending.begin());
          lock.unlock();
          std::optional<std::string> failure;
          bool no_memory = false;
          try {
            sink.consume(std::move(ready));
          } catch (const std::bad_alloc& e) {
            failure = e.what();
            no_memory = true;
          } catch (const std::exception& e) {
            failure = e.what();
          }
          lock.lock();
          if (failure && !failed) {  // the first failure is the cause (as guarded() keeps it)
            error = failure;
            out_of_memory = no_memory;
          }
          if (failure)
            failed = true;
          else
            delivered += ready_size;
          ++next_deliver;
          if (progress && !failed) progress(std::min(total, next_deliver * chunk), total);
          cv.notify_all();  // the window moved on
        }
        delivering = false;
      }
      cv.notify_all();
    }
  };

  // No exception may leave a thread (std::terminate): a worker's failure (out of memory with
  // --impacts, a throwing progress callback) stops the others and is reported like a sink's.
  auto guarded = [&] {
    std::string what;
    bool no_memory = false;
    try {
      worker();
      return;
    } catch (const std::bad_alloc& e) {
      what = e.what();
      no_memory = true;
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
      what = "a worker thread failed";
    }
    const std::lock_guard lock(mu);
    if (!failed) {
      error = std::move(what);
      out_of_memory = no_memory;
    }
    failed = true;
    cv.notify_all();
  };

  sink.expect(total);
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < threads; ++i) {
    try {
      pool.emplace_back(guarded);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones running share the chunks
    }
  }
  guarded();
  for (auto& t : pool) t.join();

  RunReport rep;
  rep.trajectories = total;
  rep.impacts = impacts;
  rep.error = error;
  rep.out_of_memory = out_of_memory;
  rep.delivered = delivered;
  rep.interrupted = next_deliver < n_chunks && !failed;
  return rep;
}

}  // namespace pierre::sim
