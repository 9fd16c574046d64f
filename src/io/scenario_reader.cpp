// The scenario reader (docs/scenario-format.md). Reading order: [scenario], [simulation],
// [materials] (with the presets of the materials file), then either [profile], [blocks],
// [[sources]] (section_readers.cpp), [[observation_lines]], [[barriers]] (barrier_reader.cpp: with
// their rule sets, class tables and observed data), or — a quarry scenario — [[quarries]]
// (quarry_reader.cpp); the first problem found stops the reading with an InputError.
#include "pierre/io/scenario_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "barrier_reader.hpp"
#include "confirmed_inputs.hpp"
#include "pierre/io/nearest_name.hpp"
#include "pierre/io/quarry_reader.hpp"
#include "section_readers.hpp"
#include "text_check.hpp"
#include "toml_fields.hpp"

namespace pierre::io {
namespace {

namespace fs = std::filesystem;
using detail::apply_confirmations;
using detail::describe;
using detail::line_of;
using detail::extent;
using detail::parse_toml;
using detail::read_text;
using detail::TomlTable;
using model::ModelDefaults;
using model::InputLimits;

// ---- materials ----

// Reads the fields present in `t` over `m`; returns the names of the fields it set.
std::vector<std::string> read_material_fields(const TomlTable& t, model::Material& m) {
  std::vector<std::string> set;
  if (auto v = t.number("normal_energy")) {
    t.check("normal_energy", *v > 0, "a reference normal energy E_n > 0 (m³/s²)");
    m.normal_energy = *v;
    set.push_back("normal_energy");
  }
  if (auto v = t.number("normal_energy_k")) {
    t.check("normal_energy_k", *v > 0 && *v < 1, "a restitution factor k_n,ref in (0, 1)");
    m.normal_energy_k = *v;
    set.push_back("normal_energy_k");
  }
  if (auto v = t.number("tangential_energy")) {
    t.check("tangential_energy", *v > 0, "a reference tangential energy E_t > 0 (m³/s²)");
    m.tangential_energy = *v;
    set.push_back("tangential_energy");
  }
  if (auto v = t.number("tangential_energy_k")) {
    t.check("tangential_energy_k", *v > 0 && *v < 1, "a restitution factor k_t,ref in (0, 1)");
    m.tangential_energy_k = *v;
    set.push_back("tangential_energy_k");
  }
  if (auto v = t.number("roughness")) {
    // θ > 0 is what lifts a block sliding faster than the maximum sliding speed (§3.2.2,
    // model-2d.md §3 step 3): at 0 it would be launched again and again at one instant.
    t.check("roughness", *v > 0,
            "a roughness scale > 0 (tangent scale, typically 0.3-1.5; 0 leaves a block sliding "
            "faster than max_sliding_speed no way to leave the ground)");
    m.roughness = *v;
    set.push_back("roughness");
  }
  if (auto v = t.number("friction_angle")) {
    t.check("friction_angle", *v >= 0 && *v < 90, "a friction angle in [0, 90) degrees");
    m.friction_angle_deg = *v;
    set.push_back("friction_angle");
  }
  return set;
}

class Presets {
 public:
  // `what` names the file in a message when it cannot be read ("materials file (TOML) in …").
  Presets(fs::path file, std::string what) : file_(std::move(file)), what_(std::move(what)) {}
  const fs::path& file() const { return file_; }

  const model::Material* find(const std::string& name) {
    load();
    const auto it = presets_.find(name);
    return it == presets_.end() ? nullptr : &it->second;
  }
  std::string names() {
    load();
    std::string s;
    for (const auto& [k, v] : presets_) s += (s.empty() ? "" : ", ") + k;
    return s;
  }
  // "; the nearest is talus" for a name typed wrong ("tallus"), else "".
  std::string nearest(const std::string& name) {
    load();
    std::vector<std::string> all;
    for (const auto& [k, v] : presets_) all.push_back(k);
    return detail::nearest_name_hint(name, all);
  }

