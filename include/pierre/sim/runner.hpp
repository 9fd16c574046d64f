// The Monte Carlo runner: trajectories in fixed chunks over worker threads, results handed to a
// sink in trajectory order, so every output is the same for any thread count (model-2d.md §6;
// library-notes.md: reduce in trajectory order, never in thread order).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pierre/sim/results.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::sim {

struct RunOptions {
  unsigned threads = 0;          // 0: every hardware thread
  bool record_impacts = false;   // keep the per-impact records (large)
  bool all_crossings = false;    // every crossing, not only the first in the main direction
  std::uint32_t chunk_size = 512;  // trajectories per unit of work
  // When set (by another thread, or a signal handler at the edge), no further chunk starts and
  // the run returns early with RunReport::interrupted.
  const std::atomic<bool>* stop = nullptr;
};

// What a sink made of a chunk before its turn came (ResultSink::prepare), carried with it.
struct PreparedChunk {
  virtual ~PreparedChunk() = default;
};

// One chunk of consecutive trajectories and what they produced, in trajectory order.
struct ChunkResult {
  std::uint64_t first = 0;  // global index of the first trajectory
  std::vector<TrajectorySummary> trajectories;
  std::vector<Crossing> crossings;
  std::vector<ImpactRecord> impacts;
  std::unique_ptr<PreparedChunk> prepared;  // set by ResultSink::prepare, if the sink has one
};

// Receives chunks strictly in trajectory order, one at a time (never concurrently).
class ResultSink {
 public:
  virtual ~ResultSink() = default;
  // Called once before the first chunk with the number of trajectories the run will deliver.
  virtual void expect(std::uint64_t /*trajectories*/) {}
  // Called by the worker that made the chunk, before its turn, concurrently with other chunks'
  // prepare and with consume: work that does not depend on order (the CSV text) is done here on
  // every thread, not only on the one delivering. It may only read the sink, and write
  // chunk.prepared. A sink that hands chunks on to another passes this on too.
  virtual void prepare(ChunkResult& /*chunk*/) const {}
  virtual void consume(ChunkResult&& chunk) = 0;
};

// Keeps everything in memory (tests, benchmarks, small runs).
class ResultCollector : public ResultSink {
 public:
  void expect(std::uint64_t trajectories) override;
  void consume(ChunkResult&& chunk) override;
  std::vector<TrajectorySummary> trajectories;
  std::vector<Crossing> crossings;
  std::vector<ImpactRecord> impacts;
};

struct RunReport {
  std::uint64_t trajectories = 0;
  std::uint64_t impacts = 0;
  double seconds = 0;  // wall-clock time of the simulation (measured by the caller's clock)
  // A sink failure, reported instead of thrown across threads; or a scenario_fault, in which
  // case nothing was run.
  std::optional<std::string> error;
  bool out_of_memory = false;  // the error was an allocation that failed (std::bad_alloc)
  std::uint64_t delivered = 0;  // trajectories the sink received, in order, before it stopped
  bool interrupted = false;  // RunOptions::stop was set before every chunk was delivered
};

// Called after each delivered chunk with (done, total); from a worker thread, never concurrently.
using Progress = std::function<void(std::uint64_t, std::uint64_t)>;

RunReport run_simulation(const Scenario& scenario, const RunOptions& options, ResultSink& sink,
                         const Progress& progress = {});

}  // namespace pierre::sim
