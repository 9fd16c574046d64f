// The quarry reader (docs/quarry.md) and quarry rule sets. The profile and block formats are
// those of docs/scenario-format.md; the scenario reader keeps its readers private, so the
// few lines they need are repeated here (same fields, same messages).
#include "pierre/io/quarry_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "csv_table.hpp"
#include "toml_fields.hpp"

namespace pierre::io {
namespace {

namespace fs = std::filesystem;
using detail::CsvTable;
using detail::describe;
using detail::line_of;
using detail::TomlTable;
using model::ModelDefaults;

constexpr std::int64_t kMaxCount = 1'000'000;

std::string read_text(const fs::path& file, std::string_view what) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::error_code ec;
    const bool exists = fs::is_regular_file(file, ec);
    throw InputError(file, 0, "file", exists ? "a file that cannot be read" : "no such file",
                     fmt::format("a readable {}", what));
  }
  std::stringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

toml::table parse_toml(const fs::path& file, const std::string& text) {
  try {
    return toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(file, static_cast<long>(e.source().begin.line), "TOML syntax",
                     fmt::format("{} (column {})", e.description(), e.source().begin.column),
                     "valid TOML (https://toml.io)");
  }
}

fs::path relative_to(const fs::path& base_file, const std::string& p) {
  const fs::path q(p);
  return q.is_absolute() ? q : base_file.parent_path() / q;
}

bool is_path(const std::string& s) {
  return s.find('/') != std::string::npos ||
         (s.size() > 5 && s.compare(s.size() - 5, 5, ".toml") == 0);
}

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
  r.title = head->required_string("title", "a title for the rule set");
  r.source = head->required_string("source", "a string citing where the rules come from");

  const auto toe = top.subtable("toe", {"floor_angle", "source"});
  if (!toe) top.missing("toe", "a [toe] table with floor_angle");
  r.floor_angle_deg = toe->required_number("floor_angle", "a floor angle in (0, 90) degrees");
  toe->check("floor_angle", r.floor_angle_deg > 0 && r.floor_angle_deg < 90,
             "a floor angle in (0, 90) degrees");

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

  const auto ret = top.subtable("retention", {"target", "source"});
  if (!ret) top.missing("retention", "a [retention] table with target");
  r.retention_target = ret->required_number("target", "a share in (0, 1]");
  ret->check("target", r.retention_target > 0 && r.retention_target <= 1, "a share in (0, 1]");

  const auto rit = top.subtable("ritchie", {"factor", "offset", "source"});
  if (!rit) top.missing("ritchie", "a [ritchie] table with factor and offset");
  r.ritchie_factor = rit->required_number("factor", "a factor >= 0 (width = factor·H + offset)");
  rit->check("factor", r.ritchie_factor >= 0, "a factor >= 0");
  r.ritchie_offset = rit->required_number("offset", "an offset >= 0 (m)");
  rit->check("offset", r.ritchie_offset >= 0, "an offset >= 0 (m)");

  if (const auto s = top.subtable("sample", {"min_reached", "percentile", "tolerance", "confidence",
                                             "resamples", "source"})) {
    if (auto n = s->integer("min_reached")) {
      s->check("min_reached", *n >= 0, "an integer >= 0");
      r.min_reached = static_cast<std::size_t>(*n);
    }
    r.sample_percentile = s->number("percentile", r.sample_percentile);
    s->check("percentile", r.sample_percentile > 0 && r.sample_percentile <= 100, pct);
    r.sample_tolerance = s->number("tolerance", r.sample_tolerance);
    s->check("tolerance", r.sample_tolerance > 0, "a relative tolerance > 0");
    r.sample_confidence = s->number("confidence", r.sample_confidence);
    s->check("confidence", r.sample_confidence > 0 && r.sample_confidence < 1, "a confidence in (0, 1)");
    if (auto n = s->integer("resamples")) {
      s->check("resamples", *n >= 2 && *n <= 1'000'000, "an integer from 2 to 1000000");
      r.sample_resamples = static_cast<std::size_t>(*n);
    }
  }
  if (const auto f = top.subtable("fit", {"p_value", "source"})) {
    r.fit_p_value = f->number("p_value", r.fit_p_value);
    f->check("p_value", r.fit_p_value > 0 && r.fit_p_value < 1, "a p-value in (0, 1)");
  }
  if (const auto c = top.subtable("clauses", {})) {
    for (auto&& [k, v] : c->table()) {
      const std::string key(k.str());
      const auto* s = v.as_string();
      if (!s) c->fail(key, "a string naming the clause");
      r.clauses[key] = s->get();
    }
  }
  return r;
}

