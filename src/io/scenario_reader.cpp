// The scenario reader (docs/scenario-format.md). Reading order: [scenario], [simulation],
// [materials] (with the presets of the materials file), then either [profile], [blocks],
// [[sources]] (section_readers.cpp), [[observation_lines]], [[barriers]] (with their rule sets,
// class tables and observed data), or — a quarry scenario — [[quarries]] (quarry_reader.cpp);
// the first problem found stops the reading with an InputError.
#include "pierre/io/scenario_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numbers>

#include <fmt/format.h>

#include "csv_table.hpp"
#include "pierre/io/quarry_reader.hpp"
#include "pierre/io/rule_set_reader.hpp"
#include "rule_kind.hpp"
#include "section_readers.hpp"
#include "text_check.hpp"
#include "toml_fields.hpp"

namespace pierre::io {
namespace {

namespace fs = std::filesystem;
using detail::CsvTable;
using detail::describe;
using detail::quoted_list;
using detail::line_of;
using detail::extent;
using detail::parse_toml;
using detail::read_text;
using detail::relative_to;
using detail::TomlTable;
using model::ModelDefaults;

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
  const double typical_deg = std::atan(kTypicalX * scale) * 180.0 / std::numbers::pi;
  notes.push_back({t.file(), line_of(*t.find("roughness")), t.field("roughness"),
                   fmt::format("roughness {:g} is a tangent scale, not an angle or a percentage: "
                               "tan θ = roughness · X, and with X about 0.5 the typical "
                               "roughness angle is {:.0f}° (the calibrated sets use 0.3 to 0.72, "
                               "typically 0.3 to 1.5)",
                               scale, typical_deg)});
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
    TomlTable t(top.file(), *tbl, mats->field(name), line_of(*node),
                {"preset", "normal_energy", "normal_energy_k", "tangential_energy",
                 "tangential_energy_k", "roughness", "friction_angle"});
    model::Material m;
    bool from_preset = false;
    if (auto p = t.string("preset")) {
      const model::Material* pre = presets.find(*p);
      if (!pre)
        t.fail("preset", fmt::format("a preset of {} ({})", presets.file().string(), presets.names()));
      m = *pre;
      from_preset = true;
    }
    m.name = name;
    const auto set = read_material_fields(t, m);
    if (std::find(set.begin(), set.end(), "roughness") != set.end())
      note_roughness(t, m.roughness, notes);
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
                                 profiles.size() > 1 ? "any section's profile" : "the profile")});
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
  s->check("gravity", out.gravity > 0, "an acceleration > 0 (m/s²)");
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
                               g)});
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
                   l.name, l.x, nearest->name, nearest->position.x)});
}

void read_lines(const TomlTable& top, sim::Scenario& sc, std::vector<InputNote>& notes) {
  const toml::array* a = top.array_of_tables("observation_lines");
  if (!a) return;
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
    note_line_behind_sources(t, sc, l, notes);
    sc.lines.push_back(std::move(l));
  }
}


// ---- barriers (design-checks.md §1) ----

// The design block's density, where it is given, said when it is not a rock's: the unit slip
// the blocks' densities are checked for (section_readers.cpp).
void note_density(const TomlTable& d, double density, std::vector<InputNote>& notes) {
  if (density >= detail::kRockDensityMin && density <= detail::kRockDensityMax) return;
  notes.push_back({d.file(), line_of(*d.find("density")), d.field("density"),
                   fmt::format("the design block's density {:g} kg/m³ is outside the densities of "
                               "rock ({:g} to {:g} kg/m³): a density is in kg/m³, and 2.65 (t/m³ "
                               "or g/cm³) makes its energy 1000 times too small",
                               density, detail::kRockDensityMin, detail::kRockDensityMax)});
}

