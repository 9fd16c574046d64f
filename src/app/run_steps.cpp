#include "run_steps.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>

#include <fmt/format.h>
#include <unistd.h>

#include "commands.hpp"
#include "pierre/io/xlsx_report.hpp"

namespace pierre::app {

unsigned threads_used(unsigned requested, std::uint64_t chunks) {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::clamp<std::uint64_t>(requested ? requested : hw, 1,
                                                         std::max<std::uint64_t>(1, chunks)));
}

namespace {

// Why `out` cannot be the output folder, said as the other input errors are: the usual causes
// by name (no path, a file in the way), else the system's reason.
std::string output_folder_problem(const std::string& out, const std::error_code& code) {
  namespace fs = std::filesystem;
  if (out.empty()) return "--out: found an empty path, expected a folder";
  std::error_code ec;
  for (fs::path at = out; !at.empty(); at = at.parent_path()) {
    if (fs::exists(at, ec)) {  // the nearest part of the path that exists
      if (fs::is_directory(at, ec)) break;
      return at == fs::path(out)
                 ? fmt::format("--out: found {}, a file, expected a folder", out)
                 : fmt::format("--out: found {}, under the file {}, expected a folder", out,
                               at.string());
    }
    if (at == at.parent_path()) break;
  }
  const bool exists = fs::is_directory(out, ec);
  return fmt::format("--out: found {} ({}), expected a folder pierre can {}", out,
                     code.message(), exists ? "write in" : "create");
}

// The input of this run that a result in `out` would replace (or, impacts.csv, remove): a
// blocks CSV named crossings.csv with --out at the scenario's folder would be overwritten by
// the run that had just read it. Empty when there is none.
std::string result_over_input(const std::string& out, const std::vector<io::InputFile>& inputs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(out, ec)) return {};  // a folder made by the run holds no input
  // A path by its folder's canonical form and its own name: the same entry of a folder however
  // named (./x.csv, ../d/x.csv), a link included (renaming over it would replace the link).
  auto entry = [](const fs::path& p) {
    std::error_code e;
    const fs::path dir = fs::weakly_canonical(fs::absolute(p, e).parent_path(), e);
    return dir / p.filename();
  };
  for (const char* name : {io::kTrajectoriesCsv, io::kCrossingsCsv, io::kImpactsCsv,
                           io::kSummaryJson, io::kReportXlsx}) {
    const fs::path result = fs::path(out) / name;
    if (!fs::exists(fs::symlink_status(result, ec))) continue;
    for (const io::InputFile& in : inputs)
      if (entry(result) == entry(in.file) || fs::equivalent(result, in.file, ec))
        return fmt::format(
            "--out: found {}, where the result {} would replace {}, an input of this run; "
            "expected a folder that holds none of the run's inputs by a result's name "
            "(trajectories.csv, crossings.csv, impacts.csv, summary.json, report.xlsx): give "
            "another --out, or rename the input",
            out, name, in.file.string());
  }
  return {};
}

}  // namespace

std::unique_ptr<io::OutputFolder> open_output_folder(const std::string& out,
                                                     const std::vector<io::InputFile>& inputs) {
  if (const std::string clash = result_over_input(out, inputs); !clash.empty()) {
    fmt::print(stderr, "{}\n", clash);
    return nullptr;
  }
  try {
    return std::make_unique<io::OutputFolder>(out);
  } catch (const std::filesystem::filesystem_error& e) {
    // Said as the other input errors are (field, found, expected), with no prefix of its own.
    fmt::print(stderr, "{}\n", output_folder_problem(out, e.code()));
    return nullptr;
  }
}

std::vector<std::filesystem::path> commit_results(io::OutputFolder& folder) {
  auto written = folder.commit({io::stale_impacts_csv()});
  for (const auto& f : folder.kept())
    fmt::print(stderr,
               "Note: {} is left as it is: pierre did not write it (it is not a file that begins "
               "with pierre's header), and this run wrote no file of that name.\n",
               f.string());
  return written;
}

int check_exit_code(const RunFlags& flags, const std::vector<design::CheckLine>& lines) {
  if (!flags.check) return kExitOk;
  if (design::any_failure(lines)) return kExitCheckFailed;
  if (!design::any_failure(lines, flags.fail_on_warn)) return kExitOk;
  std::fflush(stdout);  // after the check lines it explains, in a log that takes both streams
  const std::size_t warns = design::count_status(lines, design::CheckStatus::warn);
  fmt::print(stderr, "Exit code 1 (--fail-on-warn): {} check line{} WARN.\n", warns,
             warns == 1 ? "" : "s");
  return kExitCheckFailed;
}

