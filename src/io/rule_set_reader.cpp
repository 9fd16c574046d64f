// Barrier rule sets and energy class tables (rules/*.toml; shapes in the headers of
// rules/thesis-2015.toml and rules/etag027-classes.toml).
#include "pierre/io/rule_set_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "bootstrap_fields.hpp"
#include "rule_kind.hpp"
#include "section_readers.hpp"
#include "text_file.hpp"
#include "toml_fields.hpp"

namespace pierre::io {
namespace {

namespace fs = std::filesystem;
using detail::describe;
using detail::line_of;
using detail::TomlTable;

const char* const kCheckIds[] = {"energy.mel",        "energy.sel", "height.interception",
                                 "elongation",        "exceedance.energy",
                                 "exceedance.height", "fit.v",      "fit.h",
                                 "fit.E",             "sample.size", "reach",
                                 "design"};

using detail::parse_toml;  // shared with the scenario's section readers
using detail::read_text;

// The [rule_set] table, its kind checked.
TomlTable header(const TomlTable& top, std::string_view kind,
                 std::initializer_list<std::string_view> allowed) {
  const auto h = top.subtable("rule_set", allowed);
  if (!h) top.missing("rule_set", fmt::format("a [rule_set] table with kind = \"{}\"", kind));
  const std::string k = h->required_string("kind", fmt::format("kind = \"{}\"", kind));
  h->check("kind", k == kind, fmt::format("\"{}\" (this file is read as a {})", kind,
                                          kind == "barrier" ? "barrier rule set" : "class table"));
  return *h;
}

double positive(const TomlTable& t, std::string_view key, std::string_view expected) {
  const double v = t.required_number(key, expected);
  t.check(key, v > 0, expected);
  return v;
}

// A partial factor and each part of one: at least 1. Below 1 it designs for less than the
// characteristic value (new-user review: γF = 0.5 gave v_d half of v_k without a word); 1 is a
// factor left out, as a comparison with a plain percentile may want.
double partial_factor(const TomlTable& t, std::string_view key, std::string_view expected) {
  const double v = t.required_number(key, expected);
  t.check(key, v >= 1, expected);
  return v;
}

std::string join_names(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

design::FactorPart read_part(const TomlTable& parts, const std::string& name) {
  const toml::node* n = parts.find(name);
  const auto* tbl = n->as_table();
  if (!tbl) parts.fail(name, "a table [parts.NAME]");
  const TomlTable t(parts.file(), *tbl, parts.field(name), line_of(*n),
                    {"symbol", "choice", "options", "value", "source"});
  design::FactorPart p;
  p.symbol = t.required_string("symbol", "the part's symbol, e.g. \"γTr\"");
  p.source = t.required_string("source", "a string citing where the values come from");
  const bool has_choice = t.has("choice"), has_value = t.has("value");
  if (has_choice == has_value)
    throw InputError(t.file(), t.line(), t.field(has_choice ? "value" : "choice"),
                     has_choice ? "both choice and value" : "neither choice nor value",
                     "either choice = \"question\" with options = { answer = factor, ... }, or "
                     "value = factor");
  if (has_value) {
    if (t.has("options")) t.fail("options", "no options beside value (a fixed part)");
    p.value = partial_factor(t, "value", "a factor >= 1");
    return p;
  }
  p.choice = t.required_string("choice", "the data-quality question, e.g. \"trajectory\"");
  t.check("choice", !p.choice.empty(), "a non-empty question name");
  const auto opts = t.subtable("options", {});
  if (!opts) t.missing("options", "options = { answer = factor, ... }");
  for (auto&& [k, v] : opts->table()) {
    const std::string answer(k.str());
    const double f = partial_factor(*opts, answer, "a factor >= 1");
    p.options.emplace(answer, f);
  }
  if (p.options.empty())
    throw InputError(t.file(), opts->line(), t.field("options"), "no option",
                     "at least one answer = factor");
  return p;
}

design::FactorDefinition read_factor(const TomlTable& factors, std::string_view key,
                                     std::string symbol, const TomlTable* parts,
                                     const std::map<std::string, std::string>& sources) {
  design::FactorDefinition f;
  f.symbol = std::move(symbol);
  const std::string expected =
      "a factor >= 1, or an array of part names (tables of [parts]) whose product it is";
  const toml::node* n = factors.find(key);
  if (!n) factors.missing(key, expected);
  if (const auto* a = n->as_array()) {
    if (a->empty()) factors.fail(key, expected);
    std::vector<std::string> known;
    if (parts)
      for (auto&& [k, v] : parts->table()) known.emplace_back(k.str());
    for (const toml::node& e : *a) {
      const auto* s = e.as_string();
      const bool ok = s && std::find(known.begin(), known.end(), s->get()) != known.end();
      if (!ok)
        throw InputError(factors.file(), line_of(e), factors.field(key), describe(e),
                         known.empty() ? std::string("a part defined in a [parts.NAME] table (there is none)")
                                       : "the name of a [parts] table (" + join_names(known) + ")");
      f.parts.push_back(read_part(*parts, s->get()));
    }
  } else {
    f.value = partial_factor(factors, key, expected);
  }
  const auto it = sources.find(std::string(key));
  if (it != sources.end()) f.source = it->second;
  return f;
}

}  // namespace

bool names_a_path(const std::string& s) {
  return s.find('/') != std::string::npos ||
         (s.size() >= 5 && s.compare(s.size() - 5, 5, ".toml") == 0);
}

fs::path rule_file(const std::string& name_or_path, const fs::path& rules_dir) {
  return names_a_path(name_or_path) ? fs::path(name_or_path) : rules_dir / (name_or_path + ".toml");
}

fs::path scenario_rule_file(const std::string& name_or_path, const fs::path& scenario_file,
                            const fs::path& rules_dir) {
  return names_a_path(name_or_path) ? detail::relative_to(scenario_file, name_or_path)
                                    : rule_file(name_or_path, rules_dir);
}

design::BarrierRuleSet load_rule_set(const std::string& name_or_path, const fs::path& rules_dir) {
  return load_rule_set_file(rule_file(name_or_path, rules_dir));
}

design::BarrierRuleSet load_rule_set_file(const fs::path& file) {
  const std::string text = read_text(file, "barrier rule set (TOML)");
  const toml::table root = parse_toml(file, text);
  const TomlTable top(file, root, "", 0,
                      {"rule_set", "factors", "parts", "free_board", "clauses", "sources"});
  const TomlTable h =
      header(top, "barrier",
             {"kind", "name", "title", "source", "percentile", "governing", "design_on", "classes",
              "sample_tolerance", "sample_confidence", "sample_resamples", "fit_p_value",
              "min_crossings"});
  design::BarrierRuleSet r;
  r.name = h.string("name").value_or(file.stem().string());
  r.file = file.string();
  h.check("name", !r.name.empty(), "a non-empty name");
  r.title = h.required_string("title", "a title");
  r.source = h.required_string("source", "a string citing the rule set");
  r.percentile = h.required_number("percentile", "the percentile p of v_k and h_k, in (0, 100)");
  h.check("percentile", r.percentile > 0 && r.percentile < 100, "a percentile in (0, 100)");
  const std::string gov = h.required_string("governing", "\"weibull\", \"empirical\" or \"larger\"");
  if (gov == "weibull") r.governing = design::Governing::weibull;
  else if (gov == "empirical") r.governing = design::Governing::empirical;
  else if (gov == "larger") r.governing = design::Governing::larger;
  else h.fail("governing", "\"weibull\", \"empirical\" or \"larger\"");
  const std::string on = h.required_string("design_on", "\"MEL\", \"SEL\" or \"both\"");
  if (on == "MEL") r.design_on = design::DesignOn::mel;
  else if (on == "SEL") r.design_on = design::DesignOn::sel;
  else if (on == "both") r.design_on = design::DesignOn::both;
  else h.fail("design_on", "\"MEL\", \"SEL\" or \"both\"");
  r.classes = h.string("classes").value_or(r.classes);
  h.check("classes", !r.classes.empty(), "the name of an energy class table");
  r.sample_tolerance = h.number("sample_tolerance", r.sample_tolerance);
  h.check("sample_tolerance", r.sample_tolerance > 0 && r.sample_tolerance < 1,
          "a relative half-width in (0, 1)");
  detail::read_bootstrap_size(h, "sample_confidence", "sample_resamples", r.sample_confidence,
                              r.sample_resamples);
  r.fit_p_value = h.number("fit_p_value", r.fit_p_value);
  h.check("fit_p_value", r.fit_p_value > 0 && r.fit_p_value < 1, "a p-value in (0, 1)");
  r.min_crossings = h.number("min_crossings", r.min_crossings);
  h.check("min_crossings", r.min_crossings >= 0, "a number of crossings >= 0");

  std::map<std::string, std::string> sources;
  if (const auto s = top.subtable("sources", {"gamma_F", "gamma_M", "gamma_h", "gamma_E_MEL",
                                              "gamma_E_SEL", "gamma_d_MEL", "gamma_d_SEL"}))
    for (auto&& [k, v] : s->table()) sources[std::string(k.str())] = *s->string(k.str());
  r.sources = sources;

  const auto parts = top.subtable("parts", {});
  const auto f = top.subtable("factors", {"gamma_F", "gamma_M", "gamma_h", "gamma_E_MEL",
                                          "gamma_E_SEL", "gamma_d_MEL", "gamma_d_SEL"});
  if (!f) top.missing("factors", "a [factors] table with gamma_F, gamma_M, gamma_h, gamma_E_MEL, gamma_E_SEL");
  const TomlTable* pp = parts ? &*parts : nullptr;
  r.gamma_F = read_factor(*f, "gamma_F", "γF", pp, sources);
  r.gamma_M = read_factor(*f, "gamma_M", "γM", pp, sources);
  r.gamma_h = read_factor(*f, "gamma_h", "γh", pp, sources);
  r.gamma_E_MEL = partial_factor(*f, "gamma_E_MEL", "a factor >= 1 (MEL_req = γE,MEL · E_d)");
  r.gamma_E_SEL = partial_factor(*f, "gamma_E_SEL", "a factor >= 1 (SEL_req = γE,SEL · E_d)");
  if (f->has("gamma_d_MEL")) r.gamma_d_MEL = partial_factor(*f, "gamma_d_MEL", "a factor >= 1");
  if (f->has("gamma_d_SEL")) r.gamma_d_SEL = partial_factor(*f, "gamma_d_SEL", "a factor >= 1");
  // One set of answers per data-quality question, whichever parts ask it.
  std::map<std::string, std::vector<std::string>> answers;
  for (const design::FactorDefinition* fd : {&r.gamma_F, &r.gamma_M, &r.gamma_h})
    for (const auto& p : fd->parts) {
      if (p.choice.empty()) continue;
      std::vector<std::string> keys;
      for (const auto& [k, v] : p.options) keys.push_back(k);
      auto [it, fresh] = answers.emplace(p.choice, keys);
      if (!fresh && it->second != keys)
        throw InputError(file, parts->line(), "parts", "the question \"" + p.choice +
                         "\" with answers (" + join_names(it->second) + ") and (" +
                         join_names(keys) + ")", "one set of answers per data-quality question");
    }

  const auto fb = top.subtable("free_board", {"absolute", "relative"});
  if (!fb) top.missing("free_board", "a [free_board] table with absolute (m) and relative (× D_f)");
  r.free_board_abs = fb->required_number("absolute", "a free board >= 0 (m)");
  fb->check("absolute", r.free_board_abs >= 0, "a free board >= 0 (m)");
  r.free_board_rel = fb->required_number("relative", "a share of D_f >= 0");
  fb->check("relative", r.free_board_rel >= 0, "a share of D_f >= 0");

  if (const auto c = top.subtable("clauses", {})) {
    for (auto&& [k, v] : c->table()) {
      const std::string id(k.str());
      const bool known = std::any_of(std::begin(kCheckIds), std::end(kCheckIds),
                                     [&](const char* x) { return id == x; });
      if (!known) {
        std::vector<std::string> ids(std::begin(kCheckIds), std::end(kCheckIds));
        throw InputError(file, static_cast<long>(k.source().begin.line), c->field(id),
                         "an unknown check id", "one of " + join_names(ids));
      }
      r.clauses[id] = *c->string(id);
    }
  }
  return r;
}

design::EnergyClassTable load_energy_classes(const std::string& name_or_path,
                                             const fs::path& rules_dir) {
  return load_energy_classes_file(rule_file(name_or_path, rules_dir));
}

design::EnergyClassTable load_energy_classes_file(const fs::path& file) {
  const std::string text = read_text(file, "energy class table (TOML)");
  const toml::table root = parse_toml(file, text);
  const TomlTable top(file, root, "", 0, {"rule_set", "classes", "residual_height"});
  const TomlTable h = header(top, "energy-classes", {"kind", "name", "title", "source"});
  design::EnergyClassTable t;
  t.name = h.string("name").value_or(file.stem().string());
  t.title = h.required_string("title", "a title");
  t.file = file.string();
  t.source = h.required_string("source", "a string citing the class table");
  const toml::array* a = top.array_of_tables("classes");
  if (!a || a->empty()) top.missing("classes", "[[classes]] tables with class and mel");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const TomlTable c = top.element("classes", *a, i, {"class", "mel", "sel", "open_ended"});
    design::EnergyClass e;
    const auto num = c.integer("class");
    if (!num) c.missing("class", "the class number, an integer");
    c.check("class", *num >= 0 && *num < 1000, "a class number from 0 to 999");
    e.number = static_cast<int>(*num);
    if (!t.classes.empty())
      c.check("class", e.number > t.classes.back().number,
              fmt::format("a class number above the previous one ({})", t.classes.back().number));
    e.mel_kJ = positive(c, "mel", "the MEL in kJ (> 0)");
    if (!t.classes.empty())
      c.check("mel", e.mel_kJ >= t.classes.back().mel_kJ,
              fmt::format("an MEL >= the previous class's ({} kJ)", t.classes.back().mel_kJ));
    e.sel_kJ = c.has("sel") ? positive(c, "sel", "the SEL in kJ (> 0)")
                            : std::numeric_limits<double>::quiet_NaN();
    // A kit's service energy is a share of its maximum (ETAG 027: a third), and rises with it.
    if (c.has("sel")) {
      c.check("sel", e.sel_kJ <= e.mel_kJ,
              fmt::format("an SEL <= the class's MEL ({} kJ)", e.mel_kJ));
      for (auto it = t.classes.rbegin(); it != t.classes.rend(); ++it)
        if (!std::isnan(it->sel_kJ)) {
          c.check("sel", e.sel_kJ >= it->sel_kJ,
                  fmt::format("an SEL >= class {}'s ({} kJ)", it->number, it->sel_kJ));
          break;
        }
    }
    e.open_ended = c.boolean("open_ended").value_or(false);
    if (e.open_ended)
      c.check("open_ended", i + 1 == a->size(), "open_ended = true on the last class only");
    t.classes.push_back(e);
  }
  if (const auto r = top.subtable("residual_height", {"A", "B", "source"})) {
    design::ResidualHeightCategories rh;
    rh.a_min = r->required_number("A", "the least share of the nominal height of category A, in (0, 1]");
    r->check("A", rh.a_min > 0 && rh.a_min <= 1, "a share in (0, 1]");
    rh.b_min = r->required_number("B", "the share above which category B starts, in [0, A)");
    r->check("B", rh.b_min >= 0 && rh.b_min < rh.a_min, "a share in [0, A)");
    rh.source = r->string("source").value_or("");
    t.residual_height = rh;
  }
  return t;
}

std::vector<std::string> barrier_rule_set_names(const fs::path& rules_dir,
                                                std::vector<std::string>* unparsable) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(rules_dir, ec)) {
    if (e.path().extension() != ".toml") continue;
    std::string why;
    const auto kind = detail::rule_file_kind(e.path(), &why);
    if (kind == detail::RuleFileKind::barrier) names.push_back(e.path().stem().string());
    if (kind == detail::RuleFileKind::unparsable && unparsable)
      unparsable->push_back(e.path().filename().string() + " (" + why + ")");
  }
  std::sort(names.begin(), names.end());
  if (unparsable) std::sort(unparsable->begin(), unparsable->end());
  return names;
}

std::string barrier_rule_sets_held(const fs::path& rules_dir) {
  std::vector<std::string> broken;
  const std::vector<std::string> names = barrier_rule_set_names(rules_dir, &broken);
  // A rule set with a typo in it is not a barrier rule set yet, but it is the one the user may
  // be looking for: say it is there and why it was passed over.
  std::string held = names.empty() ? "it holds no barrier rule set"
                                   : "its barrier rule sets: " + detail::quoted_list(names);
  if (!broken.empty()) {
    held += "; not valid TOML, so not looked at: ";
    for (std::size_t i = 0; i < broken.size(); ++i) held += (i ? ", " : "") + broken[i];
  }
  return held;
}

}  // namespace pierre::io
