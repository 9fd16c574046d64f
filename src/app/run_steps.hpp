// Steps `pierre run` and `pierre check` take alike for a plain and for a quarry scenario.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "pierre/io/output_folder.hpp"
#include "pierre/io/report_template.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/design/check_line.hpp"
#include "pierre/io/scenario_reader.hpp"

namespace pierre::app {

// The worker threads a run uses: `requested` (--threads; 0: every hardware thread), at least
// one and no more than `chunks`, the most chunks any one simulation of the run hands out.
unsigned threads_used(unsigned requested, std::uint64_t chunks);

// The output folder, staged until commit (io::OutputFolder); null, with the reason on stderr,
// when it cannot be made, or when a result would replace one of `inputs` (the files the run
// read) there.
std::unique_ptr<io::OutputFolder> open_output_folder(const std::string& out,
                                                     const std::vector<io::InputFile>& inputs);

// Commits the run's files (io::OutputFolder::commit, a stale impacts.csv removed when pierre
// wrote it) and says on stderr which file by a result's name was left alone, not being pierre's.
std::vector<std::filesystem::path> commit_results(io::OutputFolder& folder);

// The command and the flags that shape what it writes and how it exits (summary.json records
// them: a pipeline's gate must be readable from the results).
struct RunFlags {
  bool check = false;         // `pierre check` (else `run`)
  bool strict = false;        // --strict
  bool fail_on_warn = false;  // --fail-on-warn (check)
  bool all_crossings = false;  // --all-crossings
  bool impacts = false;        // --impacts
};

// The exit code once the results are in place: `run` 0; `check` 1 when a line FAILs, or WARNs
// with --fail-on-warn (then said on stderr, as the verdict's lines say only WARN), else 0.
int check_exit_code(const RunFlags& flags, const std::vector<design::CheckLine>& lines);

// summary.json's account of the run: the scenario as loaded (seed and throws after --seed and
// --throws), what was run, and the report layout among the inputs.
io::RunInfo run_info(const io::LoadedScenario& loaded, std::uint64_t trajectories,
                     std::uint64_t blocks, std::uint64_t sources, unsigned threads,
                     const RunFlags& flags, const io::ReportTemplate& layout);

// LoadedScenario::overrides for --seed and --throws, worded with the file's values: call it
// before they are applied.
std::vector<std::string> command_line_overrides(const io::LoadedScenario& loaded,
                                                std::optional<std::uint64_t> seed,
                                                std::optional<std::uint32_t> throws);

// Applies --seed and --throws: the seed and throws of [simulation]; in a quarry scenario also
// every section's throws, and the seed of each section that gives none (seed + its index, as
// the reader sets it; a section's own `seed` is kept). Throws io::InputError (at --throws)
// when the throws give the scenario, or a section, more trajectories than the reader allows.
// A note (LoadedScenario::notes) for each quarry section that runs with the seed of an
// earlier one (a section's own seed meeting another's [simulation] seed + index): the same
// random numbers, so not independent samples (new-user review). Called by
// apply_command_line_overrides; by `validate` for the file's seeds.
void note_shared_section_seeds(io::LoadedScenario& loaded);

void apply_command_line_overrides(io::LoadedScenario& loaded, std::optional<std::uint64_t> seed,
                                  std::optional<std::uint32_t> throws);

// Every trajectory the run makes: the scenario's, or all its quarry sections'.
std::uint64_t total_trajectories(const io::LoadedScenario& loaded);

// The memory of this machine (RAM, not swap), bytes; none when the system does not say.
std::optional<double> physical_memory_bytes();

// The run's count against this machine's memory, once --throws (`throws`, when given) is
// applied; all of a quarry's sections together, whose statistics are kept together. Not part of
// loading (a file is valid whatever machine reads it): `validate` says it as a note. Throws
// io::InputError (at --throws, or at simulation.throws) when even the 8 bytes every trajectory
// keeps (its runout) cannot be held; returns a note when the likely need is more than the
// machine has.
std::optional<std::string> check_run_memory(const io::LoadedScenario& loaded,
                                            std::optional<std::uint32_t> throws);

// What the input notes doubt (likely slips), for design::doubt_passes.
std::vector<design::DoubtedInput> doubted_inputs(const std::vector<io::InputNote>& notes);

// --strict: an input noted as a likely slip that [confirmed] does not confirm is an input error
// (io::InputError at the first such note, saying how many there are), so that a pipeline never
// runs, nor passes a check, on a value the program itself doubts.
void refuse_doubted_inputs(const io::LoadedScenario& loaded);
// Whether a note doubts its input (and [confirmed] does not confirm it).
bool any_in_doubt(const io::LoadedScenario& loaded);

// A run that ran out of memory: the statistics keep every trajectory's runout and every first
// crossing's values, so memory grows with the trajectories, and a count too large for what this
// process may use is a count to lower (exit 2, nothing written, as for other input).
class RunOutOfMemory : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Its message: how far the run got (`done` trajectories of `total` simulated; none: it ran out
// after the simulation, in the statistics or the report), that nothing was written to `out`, and
// the throws to lower, as the file or --throws set them.
std::string out_of_memory_message(const io::LoadedScenario& loaded, std::uint64_t total,
                                  std::optional<std::uint64_t> done, const std::string& out);

}  // namespace pierre::app
