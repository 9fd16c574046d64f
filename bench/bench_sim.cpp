// Throughput of the simulator (issue: speed is measured here, never asserted in tests).
//
//   build/bench/bench_sim [--quick]
//
// For each shipped example, on one thread and on all threads: trajectories/s and impacts/s of
// the simulation alone (summaries and crossings kept in memory, no text output), the same for
// a whole `pierre run` with its files written, the bare impact-law loop (random draws +
// restitution + Goldsmith on a fixed plane: the limit the simulator approaches), the same
// loop with each impact fed the one before (the latency a serial trajectory cannot hide), that
// loop with each rebound flown back onto the plane (the least a serial trajectory does), the
// quarry section subdivided into collinear pieces to 10 000 vertices, and peak memory.
#include <fmt/core.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "pierre/io/scenario_reader.hpp"
#include "pierre/sim/random_stream.hpp"
#include "pierre/sim/runner.hpp"
#include "plain_simulator.hpp"
#include "subdivided.hpp"

using namespace pierre;
namespace fs = std::filesystem;

namespace {

double now() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

struct Rate {
  double traj_per_s, impacts_per_s, seconds;
  double mean_stop_x = 0;  // m: what the yardstick's stop points are compared with
};

Rate simulate(const sim::Scenario& s, unsigned threads) {
  sim::ResultCollector sink;
  sim::RunOptions o;
  o.threads = threads;
  const double t0 = now();
  const auto rep = sim::run_simulation(s, o, sink);
  const double dt = now() - t0;
  double sum = 0;
  for (const auto& t : sink.trajectories) sum += t.stop.x;
  const double n = static_cast<double>(sink.trajectories.size());
  return {rep.trajectories / dt, rep.impacts / dt, dt, n > 0 ? sum / n : 0.0};
}

// Three runs, sorted by rate: the median stands for the code and the range is printed, so that
// one run slowed by the shared machine (another process, a frequency step) does not.
struct Rates {
  Rate slowest, median, fastest;
};
template <class Run>
Rates three_runs(Run run) {
  Rate r[3] = {run(), run(), run()};
  std::sort(std::begin(r), std::end(r),
            [](const Rate& a, const Rate& b) { return a.traj_per_s < b.traj_per_s; });
  return {r[0], r[1], r[2]};
}

// The plain yardstick (plain_simulator.hpp) on one thread.
Rate plain(const sim::Scenario& s) {
  bench::PlainSimulator p(s);
  const double t0 = now();
  const auto r = p.run();
  const double dt = now() - t0;
  return {r.trajectories / dt, r.impacts / dt, dt, r.mean_stop_x};
}

// One impact setting for both loops: the first material, the first block, the first segment
// as a fixed plane, a throw at 12 m/s along it and 6 m/s into it.
struct PlaneImpact {
  explicit PlaneImpact(const sim::Scenario& s)
      : law(s.settings.roughness, s.settings.stop_head_factor, s.settings.gravity),
        surf(law.surface(s.materials.front())),
        blk(law.block(s.blocks.front())),
        seg(s.profile.segment(0)),
        rng(s.settings.seed, 0),
        v_throw(12.0 * seg.d - 6.0 * seg.n) {}
  model::ImpactOutcome resolve(geometry::Vec2 v, double omega) {
    return law.resolve(v, omega, seg, surf, blk, rng.impact_draws());
  }
  model::ImpactLaw law;
  model::SurfaceConstants surf;
  model::BlockConstants blk;
  geometry::Segment seg;
  sim::RandomStream rng;
  geometry::Vec2 v_throw;
};

// The loops are kept out of main (noinline) so that callgrind counts each on its own:
//   valgrind --tool=callgrind --toggle-collect='*_loop*' build/bench/bench_sim --quick
[[gnu::noinline]] double bare_impact_loop(const sim::Scenario& s, long n) {
  PlaneImpact pi(s);
  double sink = 0;
  const double t0 = now();
  for (long i = 0; i < n; ++i) {
    const auto r = pi.resolve(pi.v_throw, 1.5);
    sink += r.v.x + r.omega;
  }
  const double dt = now() - t0;
  if (sink == 42.0) fmt::print("");  // keep the loop
  return n / dt;
}

// The same loop with each impact depending on the one before, as in a trajectory (a fresh
// throw when the block stops or slides). The independent loop above lets the processor overlap
// many impacts; a trajectory cannot. How the rebound becomes the next incoming velocity:
// - Next::mirror: it is turned back onto the plane (the latency a serial trajectory cannot hide);
// - Next::flight: it is flown back onto the fixed plane in closed form (time of flight
//   2 v_n / (g n_z)), a block bouncing down an endless uniform slope. No contact search, no
//   observation lines, no summary: what any serial simulator must do per impact at the least.
enum class Next { mirror, flight };
template <Next kNext>
[[gnu::noinline]] double chained_impact_loop(const sim::Scenario& s, long n) {
  PlaneImpact pi(s);
  const double g = s.settings.gravity;
  geometry::Vec2 v = pi.v_throw;
  double omega = 1.5, sink = 0;
  const double t0 = now();
  for (long i = 0; i < n; ++i) {
    const auto r = pi.resolve(v, omega);
    const double vn = dot(r.v, pi.seg.n);
    if (r.result != model::ImpactResult::rebound || vn < 0.5) {
      v = pi.v_throw;
      omega = 1.5;
    } else {
      if constexpr (kNext == Next::mirror) {
        v = r.v - 2.0 * vn * pi.seg.n;
      } else {
        const double t = 2.0 * vn / (g * pi.seg.n.z);
        v = {r.v.x, r.v.z - g * t};
      }
      omega = r.omega;
    }
    sink += v.x;
  }
  const double dt = now() - t0;
  if (sink == 42.0) fmt::print("");  // keep the loop
  return n / dt;
}

double peak_rss_mb() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc == 2 && std::string(argv[1]) == "--quick";
  if (argc > 2 || (argc == 2 && !quick)) {
    std::string found;
    for (int i = 1; i < argc; ++i) {
      if (i > 1) found += ' ';
      found += argv[i];
    }
    fmt::print(stderr, "usage: bench_sim [--quick]   (found: {})\n", found);
    return 2;
  }
  const fs::path root = PIERRE_SOURCE_DIR;
  const unsigned all = std::max(1u, std::thread::hardware_concurrency());
  fmt::print("pierre bench_sim — {} hardware threads{}\n\n", all, quick ? " (quick)" : "");

