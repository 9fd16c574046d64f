// The [[barriers]] entries of a scenario (barrier_reader.hpp).
#include "barrier_reader.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "csv_table.hpp"
#include "pierre/design/number_text.hpp"
#include "pierre/io/rule_set_reader.hpp"
#include "rule_kind.hpp"
#include "section_readers.hpp"

namespace pierre::io {
namespace {

namespace fs = std::filesystem;
using detail::CsvTable;
using detail::line_of;
using detail::parse_toml;
using detail::quoted_list;
using detail::read_text;
using detail::relative_to;
using detail::TomlTable;
using model::InputLimits;

// The design block's density, where it is given, said when it is not a rock's: the unit slip
// the blocks' densities are checked for (section_readers.cpp).
// `barrier`: whose design block it is; its energies and their exceedance rest on it.
void note_density(const TomlTable& d, double density, const std::string& barrier,
                  std::vector<InputNote>& notes) {
  if (density >= detail::kRockDensityMin && density <= detail::kRockDensityMax) return;
  notes.push_back({d.file(), line_of(*d.find("density")), d.field("density"),
                   fmt::format("the design block's density {:g} kg/m³ is {}", density,
                               detail::density_slip(density, "an energy 1000 times too small")),
                   design::DoubtedInput{d.field("density"), barrier,
                                        {"energy.", "exceedance.energy"}, density}});
}

design::DesignBlock read_design_block(const TomlTable& t, const std::string& barrier,
                                      std::vector<InputNote>& notes) {
  const std::string expected =
      "\"largest\", { percentile = p } (of the block volumes, optional density) or "
      "{ volume = m³, density = kg/m³ }";
  design::DesignBlock b;
  const toml::node* n = t.find("design_block");
  if (!n) return b;  // default: the largest block thrown, by mass
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
      note_density(*d, b.density, barrier, notes);
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
  d->check("volume", mass <= InputLimits::max_block_mass,
           detail::block_mass_limit("a design block", b.volume, b.density, mass, true));
  note_density(*d, b.density, barrier, notes);
  return b;
}

std::optional<double> positive_number(const TomlTable& t, std::string_view key,
                                      std::string_view expected) {
  const auto v = t.number(key);
  if (v) t.check(key, *v > 0, expected);
  return v;
}

// A barrier's value far beyond its kind: most likely typed in the smaller unit
// (mm for m, J for kJ), which passes every range check. Noted at the value, with what it is in
// that unit. `beyond`: what the limit stands for.
struct UnitSlip {
  double limit;
  const char* unit;
  const char* small_unit;  // a thousandth of `unit`
  std::string beyond;
};

// A number as typed: 15 significant digits, no exponent below 10^15 (3000000, not 3e+06; 1.1).
std::string typed(double v) { return design::number_text(v, 15); }

// `lines`: the check ids of barrier `barrier` that rest on the value (none: doubt none).
void note_unit_slip(const TomlTable& t, std::string_view key, std::string_view what, double v,
                    const UnitSlip& u, std::vector<InputNote>& notes, const std::string& barrier = "",
                    std::vector<std::string> lines = {}) {
  if (!(v > u.limit)) return;
  std::optional<design::DoubtedInput> doubt;
  if (!lines.empty()) doubt = design::DoubtedInput{t.field(key), barrier, std::move(lines), v};
  notes.push_back({t.file(), line_of(*t.find(key)), t.field(key),
                   fmt::format("{} {} {} is more than {} {}{}: it is read in {}; if it was "
                               "meant in {}, it is {} {}",
                               what, typed(v), u.unit, typed(u.limit), u.unit, u.beyond, u.unit,
                               u.small_unit, typed(v / 1000), u.unit),
                   doubt});
}

// An acceptable probability of exceedance is a fraction, while every output shows it in %: 0.5
// copied from a report's "0.5 %" is read as 50 %, and the exceedance line passes on it. Design
// practice accepts some tenths of a percent to a few percent; above kLargestAcceptableExceedance
// it is noted, at its value, and the line resting on it (`line`) cannot PASS.
constexpr double kLargestAcceptableExceedance = 0.1;
void note_percent_as_fraction(const TomlTable& t, std::string_view key, double p,
                              const std::string& barrier, const std::string& line,
                              std::vector<InputNote>& notes) {
  if (!(p > kLargestAcceptableExceedance)) return;
  notes.push_back({t.file(), line_of(*t.find(key)), t.field(key),
                   fmt::format("an acceptable probability of {} is {} %: it is a fraction (0.01 "
                               "is 1 %); if it was meant in %, it is {}",
                               typed(p), typed(100 * p), typed(p / 100)),
                   design::DoubtedInput{t.field(key), barrier, {line}, p}});
}

// Rockfall barriers are some metres high and stretch some metres; their energies are up to
// some thousands of kJ (ETAG 027's last class: MEL > 4 500 kJ). The limits are far beyond
// those, to catch only a value in mm or J.
constexpr double kTallestBarrier = 20.0;            // m
constexpr double kLongestElongation = 30.0;         // m
constexpr double kLargestBarrierEnergy = 30e3;      // kJ
constexpr double kLargestFreeBoardDiameter = 10.0;  // m: a block of some 1 400 t at 2650 kg/m³

// The candidate's MEL, SEL and height so noted doubt the lines of barrier `barrier` that pass
// on them (design::doubt_passes); an elongation in mm only makes its check stricter.
void note_candidate(const TomlTable& c, const design::CandidateBarrier& k, const std::string& barrier,
                    const design::EnergyClassTable& classes, std::vector<InputNote>& notes) {
  const design::EnergyClass* top = nullptr;
  for (const auto& e : classes.classes)
    if (!top || e.mel_kJ >= top->mel_kJ) top = &e;  // the last of equals: the open-ended one
  // The largest class's own capacity of the same kind, MEL beside a MEL, SEL beside a SEL.
  auto energy = [&](const char* name, double top_value) {
    return UnitSlip{kLargestBarrierEnergy, "kJ", "J",
                    top ? fmt::format(" (the largest class of {}: {} {}{} kJ)", classes.name, name,
                                      top->open_ended ? "> " : "", typed(top_value))
                        : ""};
  };
  const UnitSlip length{kTallestBarrier, "m", "mm", ""};
  const UnitSlip stretch{kLongestElongation, "m", "mm", ""};
  if (k.mel_kJ)
    note_unit_slip(c, "mel", "the candidate's MEL", *k.mel_kJ, energy("MEL", top ? top->mel_kJ : 0),
                   notes, barrier, {"energy.mel", "exceedance.energy"});
  if (k.sel_kJ)
    note_unit_slip(c, "sel", "the candidate's SEL", *k.sel_kJ, energy("SEL", top ? top->sel_kJ : 0),
                   notes, barrier, {"energy.sel"});
  if (k.height)
    note_unit_slip(c, "height", "the candidate's height", *k.height, length, notes, barrier,
                   {"height.interception", "exceedance.height"});
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
  // Speed and height may go without their unit (m/s, m, as the profile's x and z do); an energy
  // may not: J or kJ is the slip that matters.
  const auto allowed = detail::with_record_columns(columns);
  const CsvTable t = detail::read_csv(file, allowed,
                                      "speed_m_s, height_m and/or energy_kJ (and id, note if wanted)",
                                      {{"speed", "speed_m_s"}, {"height", "height_m"}},
                                      allowed);  // a value not measured for a block: empty
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
           fmt::format("{} {} {}{} is more than {} {}, {}: the column is read in {}; if it "
                       "is in {}, {} is {:.3g} {}",
                       c.name, typed(first), c.unit,
                       beyond > 1 ? fmt::format(" (and {} more rows like it)", beyond - 1) : "",
                       typed(c.limit), c.unit, c.beyond, c.unit, c.slip, typed(first),
                       first * c.slip_factor, c.unit),
           {}});
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

}  // namespace

namespace detail {

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
    b.rules = t.string("rules").value_or(design::kDefaultBarrierRules);
    const fs::path rules_file = scenario_rule_file(b.rules, top.file(), rules_dir);
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

    b.design_block = read_design_block(t, b.name, out.notes);
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
      note_candidate(*c, *b.candidate, b.name, classes, out.notes);
    }
    for (const char* key : {"acceptable_energy_exceedance", "acceptable_height_exceedance"}) {
      const auto p = t.number(key);
      if (!p) continue;
      t.check(key, *p > 0 && *p < 1, probability_expected("a probability in (0, 1)", *p));
      if (!b.candidate)
        t.fail(key, "no acceptable probability without a [barriers.candidate] (without one the "
                    "barrier is a design and reports only the advisory lines)");
      const bool energy = std::string_view(key) == "acceptable_energy_exceedance";
      (energy ? b.acceptable_energy_exceedance : b.acceptable_height_exceedance) = p;
      note_percent_as_fraction(t, key, *p, b.name, energy ? "exceedance.energy" : "exceedance.height",
                               out.notes);
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

}  // namespace detail
}  // namespace pierre::io