design::DesignBlock read_design_block(const TomlTable& t, std::vector<InputNote>& notes) {
  const std::string expected =
      "\"largest\", { percentile = p } (of the block volumes, optional density) or "
      "{ volume = m³, density = kg/m³ }";
  design::DesignBlock b;
  const toml::node* n = t.find("design_block");
  if (!n) return b;  // default: the largest block thrown
  if (const auto* s = n->as_string()) {
    if (s->get() != "largest") t.fail("design_block", expected);
    return b;
  }
  if (!n->as_table()) t.fail("design_block", expected);
  const auto d = t.subtable("design_block", {"percentile", "volume", "density"});
  const bool has_p = d->has("percentile"), has_v = d->has("volume");
  if (has_p == has_v)
    throw InputError(t.file(), d->line(), t.field("design_block"),
                     has_p ? "both percentile and volume" : "neither percentile nor volume",
                     expected);
  if (has_p) {
    b.kind = design::DesignBlock::Kind::percentile;
    b.percentile = d->required_number("percentile", "a percentile in (0, 100]");
    d->check("percentile", b.percentile > 0 && b.percentile <= 100, "a percentile in (0, 100]");
    if (d->has("density")) {
      b.density = d->required_number("density", "a density > 0 (kg/m³)");
      d->check("density", b.density > 0, "a density > 0 (kg/m³)");
      note_density(*d, b.density, notes);
    }
    return b;
  }
  b.kind = design::DesignBlock::Kind::given;
  b.volume = d->required_number("volume", "a volume > 0 (m³)");
  d->check("volume", b.volume > 0, "a volume > 0 (m³)");
  b.density = d->required_number("density", "a density > 0 (kg/m³) with the volume");
  d->check("density", b.density > 0, "a density > 0 (kg/m³)");
  // The blocks' own limit and unit slip (section_readers.cpp), for the block designed on.
  const double mass = b.volume * b.density;
  d->check("volume", mass <= ModelDefaults::max_block_mass,
           detail::block_mass_limit("a design block", b.volume, b.density, mass, true));
  note_density(*d, b.density, notes);
  return b;
}

std::optional<double> positive_number(const TomlTable& t, std::string_view key,
                                      std::string_view expected) {
  const auto v = t.number(key);
  if (v) t.check(key, *v > 0, expected);
  return v;
}

// A candidate's or a block's value far beyond its kind: most likely typed in the smaller unit
// (mm for m, J for kJ), which passes every range check. Noted at the value, with what it is in
// that unit. `beyond`: what the limit stands for.
struct UnitSlip {
  double limit;
  const char* unit;
  const char* small_unit;  // a thousandth of `unit`
  std::string beyond;
};

void note_unit_slip(const TomlTable& t, std::string_view key, std::string_view what, double v,
                    const UnitSlip& u, std::vector<InputNote>& notes) {
  if (!(v > u.limit)) return;
  notes.push_back({t.file(), line_of(*t.find(key)), t.field(key),
                   fmt::format("{} {:g} {} is more than {:g} {}{}: it is read in {}; if it was "
                               "meant in {}, it is {:g} {}",
                               what, v, u.unit, u.limit, u.unit, u.beyond, u.unit, u.small_unit,
                               v / 1000, u.unit)});
}

// Rockfall barriers are some metres high and stretch some metres; their energies are up to
// some thousands of kJ (ETAG 027's last class: MEL > 4 500 kJ). The limits are far beyond
// those, to catch only a value in mm or J.
constexpr double kTallestBarrier = 20.0;            // m
constexpr double kLongestElongation = 30.0;         // m
constexpr double kLargestBarrierEnergy = 30e3;      // kJ
constexpr double kLargestFreeBoardDiameter = 10.0;  // m: a block of some 1 400 t at 2650 kg/m³

void note_candidate(const TomlTable& c, const design::CandidateBarrier& k,
                    const design::EnergyClassTable& classes, std::vector<InputNote>& notes) {
  double largest_mel = 0;
  for (const auto& e : classes.classes) largest_mel = std::max(largest_mel, e.mel_kJ);
  const UnitSlip energy{kLargestBarrierEnergy, "kJ", "J",
                        fmt::format(" ({} reaches MEL {:g} kJ)", classes.name, largest_mel)};
  const UnitSlip length{kTallestBarrier, "m", "mm", ""};
  const UnitSlip stretch{kLongestElongation, "m", "mm", ""};
  if (k.mel_kJ) note_unit_slip(c, "mel", "the candidate's MEL", *k.mel_kJ, energy, notes);
  // The SEL is at most the MEL: said for itself only when no MEL is given.
  if (k.sel_kJ && !k.mel_kJ)
    note_unit_slip(c, "sel", "the candidate's SEL", *k.sel_kJ, energy, notes);
  if (k.height) note_unit_slip(c, "height", "the candidate's height", *k.height, length, notes);
  if (k.elongation_mel)
    note_unit_slip(c, "elongation_mel", "the elongation in the MEL test", *k.elongation_mel,
                   stretch, notes);
  if (k.elongation_sel)
    note_unit_slip(c, "elongation_sel", "the elongation in the SEL test", *k.elongation_sel,
                   stretch, notes);
}

