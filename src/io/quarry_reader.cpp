// The quarry reader (docs/quarry.md) and quarry rule sets. The profile, blocks and sources of a
// section are read by the scenario reader's own readers (section_readers.hpp): one format.
#include "pierre/io/quarry_reader.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "bootstrap_fields.hpp"
#include "csv_table.hpp"
#include "pierre/io/rule_set_reader.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "rule_kind.hpp"
#include "section_readers.hpp"
#include "toml_fields.hpp"

namespace pierre::io {
namespace {

namespace fs = std::filesystem;
using detail::CsvTable;
using detail::describe;
using detail::line_of;
using detail::parse_toml;
using detail::read_text;
using detail::relative_to;
using detail::TomlTable;

// ---- rule sets ----

design::QuarryRuleSet read_rules(const fs::path& file, const std::string& stem) {
  const std::string text = read_text(file, "quarry rule set (TOML)");
  const toml::table root = parse_toml(file, text);
  const TomlTable top(file, root, "", 0,
                      {"rule_set", "toe", "governing", "retention", "ritchie", "sample", "fit",
                       "clauses"});
  design::QuarryRuleSet r;
  const auto head = top.subtable("rule_set", {"name", "title", "source"});
  if (!head) top.missing("rule_set", "a [rule_set] table with title and source");
  r.name = head->string("name").value_or(stem);
  r.file = file.string();
  r.title = head->required_string("title", "a title for the rule set");
  r.source = head->required_string("source", "a string citing where the rules come from");

  // [toe], [retention] and [ritchie] may be left out: design-checks.md §2's defaults (a 15°
  // floor angle, a 90 % retention target, 0.2·H + 4.5 m) are QuarryRuleSet's.
  if (const auto toe = top.subtable("toe", {"floor_angle", "source"})) {
    r.floor_angle_deg = toe->number("floor_angle", r.floor_angle_deg);
    toe->check("floor_angle", r.floor_angle_deg > 0 && r.floor_angle_deg < 90,
               "a floor angle in (0, 90) degrees");
  }

  const auto gov = top.subtable("governing", {"use", "percentile", "lognormal_percentile", "source"});
  if (!gov) top.missing("governing", "a [governing] table with use = [...]");
  const toml::array* use = gov->array("use");
  if (!use) gov->missing("use", "an array of \"percentile\", \"maximum\", \"lognormal\"");
  const std::string use_expected = "\"percentile\", \"maximum\" or \"lognormal\"";
  r.governing.clear();
  for (std::size_t i = 0; i < use->size(); ++i) {
    const toml::node& n = *use->get(i);
    const auto* s = n.as_string();
    const std::string field = fmt::format("{}[{}]", gov->field("use"), i);
    if (!s) throw InputError(file, line_of(n), field, describe(n), use_expected);
    if (s->get() == "percentile")
      r.governing.push_back(design::QuarryGoverning::percentile);
    else if (s->get() == "maximum")
      r.governing.push_back(design::QuarryGoverning::maximum);
    else if (s->get() == "lognormal")
      r.governing.push_back(design::QuarryGoverning::lognormal);
    else
      throw InputError(file, line_of(n), field, describe(n), use_expected);
  }
  if (r.governing.empty()) gov->fail("use", "at least one of " + use_expected);
  auto has = [&](design::QuarryGoverning g) {
    return std::find(r.governing.begin(), r.governing.end(), g) != r.governing.end();
  };
  const std::string pct = "a percentile in (0, 100]";
  if (has(design::QuarryGoverning::percentile)) {
    r.percentile = gov->required_number("percentile", pct + " (use has \"percentile\")");
    gov->check("percentile", r.percentile > 0 && r.percentile <= 100, pct);
  }
  if (has(design::QuarryGoverning::lognormal)) {
    r.lognormal_percentile =
        gov->required_number("lognormal_percentile", pct + " (use has \"lognormal\")");
    gov->check("lognormal_percentile", r.lognormal_percentile > 0 && r.lognormal_percentile < 100,
               "a percentile in (0, 100)");
  }

  if (const auto ret = top.subtable("retention", {"target", "source"})) {
    r.retention_target = ret->number("target", r.retention_target);
    ret->check("target", r.retention_target > 0 && r.retention_target <= 1, "a share in (0, 1]");
  }
  if (const auto rit = top.subtable("ritchie", {"factor", "offset", "source"})) {
    r.ritchie_factor = rit->number("factor", r.ritchie_factor);
    rit->check("factor", r.ritchie_factor >= 0, "a factor >= 0 (width = factor·H + offset)");
    r.ritchie_offset = rit->number("offset", r.ritchie_offset);
    rit->check("offset", r.ritchie_offset >= 0, "an offset >= 0 (m)");
  }

  if (const auto s = top.subtable("sample", {"min_reached", "percentile", "tolerance", "confidence",
                                             "resamples", "source"})) {
    if (auto n = s->integer("min_reached")) {
      s->check("min_reached", *n >= 0, "an integer >= 0");
      r.min_reached = static_cast<std::size_t>(*n);
    }
    // `percentile` chose the percentile sample.size judged; it now judges RD_gov itself (the
    // value the zones use). An older rule file's key is still read, so it runs, and ignored.
    const double retired = s->number("percentile", 95.0);
    s->check("percentile", retired > 0 && retired <= 100, pct + " (read and ignored: sample.size "
                                                          "judges the governing distance)");
    r.sample_tolerance = s->number("tolerance", r.sample_tolerance);
    s->check("tolerance", r.sample_tolerance > 0, "a relative tolerance > 0");
    detail::read_bootstrap_size(*s, "confidence", "resamples", r.sample_confidence,
                                r.sample_resamples);
  }
  if (const auto f = top.subtable("fit", {"p_value", "source"})) {
    r.fit_p_value = f->number("p_value", r.fit_p_value);
    f->check("p_value", r.fit_p_value > 0 && r.fit_p_value < 1, "a p-value in (0, 1)");
  }
  if (const auto c = top.subtable("clauses", {})) {
    for (auto&& [k, v] : c->table()) {
      const std::string key(k.str());
      if (!v.as_string()) c->fail(key, "a string naming the clause");
      r.clauses[key] = *c->string(key);  // checked as text for the report
    }
  }
  return r;
}

// ---- geometry given ----

// A toe or height given is taken as it is (design-checks.md §2), but one typed onto the face
// changes every distance and every /H: the floor past a given toe should be what the finder
// would call floor (flatter than the floor angle), and a given H near crest z − toe z.
// Both are likely slips that every line of the section rests on (its distances, its /H, the
// groups it is pooled in): none passes unconfirmed, and --strict refuses them (new-user review:
// a toe typed onto the face left the zone lines at PASS).
void note_given_geometry(const TomlTable& q, const std::string& section,
                         const geometry::Profile& profile, const design::QuarryGeometryInput& in,
                         const design::QuarryGeometry& g, std::vector<InputNote>& notes) {
  auto at = [&](const char* key) { return line_of(*q.find(key)); };
  if (in.toe_x) {
    std::string steep;
    int count = 0;
    for (std::size_t j = static_cast<std::size_t>(g.floor_segment); j < profile.segment_count(); ++j) {
      const geometry::Segment& sg = profile.segment(j);
      const double angle = design::inclination_deg(sg.a, sg.b, g.direction);
      if (angle <= g.floor_angle_deg) continue;
      if (++count <= 3)
        steep += fmt::format("{}segment {} (x {:g} → {:g} m, {:.0f}°)", steep.empty() ? "" : ", ",
                             j, sg.a.x, sg.b.x, angle);
    }
    if (count > 0) {
      design::QuarryGeometryInput found = in;
      found.toe_x.reset();
      const auto f = design::quarry_geometry(profile, found);
      notes.push_back(
          {q.file(), at("toe"), q.field("toe"),
           fmt::format("the floor past the given toe (x = {:g} m) has {} segment{} steeper than "
                       "the rule set's floor angle of {:g}°: {}{}. Every distance from the toe, "
                       "and H, are measured from it; {}",
                       *in.toe_x, count, count == 1 ? "" : "s", g.floor_angle_deg, steep,
                       count > 3 ? ", ..." : "",
                       f ? fmt::format("the toe found from the section is at x = {:.2f} m",
                                       f->toe.x)
                         : "check the toe's x"),
           design::DoubtedInput{q.field("toe"), section, {}, *in.toe_x}});
    }
  }
  if (in.height && g.height_derived > 0 &&
      std::abs(*in.height - g.height_derived) > 0.1 * g.height_derived)
    notes.push_back(
        {q.file(), at("height"), q.field("height"),
         fmt::format("the height given (H = {:g} m) differs from crest z − toe z ({:.2f} m) by "
                     "{:.0f} %: every distance divided by H uses the given one",
                     *in.height, g.height_derived,
                     100 * std::abs(*in.height - g.height_derived) / g.height_derived),
         design::DoubtedInput{q.field("height"), section, {}, *in.height}});
}

// A catch bench or a work area past the end of the section's floor: a length typed in cm (300
// for 3 m) passes every range check, and the checks then compare it with ground the section
// does not model. Noted at its value, with what it would be in cm.
void note_beyond_floor(const TomlTable& q, const design::QuarrySpec& spec,
                       const design::QuarryGeometry& g, std::vector<InputNote>& notes) {
  auto text = [&](double v) {
    return fmt::format("the section's floor ends {:.2f} m from the toe, so the section cannot "
                       "say what reaches {:g} m; extend the floor, or check the unit (if it is "
                       "in cm, it is {:g} m)",
                       g.floor_length, v, v / 100);
  };
  if (spec.bench_width && *spec.bench_width > g.floor_length)
    notes.push_back({q.file(), line_of(*q.find("bench_width")), q.field("bench_width"),
                     fmt::format("bench width {:g} m: {}", *spec.bench_width,
                                 text(*spec.bench_width)),
                     design::DoubtedInput{q.field("bench_width"), spec.name, {"bench."},
                                          *spec.bench_width}});
  const toml::array* a = q.array_of_tables("work_areas");
  for (std::size_t i = 0; a && i < spec.work_areas.size(); ++i) {
    const design::WorkArea& w = spec.work_areas[i];
    if (!(w.distance > g.floor_length)) continue;
    const TomlTable t = q.element("work_areas", *a, i, {"name", "distance"});
    notes.push_back({q.file(), line_of(*t.find("distance")), t.field("distance"),
                     fmt::format("work area \"{}\" at {:g} m from the toe: {}", w.name, w.distance,
                                 text(w.distance)),
                     design::DoubtedInput{t.field("distance"), spec.name, {"zone." + w.name},
                                          w.distance}});
  }
}

// A source behind the crest (on the ground above the face, away from the floor): its blocks
// reach the floor only if they roll over the crest, and a section whose blocks all stop up
// there gives a zone of 0 m and a full bench from no evidence (new-user review: x = 3 m behind
// a crest at 8 m, "valid", and the run's zone read [0, 0.00] m). May be meant (loose blocks on
// the top bench): a note, not a doubt; the zone and bench lines WARN when too few reach the floor.
void note_sources_behind_crest(const TomlTable& q, const sim::Scenario& sc,
                               const design::QuarryGeometry& g, std::vector<InputNote>& notes) {
  const toml::node* n = q.find("sources");
  for (std::size_t i = 0; n && i < sc.sources.size(); ++i) {
    const double behind = (g.crest.x - sc.sources[i].position.x) * g.direction;
    if (!(behind > 0)) continue;
    const toml::array* a = n->as_array();
    const toml::node* at = a && i < a->size() ? a->get(i) : n;
    notes.push_back({q.file(), line_of(*at), fmt::format("{}[{}].x", q.field("sources"), i),
                     fmt::format("the source at x = {:g} m lies {:.2f} m behind the crest (x = "
                                 "{:.2f} m), above the face, not on it: its blocks reach the floor "
                                 "only if they roll over the crest; a release from the face lies "
                                 "between crest and toe (x = {:.2f} m)",
                                 sc.sources[i].position.x, behind, g.crest.x, g.toe.x),
                     std::nullopt});
  }
}

// ---- numbers ----

double coordinate(const TomlTable& t, const toml::node& c, const std::string& field,
                  const std::string& expected) {
  double v;
  if (const auto* iv = c.as_integer())
    v = static_cast<double>(iv->get());
  else if (const auto* fv = c.as_floating_point())
    v = fv->get();
  else
    throw InputError(t.file(), line_of(c), field, describe(c), expected);
  if (!std::isfinite(v)) throw InputError(t.file(), line_of(c), field, describe(c), expected);
  return v;
}

// ---- work areas, observed values ----

void read_work_areas(const TomlTable& q, design::QuarrySpec& spec) {
  const toml::array* a = q.array_of_tables("work_areas");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const TomlTable t = q.element("work_areas", *a, i, {"name", "distance"});
    design::WorkArea w;
    w.name = t.required_string("name", "a name for the work area (check id zone.<name>)");
    t.check("name",
            !w.name.empty() && w.name.find_first_of(" \t") == std::string::npos,
            "a non-empty name without spaces (it becomes the check id zone.<name>)");
    for (const auto& other : spec.work_areas)
      t.check("name", other.name != w.name, "a name not used by another work area of this section");
    w.distance = t.required_number("distance", "a horizontal distance from the toe >= 0 (m)");
    t.check("distance", w.distance >= 0, "a horizontal distance from the toe >= 0 (m)");
    spec.work_areas.push_back(std::move(w));
  }
}

void read_summary(const TomlTable& obs, std::string_view key, design::ObservedDistance& d) {
  const auto s = obs.subtable(key, {"p50", "p95", "max"});
  if (!s) return;
  for (std::string_view k : {"p50", "p95", "max"}) {
    const auto v = s->number(k);
    if (!v) continue;
    s->check(k, *v >= 0, "a distance >= 0 (m)");
    (k == "p50" ? d.p50 : k == "p95" ? d.p95 : d.max) = *v;
  }
  if (d.p50 && d.p95 && *d.p95 < *d.p50) s->fail("p95", "a P95 >= the P50");
  if (d.p95 && d.max && *d.max < *d.p95) s->fail("max", "a maximum >= the P95");
  if (d.p50 && d.max && *d.max < *d.p50) s->fail("max", "a maximum >= the P50");
}

void read_observed_csv(const fs::path& file, design::QuarryObserved& o) {
  const std::vector<std::string> columns = {"first_impact", "runout"};
  const auto allowed = detail::with_record_columns(columns);
  const CsvTable t = detail::read_csv(file, allowed, "first_impact and/or runout (m) (and id, note if wanted)",
                                      {{"first_impact_m", "first_impact"}, {"runout_m", "runout"}},
                                      allowed);  // a distance not measured for a block: empty
  const auto c_id = t.column("first_impact"), c_rd = t.column("runout");
  if (!c_id && !c_rd)
    throw InputError(file, t.header_line, "header", "neither first_impact nor runout",
                     "a column first_impact (m) and/or runout (m)");
  for (const auto& r : t.rows) {
    for (auto [c, dst, name] : {std::tuple{c_id, &o.id.metres, "first_impact"},
                                std::tuple{c_rd, &o.rd.metres, "runout"}}) {
      if (!c || r.cells[*c].empty()) continue;  // not measured for this block
      const double v = t.number(r, *c);
      if (!(v >= 0)) throw InputError(file, r.line, name, r.cells[*c], "a distance from the toe >= 0 (m)");
      dst->push_back(v);
    }
  }
}

void read_observed(const TomlTable& q, QuarrySection& out) {
  const auto obs = q.subtable("observed", {"file", "source", "count", "runout", "first_impact"});
  if (!obs) return;
  design::QuarryObserved& o = out.observed;
  o.source = obs->string("source").value_or("");
  // Raw values or summary values, not both: the raw ones would be used and the others dropped.
  if (obs->has("file"))
    for (const char* key : {"runout", "first_impact", "count"})
      if (obs->has(key))
        obs->fail(key, "either file (the raw observations) or summary values (runout, "
                       "first_impact, count), not both: with a file the summary follows from it");
  if (auto f = obs->file_path("file", "CSV file of observed distances")) read_observed_csv(*f, o);
  read_summary(*obs, "runout", o.rd);
  read_summary(*obs, "first_impact", o.id);
  if (auto n = obs->integer("count")) {
    obs->check("count", *n >= 1, "an integer >= 1 (observations behind the summary values)");
    o.rd.count = o.id.count = static_cast<std::size_t>(*n);
  }
  if (o.id.empty() && o.rd.empty())
    throw InputError(q.file(), obs->line(), obs->field("file"), "no observed values",
                     "file = \"...\" (a CSV with first_impact and/or runout) or runout/first_impact "
                     "= { p50, p95, max }");
  out.spec.observed_source = o.source;
}

}  // namespace