 private:
  void load() {
    if (loaded_) return;
    loaded_ = true;
    text_ = read_text(file_, what_);
    root_ = parse_toml(file_, text_);
    const TomlTable root(file_, root_, "", 0, {});
    for (auto&& [k, v] : root_) {
      const std::string name(k.str());
      const auto* tbl = v.as_table();
      if (!tbl) root.fail(name, "a preset table [NAME]");
      const TomlTable t(file_, *tbl, name, line_of(v),
                        {"source", "normal_energy", "normal_energy_k", "tangential_energy",
                         "tangential_energy_k", "roughness", "friction_angle"});
      model::Material m;
      m.name = name;
      m.source = t.required_string("source", "a string citing where the values come from");
      const auto set = read_material_fields(t, m);
      for (std::string_view req : {"normal_energy", "tangential_energy", "roughness"})
        if (std::find(set.begin(), set.end(), req) == set.end())
          t.missing(req, "a number (every preset gives normal_energy, tangential_energy and roughness)");
      presets_.emplace(name, std::move(m));
    }
  }

  fs::path file_;
  std::string what_;
  bool loaded_ = false;
  std::string text_;
  toml::table root_;
  std::map<std::string, model::Material> presets_;
};

// The roughness is the one input that is not an angle in degrees but a tangent scale
// (model-2d.md §1; tan θ = θ_scale · X · f_size, §3.4.1), so an angle typed into it (35) or a
// percentage (65) passes its range check. The calibrated sets use 0.3 to 0.72, the thesis says
// typically 0.3 to 1.5; beyond 2 the typical roughness angle (X about 0.5) is over 45°.
constexpr double kRoughnessScaleHigh = 2.0;

void note_roughness(const TomlTable& t, double scale, std::vector<InputNote>& notes) {
  if (scale <= kRoughnessScaleHigh) return;
  constexpr double kTypicalX = 0.5;
  const double typical_deg = geometry::degrees(std::atan(kTypicalX * scale));
  notes.push_back({t.file(), line_of(*t.find("roughness")), t.field("roughness"),
                   fmt::format("roughness {:g} is a tangent scale, not an angle or a percentage: "
                               "tan θ = roughness · X, and with X about 0.5 the typical "
                               "roughness angle is {:.0f}° (the calibrated sets use 0.3 to 0.72, "
                               "typically 0.3 to 1.5)",
                               scale, typical_deg),
                   doubts_every_line(t.field("roughness"), scale)});
}

// A friction angle is in degrees; one at most π/2 (0.52) reads like radians and leaves a block
// sliding almost without friction. 0 is kept silent: a frictionless test is meant as such.
void note_friction_angle(const TomlTable& t, double deg, std::vector<InputNote>& notes) {
  if (!(deg > 0 && deg <= std::numbers::pi / 2)) return;
  notes.push_back({t.file(), line_of(*t.find("friction_angle")), t.field("friction_angle"),
                   fmt::format("friction angle {:g}° is in degrees (the calibrated sets use 30°): "
                               "if it is in radians, it is {:.1f}°; as typed, blocks slide almost "
                               "without friction",
                               deg, geometry::degrees(deg)),
                   doubts_every_line(t.field("friction_angle"), deg)});
}

std::vector<model::Material> read_materials(const TomlTable& top, Presets& presets,
                                            std::vector<InputNote>& notes) {
  const auto mats = top.subtable("materials", {});
  if (!mats) top.missing("materials", "a [materials.NAME] table for each material of the profile");
  std::vector<model::Material> out;
  // toml++ tables are sorted by key: take them in file order instead, so that material indices
  // follow the file.
  std::vector<std::pair<long, std::string>> order;
  for (auto&& [k, v] : mats->table()) order.emplace_back(line_of(v), std::string(k.str()));
  std::sort(order.begin(), order.end());
  for (const auto& [line, name] : order) {
    const toml::node* node = mats->find(name);
    const auto* tbl = node->as_table();
    if (!tbl) mats->fail(name, "a table [materials.NAME]");
    if (auto bad = detail::unwritable_text(name))
      throw InputError(top.file(), line, top.field("materials"), "a material name: " + *bad,
                       std::string(detail::kWritableText));
    const TomlTable t =
        *mats->subtable(name, {"preset", "normal_energy", "normal_energy_k", "tangential_energy",
                               "tangential_energy_k", "roughness", "friction_angle"});
    model::Material m;
    bool from_preset = false;
    if (auto p = t.string("preset")) {
      const model::Material* pre = presets.find(*p);
      if (!pre)
        t.fail("preset", fmt::format("a preset of {} ({}){}", presets.file().string(),
                                     presets.names(), presets.nearest(*p)));
      m = *pre;
      from_preset = true;
    }
    m.name = name;
    const auto set = read_material_fields(t, m);
    if (std::find(set.begin(), set.end(), "roughness") != set.end())
      note_roughness(t, m.roughness, notes);
    if (std::find(set.begin(), set.end(), "friction_angle") != set.end())
      note_friction_angle(t, m.friction_angle_deg, notes);
    if (from_preset) {
      if (!set.empty()) {
        std::string list;
        for (const auto& s : set) list += (list.empty() ? "" : ", ") + s;
        m.source += " (overridden: " + list + ")";
      }
    } else {
      m.source = "scenario";
      for (std::string_view req : {"normal_energy", "tangential_energy", "roughness"})
        if (std::find(set.begin(), set.end(), req) == set.end())
          t.missing(req, "a number (without a preset, normal_energy, tangential_energy and "
                         "roughness are required)");
    }
    out.push_back(std::move(m));
  }
  if (out.empty())
    throw InputError(top.file(), mats->line(), "materials", "no material",
                     "a [materials.NAME] table for each material of the profile");
  return out;
}

// A material no segment uses changes nothing: often one left from an earlier profile, or meant
// for a segment that names another. Said at its [materials.NAME] table.
void note_unused_materials(const TomlTable& top, const std::vector<model::Material>& materials,
                           const std::vector<const geometry::Profile*>& profiles,
                           std::vector<InputNote>& notes) {
  std::vector<bool> used(materials.size(), false);
  for (const geometry::Profile* p : profiles)
    for (const auto& seg : p->segments())
      if (seg.material >= 0 && static_cast<std::size_t>(seg.material) < used.size())
        used[static_cast<std::size_t>(seg.material)] = true;
  const auto mats = top.subtable("materials", {});
  for (std::size_t m = 0; m < used.size(); ++m) {
    if (used[m]) continue;
    const toml::node* node = mats->find(materials[m].name);
    notes.push_back({top.file(), node ? line_of(*node) : 0, mats->field(materials[m].name),
                     fmt::format("material \"{}\" is defined but no segment of {} uses it",
                                 materials[m].name,
                                 profiles.size() > 1 ? "any section's profile" : "the profile"),
                     {}});
  }
}

// ---- simulation ----

sim::SimulationSettings read_simulation(const TomlTable& top) {
  const auto s = top.subtable(
      "simulation", {"seed", "throws", "roughness_distribution", "size_reduction", "roughness_mean",
                     "roughness_sd", "size_reduction_b", "size_reduction_m",
                     "size_reduction_floor", "stop_head_factor", "max_sliding_speed", "max_time",
                     "max_impacts", "gravity"});
  if (!s) top.missing("simulation", "a [simulation] table with seed and throws");
  sim::SimulationSettings out;
  const auto seed = s->integer("seed");
  if (!seed) s->missing("seed", "an integer >= 0");
  s->check("seed", *seed >= 0, "an integer >= 0");
  out.seed = static_cast<std::uint64_t>(*seed);
  const auto throws = s->integer("throws");
  if (!throws) s->missing("throws", "an integer >= 1");
  s->check("throws", *throws >= 1 && *throws <= std::numeric_limits<std::uint32_t>::max(),
           fmt::format("an integer from 1 to {} (throws per block and source)",
                       std::numeric_limits<std::uint32_t>::max()));
  out.throws = static_cast<std::uint32_t>(*throws);

  model::RoughnessModel& r = out.roughness;
  if (auto d = s->string("roughness_distribution")) {
    if (*d == "truncated-normal")
      r.distribution = model::RoughnessDistribution::truncated_normal;
    else if (*d == "uniform")
      r.distribution = model::RoughnessDistribution::uniform;
    else
      s->fail("roughness_distribution", "\"truncated-normal\" or \"uniform\"");
  }
  r.size_reduction = s->boolean("size_reduction").value_or(ModelDefaults::size_reduction);
  r.mean = s->number("roughness_mean", ModelDefaults::roughness_mean);
  r.sd = s->number("roughness_sd", ModelDefaults::roughness_sd);
  s->check("roughness_sd", r.sd > 0, "a standard deviation > 0");
  // X is the normal truncated to X > 0: 30 σ below 0 its part above 0, Φ(−30) ≈ 5e-198, is
  // about the last a double carries through the inverse CDF.
  s->check("roughness_mean", r.mean >= -30.0 * r.sd,
           fmt::format("a mean >= -30 × roughness_sd = {:g} (X is the normal truncated to X > 0; "
                       "further below 0 none of it is left to draw from)",
                       -30.0 * r.sd));
  r.b = s->number("size_reduction_b", ModelDefaults::size_reduction_b);
  s->check("size_reduction_b", r.b > 0, "a number > 0 (Eq 6.6)");
  r.m = s->number("size_reduction_m", ModelDefaults::size_reduction_m);
  s->check("size_reduction_m", r.m >= 0, "a number >= 0 (1/m, Eq 6.6)");
  r.floor = s->number("size_reduction_floor", ModelDefaults::size_reduction_floor);
  s->check("size_reduction_floor", r.floor > 0, "a number > 0");
  out.stop_head_factor = s->number("stop_head_factor", ModelDefaults::stop_head_factor);
  s->check("stop_head_factor", out.stop_head_factor > 0, "a number > 0 (H_stop = c·R)");
  out.max_sliding_speed = s->number("max_sliding_speed", ModelDefaults::max_sliding_speed);
  s->check("max_sliding_speed", out.max_sliding_speed > 0, "a speed > 0 (m/s)");
  out.max_time = s->number("max_time", ModelDefaults::max_time);
  s->check("max_time", out.max_time > 0, "a time > 0 (s)");
  if (auto n = s->integer("max_impacts")) {
    // Counted per trajectory in 32 bits (TrajectorySummary::impacts).
    s->check("max_impacts", *n >= 1 && *n <= std::numeric_limits<std::uint32_t>::max(),
             fmt::format("an integer from 1 to {}", std::numeric_limits<std::uint32_t>::max()));
    out.max_impacts = static_cast<long>(*n);
  }
  out.gravity = s->number("gravity", ModelDefaults::gravity);
  s->check("gravity", out.gravity > 0 && out.gravity <= InputLimits::max_gravity,
           fmt::format("an acceleration > 0 and <= {:g} m/s²", InputLimits::max_gravity));
  return out;
}

// Any gravity > 0 is taken (a test on another body, a round 10), but one far from the Earth's
// is more likely a slip (98.1, 0.981): said, as the unit slips of the blocks are.
void note_gravity(const TomlTable& top, double g, std::vector<InputNote>& notes) {
  constexpr double kEarthLow = 9.7, kEarthHigh = 10.0;  // m/s²: 9.78 at the equator to 9.83, and 10 rounded
  if (g >= kEarthLow && g <= kEarthHigh) return;
  const auto s = top.subtable("simulation", {});
  const toml::node* n = s ? s->find("gravity") : nullptr;
  if (!n) return;
  notes.push_back({top.file(), line_of(*n), "simulation.gravity",
                   fmt::format("gravity {:g} m/s² is not the Earth's (9.78 to 9.83 m/s²): every "
                               "speed and energy depends on it; check the value if the slope is "
                               "on Earth",
                               g),
                   doubts_every_line("simulation.gravity", g)});
}

// Lines count first crossings in the main direction (the profile's vertex order): one behind
// every source, upslope of where the blocks start, is crossed by none of them unless one bounces
// back past it. A design at such a line has nothing to stand on: said before the run.
void note_line_behind_sources(const TomlTable& t, const sim::Scenario& sc,
                              const sim::ObservationLine& l, std::vector<InputNote>& notes) {
  const int dir = sc.profile.main_direction();
  const sim::Source* nearest = nullptr;
  for (const auto& src : sc.sources) {
    if ((l.x - src.position.x) * dir >= 0) return;  // ahead of (or at) this one
    if (!nearest || std::abs(src.position.x - l.x) < std::abs(nearest->position.x - l.x))
      nearest = &src;
  }
  if (!nearest) return;
  notes.push_back(
      {t.file(), line_of(*t.find("x")), t.field("x"),
       fmt::format("observation line \"{}\" (x = {} m) lies behind every source (the nearest, "
                   "\"{}\", is at x = {} m): lines count the blocks that cross them in the "
                   "profile's vertex order, away from the sources, so none reaches this one unless "
                   "it bounces back past it. Check x, or the order of the profile's vertices",
                   l.name, l.x, nearest->name, nearest->position.x),
       {}});
}

// The note of a line behind every source: which note, on which of the scenario's lines.
struct LineBehindNote {
  std::size_t note, line;
};

// A barrier on a line behind every source has nothing to be designed from: the line's note is
// a likely slip for it (a chainage typed wrong, a profile listed from the toe end), so that
// `--strict` refuses it and none of its lines passes unconfirmed (new-user review: a design
// that got no crossing left `check --strict` at exit 0). A line no barrier stands on stays a
// plain note. A second barrier on the line gets a copy of the note, doubting its own lines.
void doubt_barriers_behind_sources(const std::vector<LineBehindNote>& behind, LoadedScenario& loaded) {
  std::vector<InputNote>& notes = loaded.notes;
  for (const LineBehindNote& b : behind) {
    const sim::ObservationLine& line = loaded.scenario.lines[b.line];
    bool first = true;
    for (const design::BarrierSpec& spec : loaded.barriers) {
      if (spec.line != line.name) continue;
      InputNote n = notes[b.note];
      n.doubt = design::DoubtedInput{n.field, spec.name, {}, line.x};
      if (first)
        notes[b.note] = std::move(n);
      else
        notes.push_back(std::move(n));
      first = false;
    }
  }
}

std::vector<LineBehindNote> read_lines(const TomlTable& top, sim::Scenario& sc,
                                       std::vector<InputNote>& notes) {
  std::vector<LineBehindNote> behind;
  const toml::array* a = top.array_of_tables("observation_lines");
  if (!a) return behind;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const TomlTable t = top.element("observation_lines", *a, i, {"name", "x"});
    sim::ObservationLine l;
    l.name = t.required_string("name", "a name for the line");
    t.check("name", !l.name.empty(), "a non-empty name");
    for (const auto& other : sc.lines)
      t.check("name", other.name != l.name, "a name not used by another observation line");
    l.x = t.required_number("x", "a chainage x (m)");
    t.check("x", l.x >= sc.profile.x_min() && l.x <= sc.profile.x_max(),
            "a chainage " + extent(sc.profile) +
                " (the section's own horizontal x, not the road's or railway's station)");
    const std::size_t before = notes.size();
    note_line_behind_sources(t, sc, l, notes);
    if (notes.size() > before) behind.push_back({before, sc.lines.size()});
    sc.lines.push_back(std::move(l));
  }
  return behind;
}


}  // namespace