// ---- profile ----

struct Vertex {
  geometry::Vec2 p;
  std::string material;
  long line;
  std::string field;
  fs::path file;
};

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

std::vector<Vertex> read_inline_points(const TomlTable& prof) {
  const toml::array* pts = prof.array("points");
  std::vector<Vertex> out;
  const std::string expected = "an entry [x, z, \"material\"] with x and z finite numbers (m)";
  for (std::size_t i = 0; i < pts->size(); ++i) {
    const toml::node& e = *pts->get(i);
    const std::string field = fmt::format("{}[{}]", prof.field("points"), i);
    const auto* a = e.as_array();
    if (!a || a->size() != 3)
      throw InputError(prof.file(), line_of(e), field,
                       a ? fmt::format("an array of {} values", a->size()) : describe(e), expected);
    const double x = coordinate(prof, *a->get(0), field, expected);
    const double z = coordinate(prof, *a->get(1), field, expected);
    const toml::node& mc = *a->get(2);
    const auto* ms = mc.as_string();
    if (!ms) throw InputError(prof.file(), line_of(mc), field, describe(mc), expected);
    out.push_back({{x, z}, ms->get(), line_of(e), field, prof.file()});
  }
  if (out.size() < 2)
    throw InputError(prof.file(), line_of(*prof.find("points")), prof.field("points"),
                     fmt::format("{} vert{}", out.size(), out.size() == 1 ? "ex" : "ices"),
                     "at least two vertices");
  return out;
}

std::vector<Vertex> read_profile_csv(const fs::path& file) {
  const CsvTable t = detail::read_csv(file, {"x", "z", "material"}, "x,z,material");
  for (std::string_view c : {"x", "z", "material"})
    if (!t.column(c))
      throw InputError(file, t.header_line, "header", fmt::format("no column \"{}\"", c),
                       "the header x,z,material");
  const std::size_t cx = *t.column("x"), cz = *t.column("z"), cm = *t.column("material");
  std::vector<Vertex> out;
  for (const auto& row : t.rows)
    out.push_back({{t.number(row, cx), t.number(row, cz)}, row.cells[cm], row.line, "x,z", file});
  if (out.size() < 2)
    throw InputError(file, t.rows.empty() ? t.header_line : t.rows.back().line, "profile",
                     fmt::format("{} vertex row{}", out.size(), out.size() == 1 ? "" : "s"),
                     "at least two vertex rows after the header");
  return out;
}