io::RunInfo run_info(const io::LoadedScenario& loaded, std::uint64_t trajectories,
                     std::uint64_t blocks, std::uint64_t sources, unsigned threads,
                     const RunFlags& flags, const io::ReportTemplate& layout) {
  io::RunInfo info;
  info.scenario_name = loaded.scenario.name;
  info.document = loaded.document;
  info.scenario_file = loaded.file;
  info.materials_file = loaded.materials_file;
  info.seed = loaded.scenario.settings.seed;
  info.throws = loaded.scenario.settings.throws;
  info.trajectories = trajectories;
  info.blocks = blocks;
  info.sources = sources;
  info.threads = threads;
  info.command = flags.check ? "check" : "run";
  info.strict = flags.strict;
  info.fail_on_warn = flags.fail_on_warn;
  info.all_crossings = flags.all_crossings;
  info.impacts = flags.impacts;
  info.settings = loaded.scenario.settings;
  info.materials = loaded.scenario.materials;
  info.overrides = loaded.overrides;
  info.input_notes = loaded.notes;
  info.inputs = loaded.inputs;
  info.inputs.push_back(layout.source);  // the report's layout shapes report.xlsx
  return info;
}

std::vector<std::string> command_line_overrides(const io::LoadedScenario& loaded,
                                                std::optional<std::uint64_t> seed,
                                                std::optional<std::uint32_t> throws) {
  const sim::SimulationSettings& s = loaded.scenario.settings;
  const bool own_seeds = std::any_of(loaded.quarries.begin(), loaded.quarries.end(),
                                     [](const io::QuarrySection& q) { return q.seed_given; });
  std::vector<std::string> out;
  if (seed)
    out.push_back(fmt::format("--seed {} (the scenario file's simulation.seed: {}{})", *seed,
                              s.seed, own_seeds ? "; sections with a seed of their own keep it" : ""));
  if (throws)
    out.push_back(fmt::format("--throws {} (the scenario file's simulation.throws: {})", *throws,
                              s.throws));
  return out;
}

void note_shared_section_seeds(io::LoadedScenario& loaded) {
  const auto& q = loaded.quarries;
  for (std::size_t j = 1; j < q.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      if (q[i].scenario.settings.seed != q[j].scenario.settings.seed) continue;
      auto how = [](const io::QuarrySection& s) {
        return s.seed_given ? "its own" : "[simulation] seed + its index";
      };
      loaded.notes.push_back(
          {loaded.file, 0, fmt::format("quarries[{}].seed", j),
           fmt::format("sections \"{}\" ({}) and \"{}\" ({}) both run with seed {}: their blocks "
                       "draw the same random numbers, so the two are not independent samples "
                       "(pooled, they count twice what one shows). Give one a seed of its own",
                       q[i].spec.name, how(q[i]), q[j].spec.name, how(q[j]),
                       q[j].scenario.settings.seed),
           {}});
      break;  // one note per section
    }
}

void apply_command_line_overrides(io::LoadedScenario& loaded, std::optional<std::uint64_t> seed,
                                  std::optional<std::uint32_t> throws) {
  sim::SimulationSettings& top = loaded.scenario.settings;
  if (seed) top.seed = *seed;
  if (throws) top.throws = *throws;
  if (loaded.quarries.empty()) {
    // The reader's limit, for the count the run will make (it wrapped, exit 3; or ran on).
    if (throws)
      io::check_trajectory_count(loaded.scenario, loaded.file, 0, "--throws", std::to_string(*throws));
    return;
  }
  for (std::size_t i = 0; i < loaded.quarries.size(); ++i) {
    sim::SimulationSettings& s = loaded.quarries[i].scenario.settings;
    if (seed && !loaded.quarries[i].seed_given) s.seed = io::section_seed(*seed, i);
    if (throws) {
      s.throws = *throws;
      io::check_trajectory_count(loaded.quarries[i].scenario, loaded.file, 0, "--throws",
                                 std::to_string(*throws),
                                 io::section_label(i, loaded.quarries[i].spec.name));
    }
  }
  note_shared_section_seeds(loaded);
}

std::uint64_t total_trajectories(const io::LoadedScenario& loaded) {
  if (loaded.quarries.empty()) return loaded.scenario.trajectory_count();
  std::uint64_t n = 0;
  for (const io::QuarrySection& s : loaded.quarries) n += s.scenario.trajectory_count();
  return n;
}

std::optional<double> physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::nullopt;
  return static_cast<double>(pages) * static_cast<double>(page);
}