design::QuarryRuleSet load_quarry_rules(const std::string& name_or_path,
                                        const std::filesystem::path& rules_dir) {
  const fs::path file = rule_file(name_or_path, rules_dir);
  return read_rules(file, file.stem().string());
}

std::string section_label(std::size_t index, const std::string& name) {
  return fmt::format("quarries[{}] \"{}\"", index, name);
}

namespace {

// The section's rule set: a name in the rules folder or a path relative to the scenario, of
// the quarry kind; a file that is not there is said at the section's rules key.
void read_section_rules(const TomlTable& q, QuarrySection& s, const fs::path& file,
                        const RulesFolder& rules) {
  design::QuarrySpec& spec = s.spec;
  const fs::path& rules_dir = rules.path;
  spec.rules = q.string("rules").value_or(design::kDefaultQuarryRules);
  q.check("rules", !spec.rules.empty(), "a rule set name or path");
  const fs::path rules_file = scenario_rule_file(spec.rules, file, rules_dir);
  if (const auto kind = detail::rule_file_kind(rules_file);
      detail::is_other_rule_kind(kind, detail::RuleFileKind::quarry))
    q.fail("rules", fmt::format("a quarry rule set (e.g. \"quarry-thesis-2015\", "
                                "\"quarry-conservative\"; {} is {})",
                                rules_file.string(), detail::describe(kind)));
  try {
    s.rules = load_quarry_rules(rules_file.string(), rules_dir);
  } catch (const InputError& e) {
    // An error inside the rule file is reported there; only a file that is not there (or
    // cannot be read) is said at the scenario's rules key.
    if (e.field() != "file") throw;
    q.fail("rules", fmt::format("a rule set in {} or a path to a .toml file (e.g. "
                                "\"quarry-thesis-2015\", \"quarry-conservative\"; {}: {})",
                                rules.named(), e.file().string(), e.found()));
  }
  s.rules_file = rules_file;
}

// The probabilities of exceedance asked for (each gives a row of the exceedance table).
void read_exceedance(const TomlTable& q, design::QuarrySpec& spec, const fs::path& file) {
  if (const toml::array* ex = q.array("exceedance")) {
    spec.exceedance.clear();
    const std::string expected = "a probability of exceedance in (0, 1)";
    for (std::size_t k = 0; k < ex->size(); ++k) {
      const toml::node& e = *ex->get(k);
      const std::string field = fmt::format("{}[{}]", q.field("exceedance"), k);
      const double v = coordinate(q, e, field, expected);
      if (!(v > 0 && v < 1))
        throw InputError(file, line_of(e), field, describe(e), detail::probability_expected(expected, v));
      if (std::find(spec.exceedance.begin(), spec.exceedance.end(), v) != spec.exceedance.end())
        throw InputError(file, line_of(e), field, describe(e),
                         "a probability not already in the list (each gives one row)");
      spec.exceedance.push_back(v);
    }
  }
}

// Crest, toe and H as given or found (design-checks.md §2); a toe inside a segment cuts it
// there, so that the floor starts at a vertex.
void read_section_geometry(const TomlTable& q, QuarrySection& s, const fs::path& file) {
  design::QuarrySpec& spec = s.spec;
  sim::Scenario& sc = s.scenario;
  // A toe or crest off the section is the value's own error, at its own key.
  for (const auto& [key, x] : {std::pair{"toe", spec.geometry.toe_x},
                               std::pair{"crest", spec.geometry.crest_x}})
    if (x)
      q.check(key, *x >= sc.profile.x_min() && *x <= sc.profile.x_max(),
              fmt::format("a {} x inside the section, {:g} to {:g} m", key, sc.profile.x_min(),
                          sc.profile.x_max()));
  auto g = design::quarry_geometry(sc.profile, spec.geometry);
  if (g && !g->toe_vertex) {
    // A toe given inside a segment: the floor is the profile past the toe (design-checks.md
    // §2), so the segment is cut there into two collinear pieces (the same physics,
    // model-2d.md §2) and the floor starts at the new vertex.
    std::vector<geometry::ProfileIssue> issues;
    auto cut = sc.profile.split_at(static_cast<std::size_t>(g->floor_segment), g->toe, &issues);
    if (!cut) {  // a toe a hair from a vertex: the section cannot be cut there
      const char* key = spec.geometry.toe_x ? "toe" : "profile";
      const toml::node* n = q.find(key);
      throw InputError(file, n ? line_of(*n) : q.line(), q.field(key),
                       fmt::format("a toe at x = {:g} m that cuts segment {} of the section ({})",
                                   g->toe.x, g->floor_segment,
                                   issues.empty() ? "no reason given" : issues.front().what),
                       "a toe on a vertex of the section or clear of its ends");
    }
    sc.profile = std::move(*cut);
    g = design::quarry_geometry(sc.profile, spec.geometry);
  }
  if (!g) {
    const char* key = spec.geometry.toe_x ? "toe" : spec.geometry.crest_x ? "crest" : "profile";
    const toml::node* n = q.find(key);
    throw InputError(file, n ? line_of(*n) : q.line(), q.field(key), g.error,
                     "a section with a crest above a floor flatter than " +
                         fmt::format("{}°", s.rules.floor_angle_deg) +
                         " (or toe = x and crest = x of the section)");
  }
  s.geometry = *g;
  sc.settings.floor_segment = s.geometry.floor_segment;
  note_given_geometry(q, spec.name, sc.profile, spec.geometry, s.geometry, s.notes);
  note_beyond_floor(q, spec, s.geometry, s.notes);
  note_sources_behind_crest(q, sc, s.geometry, s.notes);
}

// What the sections say together: a group follows one rule set, gives one kind of observed
// values, and takes no name of a section outside it. Said at the later section's table.
void check_groups(const std::vector<QuarrySection>& out, const TomlTable& top, const toml::array& a) {
  auto section_table = [&](std::size_t i) { return top.element("quarries", a, i, {}); };
  // Sections pooled in one group must follow one rule set.
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (!out[i].spec.group.empty() && out[i].spec.group == out[j].spec.group &&
          out[i].rules.name != out[j].rules.name) {
        const TomlTable q = section_table(i);
        q.fail(q.has("rules") ? "rules" : "group",
               fmt::format("the rule set of the other sections of group \"{}\" (\"{}\")",
                           out[i].spec.group, out[j].rules.name));
      }
  // A group's observed values are raw observations pooled, or one section's summary values:
  // a mix would drop the summary values without a word.
  auto raw = [](const QuarrySection& s) {
    return !s.observed.rd.metres.empty() || !s.observed.id.metres.empty();
  };
  auto summary = [](const QuarrySection& s) {
    for (const auto* d : {&s.observed.rd, &s.observed.id})
      if (d->p50 || d->p95 || d->max) return true;
    return false;
  };
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (!out[i].spec.group.empty() && out[i].spec.group == out[j].spec.group &&
          ((raw(out[i]) && summary(out[j])) || (summary(out[i]) && raw(out[j])))) {
        const TomlTable q = section_table(i);
        q.fail("observed", fmt::format("observed values of the kind the other sections of group "
                                       "\"{}\" give (quarries[{}] gives {}): raw observations "
                                       "(file) in every section, or summary values",
                                       out[i].spec.group, j, raw(out[j]) ? "a file" : "summary values"));
      }
  // A report row is a lone section or a group: a group may not take the name of a section
  // outside it, or two rows would both be called so.
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t j = 0; j < out.size(); ++j)
      if (!out[i].spec.group.empty() && out[i].spec.group == out[j].spec.name &&
          out[j].spec.group != out[i].spec.group) {
        const TomlTable q = section_table(i);
        q.fail("group", fmt::format("a group name that no section outside the group has "
                                    "(quarries[{}] is named \"{}\")",
                                    j, out[j].spec.name));
      }
}

}  // namespace