geometry::Profile read_profile(const TomlTable& q, const std::vector<model::Material>& mats) {
  const auto prof = q.subtable("profile", {"file", "points"});
  if (!prof) q.missing("profile", "a [quarries.profile] table with file = \"...\" or points = [...]");
  const bool has_file = prof->has("file"), has_points = prof->has("points");
  if (has_file == has_points)
    throw InputError(q.file(), prof->line(), prof->field(has_file ? "points" : "file"),
                     has_file ? "both file and points" : "neither file nor points",
                     "exactly one of file (a CSV) or points (inline vertices)");
  const std::vector<Vertex> vs = has_file ? read_profile_csv(relative_to(q.file(), *prof->string("file")))
                                          : read_inline_points(*prof);
  std::vector<geometry::Vec2> pts;
  std::vector<int> mat_index;
  std::string names;
  for (const auto& m : mats) names += (names.empty() ? "" : ", ") + m.name;
  for (std::size_t i = 0; i < vs.size(); ++i) {
    const Vertex& v = vs[i];
    pts.push_back(v.p);
    const bool last = i + 1 == vs.size();
    if (last && v.material.empty()) continue;
    const auto it = std::find_if(mats.begin(), mats.end(),
                                 [&](const model::Material& m) { return m.name == v.material; });
    if (it == mats.end())
      throw InputError(v.file, v.line, has_file ? "material" : v.field,
                       fmt::format("\"{}\"", v.material),
                       fmt::format("a material defined in [materials] ({})", names));
    if (!last) mat_index.push_back(static_cast<int>(it - mats.begin()));
  }
  std::vector<geometry::ProfileIssue> issues;
  auto profile = geometry::Profile::build(pts, mat_index, &issues);
  if (!profile) {
    const geometry::ProfileIssue& is = issues.front();
    const Vertex& v = vs[std::min(is.vertex, vs.size() - 1)];
    throw InputError(v.file, v.line, v.field, fmt::format("vertex ({}, {}): {}", v.p.x, v.p.z, is.what),
                     "a profile of distinct, finite vertices that never crosses itself");
  }
  return std::move(*profile);
}

// ---- blocks ----

struct ShapeRange {
  double min = ModelDefaults::shape_factor_min, max = ModelDefaults::shape_factor_max;
};

bool shape_ok(double lo, double hi) {
  return ModelDefaults::shape_factor_lower_bound <= lo && lo <= hi &&
         hi <= ModelDefaults::shape_factor_upper_bound;
}

std::string shape_expected() {
  return fmt::format("[f_min, f_max] with {} <= f_min <= f_max <= {}",
                     ModelDefaults::shape_factor_lower_bound, ModelDefaults::shape_factor_upper_bound);
}

std::optional<ShapeRange> read_shape(const TomlTable& t) {
  const toml::array* a = t.array("shape_factor");
  if (!a) return std::nullopt;
  if (a->size() != 2) t.fail("shape_factor", shape_expected());
  const double lo = coordinate(t, *a->get(0), t.field("shape_factor"), shape_expected());
  const double hi = coordinate(t, *a->get(1), t.field("shape_factor"), shape_expected());
  if (!shape_ok(lo, hi))
    throw InputError(t.file(), line_of(*t.find("shape_factor")), t.field("shape_factor"),
                     fmt::format("[{}, {}]", lo, hi), shape_expected());
  return ShapeRange{lo, hi};
}

struct GroupSource {
  fs::path file;
  long line;
  std::string field;
};

