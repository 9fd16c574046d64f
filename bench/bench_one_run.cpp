// One simulation of a shipped example on one thread, results kept in memory (as bench_sim's
// "simulation, 1 thread"), for counting instructions per impact:
//
//   valgrind --tool=callgrind --toggle-collect='*measured_run*' build/bench/bench_one_run quarry-preg 4000
//
// prints the trajectories and impacts of the run; divide callgrind's "Collected" by the impacts.
// A third argument, a vertex count, runs the section subdivided into collinear pieces to that
// many vertices (bench_sim's "subdivided"): `bench_one_run quarry-preg 4000 10000`.
#include <fmt/core.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "pierre/io/scenario_reader.hpp"
#include "pierre/sim/runner.hpp"
#include "subdivided.hpp"

using namespace pierre;

namespace {

// Kept out of main so that callgrind's --toggle-collect counts the simulation alone.
[[gnu::noinline]] sim::RunReport measured_run(const sim::Scenario& s) {
  sim::ResultCollector sink;
  sim::RunOptions o;
  o.threads = 1;
  return sim::run_simulation(s, o, sink);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    fmt::print(stderr,
               "usage: bench_one_run <example> <throws> [<vertices>]   (e.g. quarry-preg 4000)\n");
    return 2;
  }
  const std::filesystem::path root = PIERRE_SOURCE_DIR;
  const auto loaded =
      io::load_scenario(root / "examples" / argv[1] / "scenario.toml", root / "rules");
  sim::Scenario s = loaded.scenario;
  s.settings.throws = static_cast<std::uint32_t>(std::atoi(argv[2]));
  if (argc == 4) s = bench::subdivided(s, static_cast<std::size_t>(std::atol(argv[3])));
  const auto rep = measured_run(s);
  fmt::print("{} trajectories {} impacts\n", rep.trajectories, rep.impacts);
  return 0;
}