design::CandidateBarrier read_candidate(const TomlTable& c, const design::EnergyClassTable& classes) {
  design::CandidateBarrier k;
  if (auto n = c.integer("energy_class")) {
    std::vector<std::string> nums;
    for (const auto& e : classes.classes) nums.push_back(std::to_string(e.number));
    std::string list;
    for (const auto& x : nums) list += (list.empty() ? "" : ", ") + x;
    const design::EnergyClass* e =
        *n >= INT32_MIN && *n <= INT32_MAX ? design::find_energy_class(classes, static_cast<int>(*n)) : nullptr;
    c.check("energy_class", e != nullptr,
            fmt::format("a class of {} ({})", classes.name, list));
    k.energy_class = static_cast<int>(*n);
    if (e->open_ended && !(c.has("mel") && c.has("sel")))
      c.fail("energy_class",
             fmt::format("a closed class, or mel and sel declared beside it (class {} is open-ended: "
                         "\"> {} kJ\")", e->number, e->mel_kJ));
  }
  k.mel_kJ = positive_number(c, "mel", "a declared MEL > 0 (kJ)");
  k.sel_kJ = positive_number(c, "sel", "a declared SEL > 0 (kJ)");
  // The SEL is the service energy a barrier stands repeatedly, a fraction of its MEL (ETAG 027:
  // SEL = MEL / 3): one above the MEL is a typo.
  if (k.mel_kJ && k.sel_kJ)
    c.check("sel", *k.sel_kJ <= *k.mel_kJ,
            fmt::format("a declared SEL <= the declared MEL ({} kJ; ETAG 027 takes SEL = MEL / 3)",
                        *k.mel_kJ));
  k.height = positive_number(c, "height", "a vertical interception height > 0 (m)");
  k.elongation_mel = positive_number(c, "elongation_mel", "a maximum elongation > 0 (m, MEL test)");
  k.elongation_sel = positive_number(c, "elongation_sel", "a maximum elongation > 0 (m, SEL test)");
  k.distance_to_object = positive_number(c, "distance_to_object", "a distance > 0 (m)");
  if (auto r = c.number("residual_height")) {
    c.check("residual_height", *r >= 0, "a residual height >= 0 (m)");
    if (!k.height) c.fail("residual_height", "a residual height together with the candidate's height");
    c.check("residual_height", *r <= *k.height,
            fmt::format("a residual height <= the height ({} m)", *k.height));
    k.residual_height = r;
  }
  if (!k.energy_class && !k.mel_kJ && !k.sel_kJ && !k.height)
    throw InputError(c.file(), c.line(), c.field("energy_class"), "nothing to check",
                     "at least one of energy_class, mel, sel, height");
  return k;
}

// Observed crossings beyond any rockfall (a column in km/h, cm or J, each a plausible slip
// that passes the >= 0 check): noted once per column, at its first such row.
constexpr double kFastestRockfall = 60.0;        // m/s (216 km/h)
constexpr double kHighestPassing = 30.0;         // m
constexpr double kLargestObservedEnergy = 30e3;  // kJ, as a barrier's (above)