void read_blocks_csv(const fs::path& file, double density, ShapeRange shape,
                     std::vector<BlockGroup>& groups, std::vector<GroupSource>& where) {
  const CsvTable t = detail::read_csv(
      file, {"id", "mass", "volume", "density", "shape_min", "shape_max", "count"},
      "mass or volume, and optionally id, density, shape_min, shape_max, count");
  const auto c_id = t.column("id"), c_mass = t.column("mass"), c_vol = t.column("volume"),
             c_den = t.column("density"), c_smin = t.column("shape_min"),
             c_smax = t.column("shape_max"), c_count = t.column("count");
  if (!c_mass && !c_vol)
    throw InputError(file, t.header_line, "header", "neither mass nor volume",
                     "a column mass (kg) or volume (m³)");
  if (t.rows.empty())
    throw InputError(file, t.header_line, "blocks", "no block rows", "at least one block row");
  auto present = [&](const detail::CsvRow& r, std::optional<std::size_t> c) {
    return c && !r.cells[*c].empty();
  };
  for (const auto& r : t.rows) {
    BlockGroup g;
    g.id = present(r, c_id) ? r.cells[*c_id] : fmt::format("B{}", groups.size() + 1);
    const bool has_mass = present(r, c_mass), has_vol = present(r, c_vol);
    if (has_mass == has_vol)
      throw InputError(file, r.line, has_mass ? "volume" : "mass",
                       has_mass ? "both mass and volume" : "neither mass nor volume",
                       "exactly one of mass (kg) or volume (m³) per row");
    g.density = density;
    if (present(r, c_den)) {
      g.density = t.number(r, *c_den);
      if (!(g.density > 0)) throw InputError(file, r.line, "density", r.cells[*c_den], "a density > 0 (kg/m³)");
    }
    if (has_mass) {
      g.mass = t.number(r, *c_mass);
      if (!(g.mass > 0)) throw InputError(file, r.line, "mass", r.cells[*c_mass], "a mass > 0 (kg)");
      g.volume = g.mass / g.density;
    } else {
      g.volume = t.number(r, *c_vol);
      if (!(g.volume > 0)) throw InputError(file, r.line, "volume", r.cells[*c_vol], "a volume > 0 (m³)");
      g.mass = g.volume * g.density;
    }
    g.shape_min = present(r, c_smin) ? t.number(r, *c_smin) : shape.min;
    g.shape_max = present(r, c_smax) ? t.number(r, *c_smax) : shape.max;
    if (!shape_ok(g.shape_min, g.shape_max))
      throw InputError(file, r.line, c_smin ? "shape_min" : "shape_max",
                       fmt::format("shape_min {}, shape_max {}", g.shape_min, g.shape_max),
                       fmt::format("{} <= shape_min <= shape_max <= {}",
                                   ModelDefaults::shape_factor_lower_bound,
                                   ModelDefaults::shape_factor_upper_bound));
    if (present(r, c_count)) {
      const std::string& s = r.cells[*c_count];
      std::int64_t n = 0;
      const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
      if (ec != std::errc{} || p != s.data() + s.size() || n < 1 || n > kMaxCount)
        throw InputError(file, r.line, "count", fmt::format("\"{}\"", s),
                         fmt::format("an integer from 1 to {}", kMaxCount));
      g.count = static_cast<unsigned>(n);
    }
    groups.push_back(std::move(g));
    where.push_back({file, r.line, "id"});
  }
}

void read_blocks(const TomlTable& q, QuarrySection& out) {
  const auto b = q.subtable("blocks", {"density", "shape_factor", "file", "table"});
  if (!b) q.missing("blocks", "a [quarries.blocks] table");
  const double density = b->number("density", ModelDefaults::density);
  b->check("density", density > 0, "a density > 0 (kg/m³)");
  const ShapeRange shape = read_shape(*b).value_or(ShapeRange{});
  std::vector<GroupSource> where;
  if (auto f = b->string("file"))
    read_blocks_csv(relative_to(q.file(), *f), density, shape, out.block_groups, where);
  if (const toml::array* rows = b->array_of_tables("table")) {
    for (std::size_t i = 0; i < rows->size(); ++i) {
      const toml::node& node = *rows->get(i);
      const TomlTable t(q.file(), *node.as_table(), fmt::format("{}[{}]", b->field("table"), i),
                        line_of(node), {"id", "mass", "volume", "density", "count", "shape_factor"});
      BlockGroup g;
      g.id = t.string("id").value_or(fmt::format("B{}", out.block_groups.size() + 1));
      g.density = t.number("density", density);
      t.check("density", g.density > 0, "a density > 0 (kg/m³)");
      const auto mass = t.number("mass"), volume = t.number("volume");
      if (mass.has_value() == volume.has_value())
        throw InputError(q.file(), t.line(), t.field(mass ? "volume" : "mass"),
                         mass ? "both mass and volume" : "neither mass nor volume",
                         "exactly one of mass (kg) or volume (m³)");
      if (mass) {
        t.check("mass", *mass > 0, "a mass > 0 (kg)");
        g.mass = *mass;
        g.volume = g.mass / g.density;
      } else {
        t.check("volume", *volume > 0, "a volume > 0 (m³)");
        g.volume = *volume;
        g.mass = g.volume * g.density;
      }
      const ShapeRange s = read_shape(t).value_or(shape);
      g.shape_min = s.min;
      g.shape_max = s.max;
      if (auto n = t.integer("count")) {
        t.check("count", *n >= 1 && *n <= kMaxCount, fmt::format("an integer from 1 to {}", kMaxCount));
        g.count = static_cast<unsigned>(*n);
      }
      where.push_back({q.file(), t.has("id") ? line_of(*t.find("id")) : t.line(), t.field("id")});
      out.block_groups.push_back(std::move(g));
    }
  }
  if (out.block_groups.empty())
    throw InputError(q.file(), b->line(), b->field("file"), "no blocks",
                     "a blocks file or at least one [[quarries.blocks.table]]");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < out.block_groups.size(); ++i) {
    const BlockGroup& g = out.block_groups[i];
    if (!ids.insert(g.id).second)
      throw InputError(where[i].file, where[i].line, where[i].field, fmt::format("\"{}\"", g.id),
                       "a block id not used by another row");
    for (unsigned k = 1; k <= g.count; ++k) {
      model::Block blk;
      blk.id = g.count == 1 ? g.id : fmt::format("{}.{}", g.id, k);
      blk.mass = g.mass;
      blk.density = g.density;
      blk.shape_min = g.shape_min;
      blk.shape_max = g.shape_max;
      out.scenario.blocks.push_back(std::move(blk));
    }
  }
}

