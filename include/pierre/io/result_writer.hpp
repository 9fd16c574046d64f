// The run's result files, streamed as the runner delivers chunks (in trajectory order):
//
// trajectories.csv — one row per trajectory (model-2d.md §4):
//   trajectory,source,block_id,throw,mass_kg,start_x_m,start_z_m,stop_x_m,stop_z_m,runout_m,
//   stop_reason,duration_s,impacts,first_impact_x_m,first_impact_z_m,max_jump_height_m,
//   max_speed_m_s,max_energy_kJ
//   (trajectory: the global index that keys the random stream, from 0; throw from 0; the
//   first impact is empty when there was none)
// crossings.csv — one row per recorded crossing (model-2d.md §5):
//   trajectory,line,chainage_m,block_id,mass_kg,time_s,direction,vx_m_s,vz_m_s,speed_m_s,
//   omega_rad_s,translational_energy_kJ,rotational_energy_kJ,passing_height_m,sliding
//   (line: the observation line's name; direction +1 towards increasing x; sliding 0/1)
// impacts.csv (optional) — one row per impact (the thesis's TR file, model-2d.md §3 step 9):
//   trajectory,impact,time_s,x_m,z_m,segment,material,result,slope_deg,roughness_deg,r_eff_m,
//   vt_in_m_s,vn_in_m_s,vt_out_m_s,vn_out_m_s,vt_in_rot_m_s,vn_in_rot_m_s,vt_out_rot_m_s,
//   vn_out_rot_m_s,kn,kt,kn_apparent,kt_apparent,incidence_deg,contained,energy_in_kJ,
//   energy_out_kJ
//
// A quarry scenario (docs/quarry.md) writes the same files once for all its sections, one section
// after the other in file order, each row led by a `section` column (the section's name);
// `trajectory` then counts within the section (it keys the section's own random streams).
// Its trajectories.csv also has, after first_impact_z_m:
//   floor_contact_x_m,floor_contact_z_m — the first contact with the floor, from which ID is
//     measured (empty when the block never reached it);
//   ID_m — the first-impact distance from the toe (design-checks.md §2; empty as above);
//   RD_m — the runout distance from the toe: 0 for a block that stopped at or above the toe or
//     left the section at its source end, inf for one that left it at its runout end
//     (right-censored).
//
// Numbers are written with 9 significant digits ({:.9g}): the same seed gives the same bytes.
// Only what the statistics need stays in memory (design::RunSamples).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pierre/design/barrier_check.hpp"
#include "pierre/design/check_line.hpp"
#include "pierre/design/quarry_zones.hpp"
#include "pierre/design/run_statistics.hpp"
#include "pierre/io/document_control.hpp"
#include "pierre/io/input_error.hpp"
#include "pierre/io/input_files.hpp"
#include "pierre/io/output_folder.hpp"
#include "pierre/sim/runner.hpp"
#include "pierre/sim/scenario.hpp"

namespace pierre::io {

inline constexpr const char* kTrajectoriesCsv = "trajectories.csv";
inline constexpr const char* kCrossingsCsv = "crossings.csv";
inline constexpr const char* kImpactsCsv = "impacts.csv";
inline constexpr const char* kSummaryJson = "summary.json";
// summary.json's "schema_version" (docs/summary-json.md): raised when a key is renamed or
// removed, or its meaning changes; keys added leave it.
inline constexpr int kSummarySchemaVersion = 1;

// The first line of impacts.csv: plain, or led by the quarry section's column.
std::string impacts_csv_header(bool sectioned);
// impacts.csv as a result an earlier run may have left (OutputFolder::commit): pierre's when its
// first line is the header of either form. A field record of the user's by that name stays.
StaleResult stale_impacts_csv();

class ResultFiles final : public sim::ResultSink {
 public:
  // Opens the CSV files in `folder` and writes their headers; `impacts` adds impacts.csv.
  // `every_crossing`: the run records all crossings and the lines' statistics use them all
  // (design::RunSamples). Throws std::runtime_error when a file cannot be opened.
  ResultFiles(const std::filesystem::path& folder, const sim::Scenario& scenario, bool impacts,
              bool every_crossing = false);
  // The files of a quarry scenario: every row led by a `section` column. Call begin_section
  // before each section's chunks.
  ResultFiles(const std::filesystem::path& folder, bool impacts);
  ~ResultFiles() override;