std::optional<std::string> check_run_memory(const io::LoadedScenario& loaded,
                                            std::optional<std::uint32_t> throws) {
  const double n = static_cast<double>(total_trajectories(loaded));
  const auto memory = physical_memory_bytes();
  if (!memory) return std::nullopt;
  // A count no machine of this size can hold (a throws with zeros too many): said now, not after
  // hours of running. The least a trajectory keeps is its runout (a double), for the percentiles.
  constexpr double kLeast = 8;
  if (n * kLeast > *memory)
    throw io::InputError(
        loaded.file, throws ? 0 : loaded.throws_line, throws ? "--throws" : "simulation.throws",
        std::to_string(loaded.scenario.settings.throws),
        fmt::format("fewer than {:.3g} trajectories, the most this machine's {:.1f} GB of memory "
                    "could hold even at the {} bytes the statistics keep of each at the least "
                    "(its runout; a run keeps more) ({})",
                    *memory / kLeast, *memory / 1e9, kLeast,
                    loaded.quarries.empty() ? io::trajectory_count_text(loaded.scenario)
                                            : io::sections_count_text(loaded.quarries)));
  // What a run likely keeps: the runout (8 bytes) and each line's first crossing (4 doubles) of
  // every trajectory, a quarry's distances (4 doubles) instead of lines; up to twice that while a
  // vector grows. An estimate (blocks that miss a line keep less), said, not enforced.
  const double per = 8.0 + 32.0 * (loaded.quarries.empty()
                                       ? static_cast<double>(loaded.scenario.lines.size())
                                       : 1.0);
  const double likely = 2 * per * n;
  if (likely <= *memory) return std::nullopt;
  return fmt::format(
      "{} trajectories may need about {:.1f} GB of memory (the statistics keep each one's runout "
      "and first crossings, up to twice that while their vectors grow), more than this machine's "
      "{:.1f} GB: if the run runs out of memory, lower {}",
      static_cast<std::uint64_t>(n), likely / 1e9, *memory / 1e9,
      throws ? "--throws" : "simulation.throws");
}

namespace {
bool in_doubt(const io::InputNote& n) { return n.doubt.has_value(); }
}  // namespace

std::vector<design::DoubtedInput> doubted_inputs(const std::vector<io::InputNote>& notes) {
  std::vector<design::DoubtedInput> out;
  for (const io::InputNote& n : notes)
    if (n.doubt) out.push_back(*n.doubt);
  return out;
}

bool any_in_doubt(const io::LoadedScenario& loaded) {
  return io::doubted_count(loaded.notes) > 0;
}

void refuse_doubted_inputs(const io::LoadedScenario& loaded) {
  const auto first = std::find_if(loaded.notes.begin(), loaded.notes.end(), in_doubt);
  if (first == loaded.notes.end()) return;
  const auto n = std::count_if(loaded.notes.begin(), loaded.notes.end(), in_doubt);
  throw io::InputError(
      first->file, first->line, first->field, fmt::format("{}", first->doubt->value),
      fmt::format("the value corrected, or confirmed as meant under [confirmed] (--strict refuses "
                  "an input noted as a likely slip): {}{}",
                  first->text,
                  n > 1 ? fmt::format(" ({} more input{} in doubt, noted above)", n - 1, n > 2 ? "s" : "")
                        : std::string()));
}

std::string out_of_memory_message(const io::LoadedScenario& loaded, std::uint64_t total,
                                  std::optional<std::uint64_t> done, const std::string& out) {
  const bool by_option = std::any_of(loaded.overrides.begin(), loaded.overrides.end(),
                                     [](const std::string& o) { return o.starts_with("--throws "); });
  const std::uint32_t throws = loaded.scenario.settings.throws;
  const std::string where =
      by_option ? fmt::format("--throws {}", throws)
                : fmt::format("simulation.throws = {} in {}", throws, loaded.file.string());
  const std::string when =
      done ? fmt::format("after about {} of {} trajectories", *done, total)
           : fmt::format("after the {} trajectories were simulated, in their statistics or the report",
                         total);
  const char* kept = loaded.quarries.empty()
                         ? "every trajectory's runout and every first crossing of an observation "
                           "line in memory for the statistics (all crossings with --all-crossings)"
                         : "every trajectory's runout and distances from the toe in memory for "
                           "the statistics";
  return fmt::format("out of memory {}; nothing was written to {}. A run keeps {}: run fewer "
                     "trajectories, lowering {}",
                     when, out, kept, where);
}

}  // namespace pierre::app