design::ObservedSample read_observed(const fs::path& file, std::vector<InputNote>& notes) {
  const std::vector<std::string> columns = {"speed_m_s", "height_m", "energy_kJ"};
  const CsvTable t = detail::read_csv(file, columns, "speed_m_s, height_m and/or energy_kJ", {},
                                      columns);  // a value not measured for a block: empty
  design::ObservedSample o;
  o.file = file.string();
  struct Col {
    const char* name;
    std::vector<double>* out;
    double scale;
    double limit;
    const char* unit;
    const char* beyond;
    const char* slip;  // the unit it was likely typed in, and the value it then has
    double slip_factor;
  };
  const Col cols[] = {{"speed_m_s", &o.speed, 1.0, kFastestRockfall, "m/s",
                       "far faster than blocks cross a line on a slope", "km/h", 1 / 3.6},
                      {"height_m", &o.height, 1.0, kHighestPassing, "m",
                       "far higher than blocks pass a barrier's line", "cm", 0.01},
                      {"energy_kJ", &o.energy, 1000.0, kLargestObservedEnergy, "kJ",
                       "far beyond any barrier's energy class", "J", 0.001}};
  bool any = false;
  for (const Col& c : cols) {
    const auto idx = t.column(c.name);
    if (!idx) continue;
    any = true;
    long first_line = 0;
    double first = 0;
    std::size_t beyond = 0;
    for (const auto& r : t.rows) {
      if (r.cells[*idx].empty()) continue;
      const double v = t.number(r, *idx);
      if (!(v >= 0))
        throw InputError(file, r.line, c.name, r.cells[*idx], "a value >= 0");
      if (v > c.limit && beyond++ == 0) {
        first_line = r.line;
        first = v;
      }
      c.out->push_back(v * c.scale);
    }
    if (beyond > 0)
      notes.push_back(
          {file, first_line, c.name,
           fmt::format("{} {:g} {}{} is more than {:g} {}, {}: the column is read in {}; if it "
                       "is in {}, {:g} is {:.3g} {}",
                       c.name, first, c.unit,
                       beyond > 1 ? fmt::format(" (and {} more rows like it)", beyond - 1) : "",
                       c.limit, c.unit, c.beyond, c.unit, c.slip, first, first * c.slip_factor,
                       c.unit)});
  }
  if (!any)
    throw InputError(file, t.header_line, "header", "none of the columns",
                     "a header with speed_m_s, height_m and/or energy_kJ");
  if (o.speed.empty() && o.height.empty() && o.energy.empty())
    throw InputError(file, t.header_line, "observed", "no values", "at least one observed value");
  return o;
}

// The energy class table a rule set names ([rule_set].classes): beside the rule set first, then
// in the rules folder. When neither holds it, an InputError at the line of `classes` in the rule
// file, or of its [rule_set] header when it gives none (the default table is meant).
fs::path energy_classes_file(const design::BarrierRuleSet& rules, const fs::path& rules_file,
                             const RulesFolder& rules_folder) {
  const fs::path name = rules.classes + ".toml";
  std::error_code ec;
  for (const fs::path& f : {rules_file.parent_path() / name, rules_folder.path / name})
    if (fs::is_regular_file(f, ec)) return f;
  // Read again for the line: an error path, and the rule set has been read without fault.
  const toml::table root = parse_toml(rules_file, read_text(rules_file, "barrier rule set (TOML)"));
  const toml::node* header = root.get("rule_set");
  const toml::node* given = header && header->as_table() ? header->as_table()->get("classes") : nullptr;
  const long line = given ? line_of(*given) : header ? line_of(*header) : 0;
  throw InputError(
      rules_file, line, "rule_set.classes",
      fmt::format("\"{}\"{}", rules.classes,
                  given ? "" : " (the default: [rule_set] names no classes)"),
      fmt::format("an energy class table {} beside the rule set or in {}", name.string(),
                  rules_folder.named()));
}

