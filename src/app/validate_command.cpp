// pierre validate SCENARIO: every check of `run`, no simulation, a summary of one item a line.
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "commands.hpp"
#include "console.hpp"
#include "data_folders.hpp"
#include "report.hpp"
#include "run_steps.hpp"
#include "pierre/design/design_block.hpp"
#include "pierre/design/number_text.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/io/scenario_reader.hpp"

namespace pierre::app {
namespace {

// The blocks' masses and densities, "1500 to 3500 kg, density 2650 kg/m³": the numbers a unit
// slip shows in (t for kg, t/m³ for kg/m³) before a long run.
std::string block_ranges(const std::vector<model::Block>& blocks) {
  if (blocks.empty()) return "no blocks";
  double m_lo = blocks.front().mass, m_hi = m_lo, d_lo = blocks.front().density, d_hi = d_lo;
  for (const auto& b : blocks) {
    m_lo = std::min(m_lo, b.mass);
    m_hi = std::max(m_hi, b.mass);
    d_lo = std::min(d_lo, b.density);
    d_hi = std::max(d_hi, b.density);
  }
  auto range = [](double lo, double hi, const char* unit) {
    return lo == hi ? fmt::format("{} {}", design::number_text(lo), unit)
                    : fmt::format("{} to {} {}", design::number_text(lo), design::number_text(hi), unit);
  };
  return range(m_lo, m_hi, "kg") + ", density " + range(d_lo, d_hi, "kg/m³");
}

class ValidateCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& parent) override {
    CLI::App* c = parent.add_subcommand("validate", "Check a scenario without running it");
    c->add_option("scenario", scenario_, "Scenario file (TOML, docs/scenario-format.md)")
        ->required()
        ->type_name("FILE");
    c->add_option("--rules", rules_, "Rules folder holding materials.toml and the barrier and quarry rule sets")
        ->type_name("DIR");
    c->add_flag("--strict", strict_,
                "An input noted as a likely slip that [confirmed] does not confirm is an error "
                "(exit 2), as `run --strict` and `check --strict` make it; so is a run too large "
                "for this machine's memory, which `run` refuses");
    c->add_flag("--json", json_,
                "Print the verdict as JSON on stdout, for a script: valid, the error's file, line, "
                "field, found and expected, the input notes (docs/summary-json.md)");
    c->footer(
        "Example:\n"
        "  pierre validate examples/vaujany-2d/scenario.toml\n"
        "prints a summary and exits 0 when the scenario is valid; else names the file, line and\n"
        "field at fault and exits 2. With --json the same verdict and exit code, as JSON.");
    return c;
  }

  int run() override { return json_ ? run_json() : run_text(); }

 private:
  // --json: every check of the text form, the verdict as one JSON object on stdout; an input
  // error is part of it (exit 2 all the same), and nothing else goes to stdout.
  int run_json() {
    std::optional<io::LoadedScenario> l;
    try {
      l = io::load_scenario(scenario_, rules_folder(rules_));
      check_as_run(*l, stderr, false);
    } catch (const io::InputError& e) {
      fmt::print("{}", io::validation_json(scenario_, &e, l ? l->notes : std::vector<io::InputNote>{},
                                           std::nullopt, std::nullopt));
      return kExitInput;
    }
    fmt::print("{}", io::validation_json(scenario_, nullptr, l->notes, total_trajectories(*l),
                                         memory_note(*l)));
    return kExitOk;
  }

