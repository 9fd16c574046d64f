#include "run_steps.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <thread>

#include <fmt/format.h>

namespace pierre::app {

unsigned threads_used(unsigned requested, std::uint64_t chunks) {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::clamp<std::uint64_t>(requested ? requested : hw, 1,
                                                         std::max<std::uint64_t>(1, chunks)));
}

std::unique_ptr<io::OutputFolder> open_output_folder(const std::string& out) {
  try {
    return std::make_unique<io::OutputFolder>(out);
  } catch (const std::filesystem::filesystem_error& e) {
    std::error_code ec;
    const bool exists = std::filesystem::is_directory(out, ec);
    fmt::print(stderr, "error: cannot {} the output folder {}: {}\n",
               exists ? "write in" : "create", out, e.code().message());
    return nullptr;
  }
}

io::RunInfo run_info(const io::LoadedScenario& loaded, std::uint64_t trajectories,
                     std::uint64_t blocks, std::uint64_t sources, unsigned threads,
                     bool all_crossings) {
  io::RunInfo info;
  info.scenario_name = loaded.scenario.name;
  info.scenario_file = loaded.file;
  info.materials_file = loaded.materials_file;
  info.seed = loaded.scenario.settings.seed;
  info.throws = loaded.scenario.settings.throws;
  info.trajectories = trajectories;
  info.blocks = blocks;
  info.sources = sources;
  info.threads = threads;
  info.all_crossings = all_crossings;
  return info;
}

}  // namespace pierre::app