void read_barriers(const TomlTable& top, const RulesFolder& rules_folder, LoadedScenario& out) {
  const toml::array* a = top.array_of_tables("barriers");
  if (!a) return;
  const fs::path& rules_dir = rules_folder.path;
  const sim::Scenario& sc = out.scenario;
  std::vector<std::string> line_names;
  for (const auto& l : sc.lines) line_names.push_back(l.name);
  std::map<fs::path, std::pair<design::BarrierRuleSet, design::EnergyClassTable>> cache;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const TomlTable t = top.element(
        "barriers", *a, i,
        {"name", "line", "rules", "design_block", "free_board_diameter", "data_quality",
         "candidate", "acceptable_energy_exceedance", "acceptable_height_exceedance", "observed"});
    design::BarrierSpec b;
    b.name = t.required_string("name", "a name for the barrier");
    t.check("name", !b.name.empty(), "a non-empty name");
    for (const auto& other : out.barriers)
      t.check("name", other.name != b.name, "a name not used by another barrier");
    b.line = t.required_string("line", "the name of an observation line");
    t.check("line", std::find(line_names.begin(), line_names.end(), b.line) != line_names.end(),
            line_names.empty() ? std::string("an observation line's name (the scenario has no "
                                             "[[observation_lines]])")
                               : "the name of an observation line (" + quoted_list(line_names) + ")");

    // The rule set: a name in rules_dir, or a path relative to the scenario.
    b.rules = t.string("rules").value_or("peila-ronco-2009");
    const fs::path rules_file = names_a_path(b.rules) ? relative_to(top.file(), b.rules)
                                                      : rules_dir / (b.rules + ".toml");
    std::error_code ec;
    if (!fs::is_regular_file(rules_file, ec)) {
      const std::string folder = rules_folder.named(barrier_rule_sets_held(rules_dir));
      const std::string expected =
          fmt::format("a rule set of {} or a path to a rule-set TOML file", folder);
      if (t.has("rules"))
        t.fail("rules", expected + fmt::format(" ({} {})", rules_file.string(),
                                               fs::exists(rules_file, ec) ? "is not a file"
                                                                          : "does not exist"));
      // The default was looked for: say which, and how a rules folder of one's own gets it.
      t.missing("rules", fmt::format("the default rule set \"{}\" in {}: copy {}.toml and the "
                                     "class table it names (etag027-classes.toml) there, or give "
                                     "rules = a name or a path",
                                     b.rules, folder, b.rules));
    }
    auto cached = cache.find(rules_file);
    if (cached == cache.end()) {  // read once per file, however many barriers name it
      if (const auto kind = detail::rule_file_kind(rules_file);
          detail::is_other_rule_kind(kind, detail::RuleFileKind::barrier))
        t.fail("rules", fmt::format("a barrier rule set ({} is {}; the rules folder is {})",
                                    rules_file.string(), detail::describe(kind),
                                    rules_folder.named(barrier_rule_sets_held(rules_dir))));
      design::BarrierRuleSet rules = load_rule_set_file(rules_file);
      design::EnergyClassTable classes =
          load_energy_classes_file(energy_classes_file(rules, rules_file, rules_folder));
      cached = cache.emplace(rules_file, std::make_pair(std::move(rules), std::move(classes))).first;
    }
    const design::BarrierRuleSet& rules = cached->second.first;
    const design::EnergyClassTable& classes = cached->second.second;

    b.design_block = read_design_block(t, out.notes);
    b.free_board_diameter = positive_number(t, "free_board_diameter", "a diameter > 0 (m)");
    if (b.free_board_diameter)
      note_unit_slip(
          t, "free_board_diameter", "the free-board diameter", *b.free_board_diameter,
          {kLargestFreeBoardDiameter, "m", "mm", ", the diameter of a block of over 1 000 t"},
          out.notes);

    // Data-quality answers: exactly the questions the rule set asks.
    const auto questions = design::data_quality_questions(rules);
    std::vector<std::string> asked;
    for (const auto& [q, answers] : questions) asked.push_back(q);
    const auto dq = t.subtable("data_quality", {});
    if (dq) {
      for (auto&& [k, v] : dq->table()) {
        const std::string q(k.str());
        if (!questions.count(q))
          throw InputError(top.file(), static_cast<long>(k.source().begin.line), dq->field(q),
                           "a question the rule set does not ask",
                           asked.empty() ? fmt::format("no data_quality (rule set {} asks none)", rules.name)
                                         : fmt::format("one of the questions of rule set {}: {}",
                                                       rules.name, quoted_list(asked)));
        b.data_quality[q] = dq->required_string(q, "an answer (a string)");
      }
    }
    // Every unanswered question at once: one at a time took a run for each.
    std::vector<std::string> unanswered, wanted;
    for (const auto& [q, answers] : questions)
      if (!b.data_quality.count(q)) {
        unanswered.push_back(q);
        wanted.push_back(fmt::format("{} = {}", q, quoted_list(answers, " or ")));
      }
    if (unanswered.size() > 1) {
      std::string list, names;
      for (std::size_t i = 0; i < wanted.size(); ++i) {
        list += (i ? "; " : "") + wanted[i];
        names += (i == 0 ? "" : i + 1 == unanswered.size() ? " and " : ", ") + unanswered[i];
      }
      throw InputError(top.file(), dq ? dq->line() : t.line(), t.field("data_quality"),
                       "no answer to " + names,
                       fmt::format("an answer to each question of rule set {}: {}", rules.name, list));
    }
    for (const auto& [q, answers] : questions) {
      const std::string expected = fmt::format("{} (asked by rule set {})", quoted_list(answers, " or "),
                                               rules.name);
      const auto it = b.data_quality.find(q);
      if (it == b.data_quality.end()) {
        if (dq) dq->missing(q, expected);
        throw InputError(top.file(), t.line(), t.field("data_quality") + "." + q, "nothing", expected);
      }
      if (std::find(answers.begin(), answers.end(), it->second) == answers.end()) dq->fail(q, expected);
    }

    if (const auto c =
            t.subtable("candidate", {"energy_class", "mel", "sel", "height", "elongation_mel",
                                     "elongation_sel", "distance_to_object", "residual_height"})) {
      b.candidate = read_candidate(*c, classes);
      note_candidate(*c, *b.candidate, classes, out.notes);
    }
    for (const char* key : {"acceptable_energy_exceedance", "acceptable_height_exceedance"}) {
      const auto p = t.number(key);
      if (!p) continue;
      t.check(key, *p > 0 && *p < 1, "a probability in (0, 1)");
      if (!b.candidate)
        t.fail(key, "no acceptable probability without a [barriers.candidate] (without one the "
                    "barrier is a design and reports only the advisory lines)");
      (std::string_view(key) == "acceptable_energy_exceedance" ? b.acceptable_energy_exceedance
                                                              : b.acceptable_height_exceedance) = p;
    }
    std::optional<design::ObservedSample> observed;
    if (const auto f = t.string("observed")) {
      t.check("observed", !f->empty(), "a CSV file of observed speeds, heights, energies");
      b.observed_file = *f;
      observed =
          read_observed(*t.file_path("observed", "CSV file of observed crossings"), out.notes);
    }
    out.barriers.push_back(std::move(b));
    out.barrier_rules.push_back(rules);
    out.barrier_rules_files.push_back(rules_file);
    out.barrier_classes.push_back(classes);
    out.barrier_observed.push_back(std::move(observed));
  }
}

}  // namespace