namespace {
LoadedScenario read_scenario(const std::filesystem::path& scenario_file, const RulesFolder& rules) {
  const fs::path& rules_dir = rules.path;
  LoadedScenario out;
  out.file = scenario_file;
  out.text = read_text(scenario_file, "scenario file (TOML)");
  const toml::table root = parse_toml(scenario_file, out.text);
  const TomlTable top(scenario_file, root, "", 0, detail::kScenarioSections);

  const auto head = top.subtable("scenario", {"name", "description", "materials_file", "reference",
                                              "revision", "prepared_by", "checked_by"});
  if (!head) top.missing("scenario", "a [scenario] table with a name");
  out.scenario.name = head->required_string("name", "a name for the scenario");
  head->check("name", !out.scenario.name.empty(), "a non-empty name");
  out.description = head->string("description").value_or("");
  for (auto [key, field] : out.document.fields()) {
    *field = head->string(key).value_or("");
    // On every printed page's header, which Excel limits to 255 characters in all.
    head->check(key, field->size() <= 80, "a text of at most 80 characters (it heads every printed page)");
  }
  if (auto mf = head->file_path("materials_file", "materials file (TOML)"))
    out.materials_file = *mf;
  else
    out.materials_file = rules_dir / "materials.toml";

  out.scenario.settings = read_simulation(top);
  if (const auto s = top.subtable("simulation", {}))
    if (const toml::node* n = s->find("throws")) out.throws_line = line_of(*n);
  note_gravity(top, out.scenario.settings.gravity, out.notes);
  Presets presets(out.materials_file,
                  head->has("materials_file")
                      ? std::string("materials file (TOML)")
                      : "materials file (TOML) in " + rules.named());
  out.scenario.materials = read_materials(top, presets, out.notes);
  if (top.has("quarries")) {
    // A quarry scenario: every section brings its own profile, blocks and sources; the
    // top-level ones (and what stands on them) would be a second, unused meaning.
    for (const char* key : {"profile", "blocks", "sources", "observation_lines", "barriers"}) {
      const toml::node* n = top.find(key);
      if (!n) continue;
      const bool array = std::string_view(key) == "sources" ||
                         std::string_view(key) == "observation_lines" ||
                         std::string_view(key) == "barriers";
      throw InputError(scenario_file, line_of(*n), key,
                       fmt::format("{0}{1}{2} beside [[quarries]]", array ? "[[" : "[", key,
                                   array ? "]]" : "]"),
                       fmt::format("no top-level {} in a quarry scenario: each [[quarries]] "
                                   "section has its own profile, blocks and sources "
                                   "(docs/quarry.md); or no [[quarries]]",
                                   key));
    }
    if (!top.array_of_tables("quarries")) top.fail("quarries", "one or more [[quarries]] tables");
    out.quarries = read_quarries(root, scenario_file, rules, out.scenario.materials,
                                 out.scenario.settings);
    if (out.quarries.empty())
      throw InputError(scenario_file, line_of(*top.find("quarries")), "quarries", "no section",
                       "at least one [[quarries]] section");
    std::vector<const geometry::Profile*> profiles;
    for (auto& q : out.quarries) {
      // Moved, not copied: [confirmed] applies to the scenario's one list.
      out.notes.insert(out.notes.end(), std::make_move_iterator(q.notes.begin()),
                       std::make_move_iterator(q.notes.end()));
      q.notes.clear();
      profiles.push_back(&q.scenario.profile);
    }
    note_unused_materials(top, out.scenario.materials, profiles, out.notes);
    apply_confirmations(top, out.notes);
    return out;
  }
  out.scenario.profile = detail::read_profile(top, out.scenario.materials, "", out.notes);
  detail::read_blocks(top, out.block_groups, out.scenario.blocks, "", out.notes);
  detail::read_sources(top, out.scenario, "", out.notes);
  note_unused_materials(top, out.scenario.materials, {&out.scenario.profile}, out.notes);
  {
    const auto s = top.subtable("simulation", {});
    const toml::node& throws = *s->find("throws");
    check_trajectory_count(out.scenario, scenario_file, line_of(throws), s->field("throws"),
                           describe(throws));
  }
  const std::vector<LineBehindNote> behind = read_lines(top, out.scenario, out.notes);
  detail::read_barriers(top, rules, out);
  doubt_barriers_behind_sources(behind, out);
  apply_confirmations(top, out.notes);
  return out;
}

}  // namespace