  struct Case {
    const char* name;
    std::uint32_t throws;
  };
  const Case cases[] = {{"quarry-preg", quick ? 4000u : 40000u}, {"vaujany-2d", quick ? 200u : 2000u}};
  for (const Case& c : cases) {
    const fs::path file = root / "examples" / c.name / "scenario.toml";
    auto loaded = io::load_scenario(file, root / "rules");
    sim::Scenario s = loaded.scenario;
    s.settings.throws = c.throws;
    fmt::print("== {} : {} trajectories, {} profile vertices\n", c.name, s.trajectory_count(),
               s.profile.vertices().size());
    const Rates one = three_runs([&] { return simulate(s, 1); });
    const Rate r1 = one.median;
    fmt::print("  simulation, 1 thread   : {:>10.0f} trajectories/s {:>11.0f} impacts/s ({:.2f} impacts/trajectory; median of 3 runs, {:.0f}-{:.0f} trajectories/s)\n",
               r1.traj_per_s, r1.impacts_per_s, r1.impacts_per_s / r1.traj_per_s,
               one.slowest.traj_per_s, one.fastest.traj_per_s);
    const Rates many = three_runs([&] { return simulate(s, all); });
    const Rate rn = many.median;
    fmt::print("  simulation, {} threads  : {:>10.0f} trajectories/s {:>11.0f} impacts/s (x{:.2f}; median of 3 runs, {:.0f}-{:.0f} trajectories/s)\n",
               all, rn.traj_per_s, rn.impacts_per_s, rn.traj_per_s / r1.traj_per_s,
               many.slowest.traj_per_s, many.fastest.traj_per_s);
    const Rates yard = three_runs([&] { return plain(s); });
    fmt::print("  plain implementation   : {:>10.0f} trajectories/s {:>11.0f} impacts/s (linear segment scan, mt19937, std::normal_distribution; median of 3); simulator/plain = {:.2f}; mean stop x {:.2f} m against the simulator's {:.2f} m\n",
               yard.median.traj_per_s, yard.median.impacts_per_s,
               r1.traj_per_s / yard.median.traj_per_s, yard.median.mean_stop_x, r1.mean_stop_x);
    const double bare = bare_impact_loop(s, quick ? 2'000'000 : 20'000'000);
    fmt::print("  bare impact-law loop   : {:>10.0f} impacts/s; simulator/bare = {:.2f}\n", bare,
               r1.impacts_per_s / bare);
    const double chained = chained_impact_loop<Next::mirror>(s, quick ? 2'000'000 : 20'000'000);
    fmt::print("  chained impact-law loop: {:>10.0f} impacts/s (each impact waits for the one before); simulator/chained = {:.2f}\n",
               chained, r1.impacts_per_s / chained);
    const double plane = chained_impact_loop<Next::flight>(s, quick ? 2'000'000 : 20'000'000);
    fmt::print("  plane trajectory loop  : {:>10.0f} impacts/s (chained, each rebound flown back onto the plane); plane/bare = {:.2f}, simulator/plane = {:.2f}\n",
               plane, plane / bare, r1.impacts_per_s / plane);
    if (std::string(c.name) == "quarry-preg") {
      const sim::Scenario fine = bench::subdivided(s, 10000);
      const Rate rf = simulate(fine, 1);
      fmt::print("  subdivided to {} vertices, 1 thread: {:>10.0f} trajectories/s; cost x{:.2f} of the original\n",
                 fine.profile.vertices().size(), rf.traj_per_s, r1.traj_per_s / rf.traj_per_s);
    }
    // A whole run with its files written, through the command line, one and all threads.
    for (unsigned th : {1u, all}) {
      const fs::path out = fs::temp_directory_path() / fmt::format("pierre-bench-{}-{}", c.name, th);
      fs::remove_all(out);
      // Its notes on stderr (quiet runs send them there) are kept, and shown only if it fails.
      const fs::path err = out.string() + ".stderr";
      const std::string cmd = fmt::format(
          "\"{}\" run \"{}\" --out \"{}\" --throws {} --threads {} --quiet > /dev/null 2> \"{}\"",
          PIERRE_BINARY, file.string(), out.string(), c.throws, th, err.string());
      const double t0 = now();
      const int rc = std::system(cmd.c_str());
      const double dt = now() - t0;
      fmt::print("  pierre run, {} thread(s): {:>10.0f} trajectories/s (exit {}, {:.2f} s)\n", th,
                 s.trajectory_count() / dt, rc, dt);
      if (rc != 0)
        if (std::FILE* f = std::fopen(err.c_str(), "r")) {
          char buf[512];
          while (std::fgets(buf, sizeof buf, f)) fmt::print("    {}", buf);
          std::fclose(f);
        }
      fs::remove(err);
      fs::remove_all(out);
    }
  }
  fmt::print("\npeak resident memory of this benchmark: {:.0f} MB\n", peak_rss_mb());
  return 0;
}