LoadedScenario load_scenario(const std::filesystem::path& scenario_file, const RulesFolder& rules) {
  const fs::path& rules_dir = rules.path;
  LoadedScenario out;
  out.file = scenario_file;
  out.text = read_text(scenario_file, "scenario file (TOML)");
  const toml::table root = parse_toml(scenario_file, out.text);
  const TomlTable top(scenario_file, root, "", 0,
                      {"scenario", "simulation", "profile", "materials", "blocks", "sources",
                       "observation_lines", "barriers", "quarries"});

  const auto head = top.subtable("scenario", {"name", "description", "materials_file"});
  if (!head) top.missing("scenario", "a [scenario] table with a name");
  out.scenario.name = head->required_string("name", "a name for the scenario");
  head->check("name", !out.scenario.name.empty(), "a non-empty name");
  out.description = head->string("description").value_or("");
  if (auto mf = head->file_path("materials_file", "materials file (TOML)"))
    out.materials_file = *mf;
  else
    out.materials_file = rules_dir / "materials.toml";

  out.scenario.settings = read_simulation(top);
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
    for (const auto& q : out.quarries) {
      out.notes.insert(out.notes.end(), q.notes.begin(), q.notes.end());
      profiles.push_back(&q.scenario.profile);
    }
    note_unused_materials(top, out.scenario.materials, profiles, out.notes);
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
  read_lines(top, out.scenario, out.notes);
  read_barriers(top, rules, out);
  return out;
}

void check_trajectory_count(const sim::Scenario& sc, const std::filesystem::path& file, long line,
                            const std::string& field, const std::string& found,
                            const std::string& what) {
  // Sources × blocks × throws in a 64-bit count (it wrapped): at most 2^53, exact as a double.
  const long double n = static_cast<long double>(sc.sources.size()) * sc.blocks.size() *
                        sc.settings.throws;
  if (n > 9007199254740992.0L)
    throw InputError(file, line, field, found,
                     fmt::format("at most 2^53 trajectories {} ({}{}{} sources × {} blocks × {} "
                                 "throws are {:.3g})",
                                 what.empty() ? "in all" : "a section", what,
                                 what.empty() ? "" : ": ", sc.sources.size(), sc.blocks.size(),
                                 sc.settings.throws, static_cast<double>(n)));
}

}  // namespace pierre::io