std::string sections_count_text(const std::vector<QuarrySection>& sections) {
  double total = 0;
  std::string counted;
  for (const QuarrySection& s : sections) {
    total += static_cast<double>(s.scenario.trajectory_count());
    counted += (counted.empty() ? "" : "; ") + section_label(&s - sections.data(), s.spec.name) +
               ": " + trajectory_count_text(s.scenario);
  }
  if (sections.size() > 1) counted += fmt::format("; {:.3g} in all", total);
  return counted;
}

std::vector<QuarrySection> read_quarries(const toml::table& root, const std::filesystem::path& file,
                                         const RulesFolder& rules,
                                         const std::vector<model::Material>& materials,
                                         const sim::SimulationSettings& settings) {
  std::vector<QuarrySection> out;
  // Its root read as the scenario reader reads it: a section typed inside a [[quarries]] entry
  // is told so.
  const TomlTable top(file, root, "", 0, detail::kScenarioSections);
  const toml::array* a = top.array_of_tables("quarries");
  if (!a) return out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const TomlTable q = top.element(
        "quarries", *a, i,
        {"name", "group", "rules", "toe", "crest", "height", "bench_width", "seed", "exceedance",
         "profile", "blocks", "sources", "work_areas", "observed"});
    QuarrySection s;
    design::QuarrySpec& spec = s.spec;
    spec.name = q.required_string("name", "a name for the quarry section");
    q.check("name", !spec.name.empty(), "a non-empty name");
    q.check("name", names.insert(spec.name).second, "a name not used by another quarry section");
    spec.group = q.string("group").value_or("");
    read_section_rules(q, s, file, rules);

    spec.geometry.crest_x = q.number("crest");
    spec.geometry.toe_x = q.number("toe");
    spec.geometry.height = q.number("height");
    if (spec.geometry.height) q.check("height", *spec.geometry.height > 0, "a height H > 0 (m)");
    spec.geometry.floor_angle_deg = s.rules.floor_angle_deg;
    spec.bench_width = q.number("bench_width");
    if (spec.bench_width) q.check("bench_width", *spec.bench_width > 0, "a bench width > 0 (m)");
    read_exceedance(q, spec, file);

    sim::Scenario& sc = s.scenario;
    sc.name = spec.name;
    sc.materials = materials;
    sc.settings = settings;
    if (auto seed = q.integer("seed")) {
      q.check("seed", *seed >= 0, "an integer >= 0");
      sc.settings.seed = static_cast<std::uint64_t>(*seed);
      s.seed_given = true;
    } else {
      sc.settings.seed = section_seed(settings.seed, i);  // independent streams, pooled sections
    }
    const std::size_t notes_before = s.notes.size();
    sc.profile = detail::read_profile(q, materials, "quarries", s.notes);
    detail::read_blocks(q, s.block_groups, sc.blocks, "quarries", s.notes);
    detail::read_sources(q, sc, "quarries", s.notes);
    // A slip in this section's blocks or sources bears on this section's lines (and on those of
    // a group it is pooled in, app/quarries.cpp), not on the other sections'.
    for (std::size_t k = notes_before; k < s.notes.size(); ++k)
      if (s.notes[k].doubt && s.notes[k].doubt->subject.empty()) s.notes[k].doubt->subject = spec.name;
    {
      // Each section is a run of its own: its count, not the sum, is what must stay countable.
      // (`settings` may come from elsewhere than `root`: then the message names no line.)
      const toml::node* throws = root.at_path("simulation.throws").node();
      check_trajectory_count(sc, file, throws ? line_of(*throws) : 0, "simulation.throws",
                             std::to_string(settings.throws),
                             section_label(i, spec.name));
    }
    read_work_areas(q, spec);
    read_observed(q, s);

    read_section_geometry(q, s, file);
    out.push_back(std::move(s));
  }
  check_groups(out, top, *a);
  return out;
}

}  // namespace pierre::io