// ---- sources, work areas, observed values ----

std::string extent(const geometry::Profile& p) {
  return fmt::format("inside the section's horizontal extent [{}, {}] m", p.x_min(), p.x_max());
}

void read_sources(const TomlTable& q, sim::Scenario& sc) {
  const toml::array* a = q.array_of_tables("sources");
  if (!a) q.missing("sources", "at least one [[quarries.sources]] table with x and z");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& node = *a->get(i);
    const TomlTable t(q.file(), *node.as_table(), fmt::format("{}[{}]", q.field("sources"), i),
                      line_of(node), {"name", "x", "z", "vx", "vz", "omega"});
    sim::Source s;
    s.name = t.string("name").value_or(fmt::format("S{}", i + 1));
    s.position.x = t.required_number("x", "a number (m)");
    t.check("x", s.position.x >= sc.profile.x_min() && s.position.x <= sc.profile.x_max(),
            "an x " + extent(sc.profile));
    s.position.z = t.required_number("z", "a number (m)");
    s.velocity.x = t.number("vx", 0.0);
    s.velocity.z = t.number("vz", 0.0);
    s.omega = t.number("omega", 0.0);
    sc.sources.push_back(std::move(s));
  }
}

void read_work_areas(const TomlTable& q, design::QuarrySpec& spec) {
  const toml::array* a = q.array_of_tables("work_areas");
  if (!a) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& node = *a->get(i);
    const TomlTable t(q.file(), *node.as_table(), fmt::format("{}[{}]", q.field("work_areas"), i),
                      line_of(node), {"name", "distance"});
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
  const CsvTable t = detail::read_csv(file, {"first_impact", "runout"}, "first_impact and/or runout (m)");
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
  if (auto f = obs->string("file")) read_observed_csv(relative_to(q.file(), *f), o);
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
  const fs::path file = is_path(name_or_path) ? fs::path(name_or_path)
                                              : rules_dir / (name_or_path + ".toml");
  return read_rules(file, file.stem().string());
}