LoadedScenario load_scenario(const std::filesystem::path& scenario_file, const RulesFolder& rules) {
  // Every file the loading reads (the scenario, its CSVs, the materials, the rule sets), with
  // its SHA-256: the record of what produced the results.
  InputFilesRecord record;
  LoadedScenario out = read_scenario(scenario_file, rules);
  out.inputs = record.take();
  return out;
}


namespace {
// "1 sources × 25 blocks × 10 throws are 250", for a count `n` worked out without wrapping.
std::string trajectory_count_text(const sim::Scenario& sc, long double n) {
  return fmt::format("{} sources × {} blocks × {} throws are {:.3g}", sc.sources.size(),
                     sc.blocks.size(), sc.settings.throws, static_cast<double>(n));
}
}  // namespace

void check_trajectory_count(const sim::Scenario& sc, const std::filesystem::path& file, long line,
                            const std::string& field, const std::string& found,
                            const std::string& what) {
  // Sources × blocks × throws in a 64-bit count (it wrapped): at most 2^53, exact as a double.
  const long double n = static_cast<long double>(sc.sources.size()) * sc.blocks.size() *
                        sc.settings.throws;
  if (n > 9007199254740992.0L)
    throw InputError(file, line, field, found,
                     fmt::format("at most 2^53 trajectories {} ({}{}{})",
                                 what.empty() ? "in all" : "a section", what,
                                 what.empty() ? "" : ": ", trajectory_count_text(sc, n)));
}

std::string trajectory_count_text(const sim::Scenario& sc) {
  return trajectory_count_text(sc, static_cast<long double>(sc.sources.size()) * sc.blocks.size() *
                                       sc.settings.throws);
}


}  // namespace pierre::io