  int run_text() {
    io::LoadedScenario l = io::load_scenario(scenario_, rules_folder(rules_));
    check_as_run(l, stdout, true);
    if (!l.quarries.empty()) {
      const int code = print_quarries(l);
      print_input_notes(stdout, l.notes);
      print_memory_note(l);
      return code;
    }
    const sim::Scenario& s = l.scenario;
    // One item a line: what an engineer checks before a long run, each with its unit.
    fmt::print("{}: valid{}.\n  scenario: \"{}\"\n", l.file.string(), doubt_text(l), s.name);
    fmt::print("  profile: {} vertices, x from {} to {} m, z from {} to {} m\n",
               s.profile.vertices().size(), design::number_text(s.profile.x_min()),
               design::number_text(s.profile.x_max()), design::number_text(s.profile.z_min()),
               design::number_text(s.profile.z_max()));
    fmt::print("  {} material{}:\n", s.materials.size(), s.materials.size() == 1 ? "" : "s");
    for (const auto& m : s.materials) fmt::print("    {}: {}\n", m.name, m.source);
    fmt::print("  {} block{} from {} row{}: {}\n", s.blocks.size(), s.blocks.size() == 1 ? "" : "s",
               l.block_groups.size(), l.block_groups.size() == 1 ? "" : "s",
               block_ranges(s.blocks));
    fmt::print("  {} source{}:", s.sources.size(), s.sources.size() == 1 ? "" : "s");
    for (std::size_t i = 0; i < s.sources.size(); ++i)
      fmt::print("{} \"{}\" at x = {} m, z = {} m", i ? "," : "", s.sources[i].name,
                 design::number_text(s.sources[i].position.x),
                 design::number_text(s.sources[i].position.z));
    fmt::print("\n  {} observation line{}{}", s.lines.size(), s.lines.size() == 1 ? "" : "s",
               s.lines.empty() ? "" : ":");
    for (std::size_t i = 0; i < s.lines.size(); ++i)
      fmt::print("{} {} at x = {} m", i ? "," : "", s.lines[i].name,
                 design::number_text(s.lines[i].x));
    fmt::print("\n  {} trajector{} to run: {} throw{} per block and source, seed {}\n",
               s.trajectory_count(), s.trajectory_count() == 1 ? "y" : "ies", s.settings.throws,
               s.settings.throws == 1 ? "" : "s", s.settings.seed);
    const design::BlocksThrown thrown = design::blocks_thrown(s.blocks);
    for (std::size_t i = 0; i < l.barriers.size(); ++i) {
      const auto& b = l.barriers[i];
      // What the design will stand on besides the crossings: said now, before a long run.
      const auto block = design::resolve_design_block(b.design_block, b.free_board_diameter, thrown);
      const std::string block_text =
          block ? fmt::format("; design block {} m³ × {} kg/m³ = {} kg ({}; density {}), D_f = "
                              "{} m ({})",
                              design::number_text(block->volume), design::number_text(block->density),
                              design::number_text(block->mass()), block->volume_how,
                              block->density_how, design::number_text(block->free_board_diameter),
                              block->free_board_diameter_how)
                : "; no design block: " + block.error;
      fmt::print("  barrier \"{}\" at {}: rule set {} ({}), {}{}\n", b.name, b.line,
                 l.barrier_rules[i].name, l.barrier_rules_files[i].string(),
                 b.candidate ? "checks a candidate" : "a design (no candidate)", block_text);
    }
    print_input_notes(stdout, l.notes);
    print_memory_note(l);
    return kExitOk;
  }

  // What `run` checks besides the scenario, each an InputError: the sections' seeds; with
  // --strict the inputs in doubt (`say_doubts`: each said on stderr, then the refusal) and this
  // machine's memory, as a pipeline's pre-check must not pass a scenario the run then refuses
  // (new-user review); the report layout (its note to `layout_notes`) and the date
  // SOURCE_DATE_EPOCH gives it.
  void check_as_run(io::LoadedScenario& l, std::FILE* layout_notes, bool say_doubts) const {
    note_shared_section_seeds(l);
    if (strict_ && any_in_doubt(l)) {
      if (say_doubts) print_input_notes(stderr, l.notes);
      refuse_doubted_inputs(l);
    }
    if (strict_) (void)check_run_memory(l, std::nullopt);
    load_report_layout(layout_notes);
    (void)report_date();
  }

  // A count this machine cannot run is no fault of the file (another machine may run it): said
  // as a note, where `run` refuses it (and `validate --strict`, above).
  static std::optional<std::string> memory_note(const io::LoadedScenario& l) {
    try {
      return check_run_memory(l, std::nullopt);
    } catch (const io::InputError& e) {
      return std::string(e.what()) + " (pierre run refuses it on this machine)";
    }
  }
  static void print_memory_note(const io::LoadedScenario& l) {
    if (const auto note = memory_note(l)) fmt::print("Note: {}\n", *note);
  }