std::vector<QuarrySection> read_quarries(const toml::table& root, const std::filesystem::path& file,
                                         const std::filesystem::path& rules_dir,
                                         const std::vector<model::Material>& materials,
                                         const sim::SimulationSettings& settings) {
  std::vector<QuarrySection> out;
  const TomlTable top(file, root, "", 0, {});
  const toml::array* a = top.array_of_tables("quarries");
  if (!a) return out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& node = *a->get(i);
    const TomlTable q(file, *node.as_table(), fmt::format("quarries[{}]", i), line_of(node),
                      {"name", "group", "rules", "toe", "crest", "height", "bench_width", "seed",
                       "exceedance", "profile", "blocks", "sources", "work_areas", "observed"});
    QuarrySection s;
    design::QuarrySpec& spec = s.spec;
    spec.name = q.required_string("name", "a name for the quarry section");
    q.check("name", !spec.name.empty(), "a non-empty name");
    q.check("name", names.insert(spec.name).second, "a name not used by another quarry section");
    spec.group = q.string("group").value_or("");
    spec.rules = q.string("rules").value_or("quarry-thesis-2015");
    q.check("rules", !spec.rules.empty(), "a rule set name or path");
    const std::string rules_arg =
        is_path(spec.rules) ? relative_to(file, spec.rules).string() : spec.rules;
    try {
      s.rules = load_quarry_rules(rules_arg, rules_dir);
    } catch (const InputError& e) {
      if (e.line() != 0) throw;  // an error inside the rule file: reported there
      q.fail("rules", fmt::format("a rule set in {} (e.g. \"quarry-thesis-2015\", "
                                  "\"quarry-conservative\") or a path to a .toml file ({}: {})",
                                  rules_dir.string(), e.file().string(), e.found()));
    }
    s.rules_file = is_path(rules_arg) ? fs::path(rules_arg) : rules_dir / (rules_arg + ".toml");

    spec.geometry.crest_x = q.number("crest");
    spec.geometry.toe_x = q.number("toe");
    spec.geometry.height = q.number("height");
    if (spec.geometry.height) q.check("height", *spec.geometry.height > 0, "a height H > 0 (m)");
    spec.geometry.floor_angle_deg = s.rules.floor_angle_deg;
    spec.bench_width = q.number("bench_width");
    if (spec.bench_width) q.check("bench_width", *spec.bench_width > 0, "a bench width > 0 (m)");
    if (const toml::array* ex = q.array("exceedance")) {
      spec.exceedance.clear();
      const std::string expected = "a probability of exceedance in (0, 1)";
      for (std::size_t k = 0; k < ex->size(); ++k) {
        const toml::node& e = *ex->get(k);
        const std::string field = fmt::format("{}[{}]", q.field("exceedance"), k);
        const double v = coordinate(q, e, field, expected);
        if (!(v > 0 && v < 1)) throw InputError(file, line_of(e), field, describe(e), expected);
        spec.exceedance.push_back(v);
      }
    }

    sim::Scenario& sc = s.scenario;
    sc.name = spec.name;
    sc.materials = materials;
    sc.settings = settings;
    if (auto seed = q.integer("seed")) {
      q.check("seed", *seed >= 0, "an integer >= 0");
      sc.settings.seed = static_cast<std::uint64_t>(*seed);
    } else {
      sc.settings.seed = settings.seed + i;  // independent streams for sections pooled together
    }
    sc.profile = read_profile(q, materials);
    read_blocks(q, s);
    read_sources(q, sc);
    read_work_areas(q, spec);
    read_observed(q, s);

    const auto g = design::quarry_geometry(sc.profile, spec.geometry);
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
    out.push_back(std::move(s));
  }
  // Sections pooled in one group must follow one rule set.
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (!out[i].spec.group.empty() && out[i].spec.group == out[j].spec.group &&
          out[i].rules.name != out[j].rules.name) {
        const toml::node& node = *a->get(i);
        const TomlTable q(file, *node.as_table(), fmt::format("quarries[{}]", i), line_of(node), {});
        q.fail(q.has("rules") ? "rules" : "group",
               fmt::format("the rule set of the other sections of group \"{}\" (\"{}\")",
                           out[i].spec.group, out[j].rules.name));
      }
  return out;
}

}  // namespace pierre::io