  // The chunks that follow belong to `scenario`, named `name` in the section column, with its
  // crest and toe `geometry` (both of which it must outlive); samples() starts afresh.
  void begin_section(const sim::Scenario& scenario, std::string name,
                     const design::QuarryGeometry& geometry);

  // Formats the chunk's rows (on the worker thread; consume formats those that come without).
  void prepare(sim::ChunkResult& chunk) const override;
  void consume(sim::ChunkResult&& chunk) override;  // throws std::runtime_error on write errors
  // Flushes and closes every file; throws std::runtime_error when a write failed.
  void close();

  const design::RunSamples& samples() const { return samples_; }

  class Csv;  // a buffered file

 private:
  struct Text;
  void open(const std::filesystem::path& folder, bool impacts);
  std::unique_ptr<Text> format(const sim::ChunkResult& chunk) const;

  const sim::Scenario* scenario_ = nullptr;
  const design::QuarryGeometry* geometry_ = nullptr;  // a quarry section's
  bool sectioned_ = false;
  std::string section_;
  std::unique_ptr<Csv> trajectories_, crossings_, impacts_;
  design::RunSamples samples_;
};

// What summary.json says about the run besides the statistics.
struct RunInfo {
  std::string scenario_name;
  DocumentControl document;  // as given in [scenario]; the keys not given are left out
  std::filesystem::path scenario_file;
  std::filesystem::path materials_file;
  std::uint64_t seed = 0;
  std::uint32_t throws = 0;
  std::uint64_t trajectories = 0;
  std::uint64_t blocks = 0, sources = 0;
  unsigned threads = 0;  // worker threads used
  std::string command = "run";  // "run" or "check"
  bool strict = false;          // --strict: inputs in doubt were refused, so none is left
  bool fail_on_warn = false;    // --fail-on-warn: check's exit code takes WARN as FAIL
  bool all_crossings = false;
  bool impacts = false;  // impacts.csv written (--impacts)
  // The model as it ran: the [simulation] settings and the materials with their presets and
  // overrides resolved (in a quarry scenario, shared by every section).
  sim::SimulationSettings settings;
  std::vector<model::Material> materials;
  std::vector<std::string> overrides;  // LoadedScenario::overrides
  std::vector<InputNote> input_notes;  // LoadedScenario::notes: likely mistakes, not errors
  std::vector<InputFile> inputs;  // LoadedScenario::inputs and the report layout: every file read
};

// The design results of a run: every barrier computed, the quarry danger zones (a quarry
// scenario), and every check line (all subjects).
// A barrier whose line gave no design (too few crossings, no fit, no class): its FAIL line is
// among the checks; summary.json also lists it, so that a reader of "barriers" misses none.
struct BarrierWithoutDesign {
  std::string name, line;
  // The rule set's record, as a designed barrier's (BarrierDesign::rules_*).
  std::string rules_name, rules_title, rules_source, rules_file;
  double chainage = 0;          // m
  std::uint64_t crossings = 0;  // first crossings of the line
  std::string check_line;     // "reach" or "design"
  std::string reason;
};

struct DesignResults {
  std::vector<design::BarrierDesign> barriers;
  std::vector<BarrierWithoutDesign> barriers_without_design;
  std::optional<design::QuarryDesign> quarry;
  std::vector<std::uint64_t> quarry_seeds;  // the seed of each quarry section's run
  std::vector<design::CheckLine> checks;
};

// `pierre validate --json`: the verdict as a script reads it (docs/summary-json.md): valid or
// not, the error (file, line, field, found, expected, message) or null, the input notes as
// summary.json gives them, the trajectories to run (none when not valid) and the memory note.
// `error` null: valid.
// Bytes of a path that are not UTF-8 are replaced (the JSON writer would throw on them).
std::string validation_json(const std::filesystem::path& scenario, const InputError* error,
                            const std::vector<InputNote>& notes,
                            std::optional<std::uint64_t> trajectories,
                            const std::optional<std::string>& memory_note);

// summary.json's text (pretty-printed, NaN and infinity as null): the run, its inputs and model,
// its statistics, the design results and every check line. Every key is documented in
// docs/summary-json.md (a test holds the two together); kSummarySchemaVersion says when a
// parser must look again.
std::string summary_json(const RunInfo& info, const design::RunStatistics& stats,
                         const DesignResults& design = {});
void write_summary_json(const std::filesystem::path& file, const RunInfo& info,
                        const design::RunStatistics& stats, const DesignResults& design = {});

}  // namespace pierre::io