  // " (haul road 12 m, crusher 30 m)": each work area with its distance from the toe.
  static std::string work_areas_text(const std::vector<design::WorkArea>& areas) {
    std::string t;
    for (const auto& a : areas)
      t += fmt::format("{}{} {} m", t.empty() ? " (" : ", ", a.name, a.distance);
    return t.empty() ? t : t + " from the toe)";
  }

  // ", 2 inputs in doubt (see the notes below)" after "valid" when the readers doubt some: a
  // reader who stops at "valid." missed them (new-user review: masses in tonnes).
  static std::string doubt_text(const io::LoadedScenario& l) {
    const std::size_t n = io::doubted_count(l.notes);
    return n == 0 ? std::string()
                  : fmt::format(", {} input{} in doubt (see the notes below)", n, n == 1 ? "" : "s");
  }

  // A quarry scenario: one paragraph per section (docs/quarry.md).
  static int print_quarries(const io::LoadedScenario& l) {
    const sim::Scenario& s = l.scenario;
    std::string mats;
    for (const auto& m : s.materials)
      mats += fmt::format("{}{} ({})", mats.empty() ? "" : ", ", m.name, m.source);
    std::uint64_t total = 0;
    for (const auto& q : l.quarries) total += q.scenario.trajectory_count();
    fmt::print("{}: valid{}. \"{}\": a quarry scenario of {} section{}; {} material{}: {}. {} "
               "trajector{} to run.\n",
               l.file.string(), doubt_text(l), s.name, l.quarries.size(), l.quarries.size() == 1 ? "" : "s",
               s.materials.size(), s.materials.size() == 1 ? "" : "s", mats, total,
               total == 1 ? "y" : "ies");
    for (const auto& q : l.quarries) {
      const sim::Scenario& c = q.scenario;
      const design::QuarryGeometry& g = q.geometry;
      std::size_t groups = q.block_groups.size();
      fmt::print(
          "  quarry section \"{}\"{}: {} vertices from x = {} to {} m; {} block{} in {} "
          "group{} ({}); {} source{}; {} throw{} per block and source with seed {}{}: {} "
          "trajector{}. Crest x = {:.2f} m ({}), toe x = {:.2f} m ({}), H = {:.2f} m ({}); "
          "floor from segment {} (counted from 0, as in impacts.csv), {:.2f} m long. "
          "Rule set {} ({}); {} work area{}{}{}{}{}.\n",
          q.spec.name, q.spec.group.empty() ? "" : fmt::format(" (group \"{}\")", q.spec.group),
          c.profile.vertices().size(), c.profile.x_min(), c.profile.x_max(), c.blocks.size(),
          c.blocks.size() == 1 ? "" : "s", groups, groups == 1 ? "" : "s", block_ranges(c.blocks),
          c.sources.size(),
          c.sources.size() == 1 ? "" : "s", c.settings.throws, c.settings.throws == 1 ? "" : "s",
          c.settings.seed, q.seed_given ? " (given)" : "", c.trajectory_count(),
          c.trajectory_count() == 1 ? "y" : "ies", g.crest.x,
          design::to_string(g.crest_origin), g.toe.x, design::to_string(g.toe_origin), g.height,
          design::to_string(g.height_origin), g.floor_segment, g.floor_length, q.rules.name,
          q.rules_file.string(), q.spec.work_areas.size(), q.spec.work_areas.size() == 1 ? "" : "s",
          work_areas_text(q.spec.work_areas), q.spec.bench_width ? fmt::format(", bench width {} m", *q.spec.bench_width) : "",
          q.observed.id.empty() && q.observed.rd.empty() ? "" : ", observed values",
          q.observed.source.empty() ? "" : fmt::format(" ({})", q.observed.source));
    }
    return kExitOk;
  }

  std::string scenario_, rules_;
  bool strict_ = false, json_ = false;
};

}  // namespace

std::unique_ptr<Command> make_validate_command() { return std::make_unique<ValidateCommand>(); }

}  // namespace pierre::app
