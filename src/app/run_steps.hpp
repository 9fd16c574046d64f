// Steps `pierre run` and `pierre check` take alike for a plain and for a quarry scenario.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "pierre/io/output_folder.hpp"
#include "pierre/io/report_template.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/io/scenario_reader.hpp"

namespace pierre::app {

// The worker threads a run uses: `requested` (--threads; 0: every hardware thread), at least
// one and no more than `chunks`, the most chunks any one simulation of the run hands out.
unsigned threads_used(unsigned requested, std::uint64_t chunks);

// The output folder, staged until commit (io::OutputFolder); null, with the reason on stderr,
// when it cannot be made.
std::unique_ptr<io::OutputFolder> open_output_folder(const std::string& out);

// summary.json's account of the run: the scenario as loaded (seed and throws after --seed and
// --throws), what was run, and the report layout among the inputs.
io::RunInfo run_info(const io::LoadedScenario& loaded, std::uint64_t trajectories,
                     std::uint64_t blocks, std::uint64_t sources, unsigned threads,
                     bool all_crossings, bool impacts, const io::ReportTemplate& layout);

// LoadedScenario::overrides for --seed and --throws, worded with the file's values: call it
// before they are applied.
std::vector<std::string> command_line_overrides(const io::LoadedScenario& loaded,
                                                std::optional<std::uint64_t> seed,
                                                std::optional<std::uint32_t> throws);

// Applies --seed and --throws: the seed and throws of [simulation]; in a quarry scenario also
// every section's throws, and the seed of each section that gives none (seed + its index, as
// the reader sets it; a section's own `seed` is kept). Throws io::InputError (at --throws)
// when the throws give the scenario, or a section, more trajectories than the reader allows.
void apply_command_line_overrides(io::LoadedScenario& loaded, std::optional<std::uint64_t> seed,
                                  std::optional<std::uint32_t> throws);

}  // namespace pierre::app
