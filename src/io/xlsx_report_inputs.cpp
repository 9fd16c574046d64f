// The Inputs sheet: the scenario as read (simulation settings, materials, sources, the profile's
// vertices, observation lines), the barriers' inputs, and the scenario's text; and the Blocks
// sheet: the block groups, a table that runs over pages (100 blocks at Vaujany), on a sheet of
// its own so that its headings repeat on every printed page (Excel repeats one row range a
// sheet).
#include "xlsx_report_writer.hpp"

#include <cmath>
#include <tuple>

#include "pierre/model/block.hpp"

namespace pierre::io::detail {
namespace {

// A number inside a text: four significant digits, a whole number of kJ up to a million whole
// (a MEL of 10 000 kJ as 1e+04 would read as a typo).
std::string shown(double v) {
  if (std::isfinite(v) && std::abs(v) >= 1e4 && std::abs(v) < 1e6) return fmt::format("{:.0f}", v);
  return format_number(v);
}

}  // namespace

void Report::inputs(lxw_worksheet* ws) {
  page_setup(ws);
  width(ws, 0, 0, 30);
  width(ws, 1, 12, 16);
  text(ws, 0, 0, t_.get("titles", "inputs"), title());
  Row r = 2;
  const LoadedScenario* sc = d_.scenario;
  if (sc) {
    r = inputs_simulation(ws, r, *sc);
    r = inputs_materials(ws, r, *sc);
    // The block groups are on a sheet of their own: say where.
    r = table_title(ws, r, "blocks");
    text(ws, r++, 0, replace_all(t_.get("labels", "blocks_sheet"), "{sheet}", t_.get("sheets", "blocks")),
         note());
    r = inputs_sources(ws, r, *sc);
    r = inputs_vertices(ws, r, *sc);
    r = inputs_lines(ws, r, *sc);
  }
  r = inputs_quarries(ws, r);
  r = inputs_barriers(ws, r);
  if (sc) inputs_scenario_text(ws, r, *sc);
}

// A quarry scenario's blocks, sources and profile are its sections': `write` is called with each
// section's block groups and scenario, under the section's name.
template <class Write>
void Report::each_section(lxw_worksheet* ws, Row& r, const LoadedScenario& sc, Write&& write) {
  if (sc.quarries.empty()) return write(sc.block_groups, sc.scenario);
  for (const auto& q : sc.quarries) {
    text(ws, r++, 0, q.spec.name, bold());
    write(q.block_groups, q.scenario);
  }
}

Row Report::inputs_simulation(lxw_worksheet* ws, Row r, const LoadedScenario& sc) {
  const auto& s = sc.scenario;
  text(ws, r++, 0, t_.get("titles", "simulation"), section());
  headings(ws, r++, 0, "simulation",
           {"seed", "throws", "gravity", "max_time", "max_impacts", "stop_head_factor",
            "max_sliding_speed"});
  seed(ws, r, 0, s.settings.seed, number("general", 1));
  count(ws, r, 1, s.settings.throws);
  num(ws, r, 2, s.settings.gravity, number("material"));
  num(ws, r, 3, s.settings.max_time, number("time"));
  num(ws, r, 4, static_cast<double>(s.settings.max_impacts), number("count"));
  num(ws, r, 5, s.settings.stop_head_factor, number("factor"));
  num(ws, r++, 6, s.settings.max_sliding_speed, number("speed"));
  // The roughness draw (Eq 3.4/3.5) and its size reduction (Eq 6.6): they change the results
  // as much as the materials do, defaults or not.
  const auto& rough = s.settings.roughness;
  headings(ws, r++, 0, "simulation",
           {"roughness_distribution", "roughness_mean", "roughness_sd", "size_reduction",
            "size_reduction_b", "size_reduction_m", "size_reduction_floor"});
  text(ws, r, 0,
       rough.distribution == model::RoughnessDistribution::uniform ? "uniform (Eq 3.4)"
                                                                     : "truncated-normal (Eq 3.5)",
       centred());
  num(ws, r, 1, rough.mean, number("factor"));
  num(ws, r, 2, rough.sd, number("factor"));
  text(ws, r, 3, rough.size_reduction ? "on" : "off", centred());
  num(ws, r, 4, rough.b, number("factor"));
  num(ws, r, 5, rough.m, number("factor"));
  num(ws, r++, 6, rough.floor, number("factor"));
  return r;
}

Row Report::inputs_materials(lxw_worksheet* ws, Row r, const LoadedScenario& sc) {
  const auto& s = sc.scenario;
  r = table_title(ws, r, "materials");
  if (!sc.materials_file.empty()) {
    text(ws, r, 0, t_.get("labels", "materials_file"), bold());
    text(ws, r++, 1, sc.materials_file.string());
  }
  headings(ws, r++, 0, "materials",
           {"name", "source", "normal_energy", "normal_energy_k", "tangential_energy",
            "tangential_energy_k", "roughness", "friction_angle"});
  for (const auto& m : s.materials) {
    text(ws, r, 0, m.name);
    text(ws, r, 1, m.source, wrap());
    num(ws, r, 2, m.normal_energy, number("material"));
    num(ws, r, 3, m.normal_energy_k, number("material"));
    num(ws, r, 4, m.tangential_energy, number("material"));
    num(ws, r, 5, m.tangential_energy_k, number("material"));
    num(ws, r, 6, m.roughness, number("material"));
    num(ws, r, 7, m.friction_angle_deg, number("angle"));
    fit_row(ws, r++, {{&m.source, 16}});
  }
  return r;
}

void Report::blocks(lxw_worksheet* ws) {
  page_setup(ws);
  width(ws, 0, 0, 30);
  width(ws, 1, 7, 16);
  text(ws, 0, 0, t_.get("titles", "blocks"), title());
  if (!d_.scenario) return;
  const Row head = 2;
  const Row end = inputs_blocks(ws, head, *d_.scenario);
  check(worksheet_print_area(ws, 0, 0, end > 0 ? end - 1 : 0, 7), "worksheet_print_area");
  check(worksheet_repeat_rows(ws, head, head), "worksheet_repeat_rows");
}

// The block groups' table from row r (its heading there), a quarry section's under its name.
Row Report::inputs_blocks(lxw_worksheet* ws, Row r, const LoadedScenario& sc) {
  headings(ws, r++, 0, "blocks",
           {"id", "mass", "volume", "density", "diameter", "shape_min", "shape_max", "count"});
  each_section(ws, r, sc, [&](const std::vector<BlockGroup>& groups, const sim::Scenario&) {
    for (const auto& b : groups) {
      // The sphere of the block's volume, as the model throws it (§3.5): D_f's default is
      // the mean of these over the blocks thrown.
      model::Block sphere;
      sphere.mass = b.mass;
      sphere.density = b.density;
      text(ws, r, 0, b.id);
      num(ws, r, 1, b.mass, number("mass"));
      num(ws, r, 2, b.volume, number("volume"));
      num(ws, r, 3, b.density, number("density"));
      num(ws, r, 4, sphere.diameter(), number("length"));
      num(ws, r, 5, b.shape_min, number("factor"));
      num(ws, r, 6, b.shape_max, number("factor"));
      count(ws, r++, 7, b.count);
    }
  });
  return r;
}

Row Report::inputs_sources(lxw_worksheet* ws, Row r, const LoadedScenario& sc) {
  r = table_title(ws, r, "sources");
  headings(ws, r++, 0, "sources", {"name", "x", "z", "vx", "vz", "omega"});
  each_section(ws, r, sc, [&](const std::vector<BlockGroup>&, const sim::Scenario& sec) {
    for (const auto& so : sec.sources) {
      text(ws, r, 0, so.name);
      num(ws, r, 1, so.position.x, number("coordinate"));
      num(ws, r, 2, so.position.z, number("coordinate"));
      num(ws, r, 3, so.velocity.x, number("speed"));
      num(ws, r, 4, so.velocity.z, number("speed"));
      num(ws, r++, 5, so.omega, number("speed"));
    }
  });
  return r;
}

// The section as read: every vertex with the material of the segment that starts there (the last
// vertex ends the profile).
Row Report::inputs_vertices(lxw_worksheet* ws, Row r, const LoadedScenario& sc) {
  r = table_title(ws, r, "profile_vertices");
  headings(ws, r++, 0, "profile_vertices", {"x", "z", "material"});
  each_section(ws, r, sc, [&](const std::vector<BlockGroup>&, const sim::Scenario& sec) {
    const auto& segs = sec.profile.segments();
    for (std::size_t k = 0; k < segs.size(); ++k) {
      num(ws, r, 0, segs[k].a.x, number("coordinate"));
      num(ws, r, 1, segs[k].a.z, number("coordinate"));
      const auto m = static_cast<std::size_t>(segs[k].material);
      if (m < sec.materials.size()) text(ws, r, 2, sec.materials[m].name);
      ++r;
    }
    if (!segs.empty()) {
      num(ws, r, 0, segs.back().b.x, number("coordinate"));
      num(ws, r++, 1, segs.back().b.z, number("coordinate"));
    }
  });
  return r;
}

Row Report::inputs_lines(lxw_worksheet* ws, Row r, const LoadedScenario& sc) {
  const auto& s = sc.scenario;
  if (s.lines.empty()) return r;  // a quarry scenario, or none drawn: no empty table
  r = table_title(ws, r, "observation_lines");
  headings(ws, r++, 0, "observation_lines", {"name", "x"});
  for (const auto& l : s.lines) {
    text(ws, r, 0, l.name);
    num(ws, r++, 1, l.x, number("coordinate"));
  }
  return r;
}

// The quarry sections' inputs (docs/quarry.md), one row per section: group, rule set, crest, toe
// and H with whether each was given or found, bench width, work areas, the probabilities of
// exceedance asked for and where the observed values come from.
Row Report::inputs_quarries(lxw_worksheet* ws, Row r) {
  if (!d_.quarry || d_.quarry->sections.empty()) return r;
  r = table_title(ws, r, "quarry_inputs");
  headings(ws, r++, 0, "quarry_inputs",
           {"section", "group", "rules", "crest_x", "crest_origin", "toe_x", "toe_origin",
            "height", "height_origin", "bench_width", "work_areas", "exceedance",
            "observed_source"},
           45);
  lxw_format *xf = number("coordinate"), *lf = number("length");
  const std::string& none = t_.get("labels", "none");
  for (const design::QuarrySectionResult& s : d_.quarry->sections) {
    const design::QuarryGeometry& g = s.geometry;
    text(ws, r, 0, s.spec.name, wrap());
    text(ws, r, 1, s.spec.group.empty() ? none : s.spec.group, wrap());
    text(ws, r, 2, s.spec.rules, wrap());
    num(ws, r, 3, g.crest.x, xf);
    text(ws, r, 4, std::string(design::to_string(g.crest_origin)), centred());
    num(ws, r, 5, g.toe.x, xf);
    text(ws, r, 6, std::string(design::to_string(g.toe_origin)), centred());
    num(ws, r, 7, g.height, lf);
    text(ws, r, 8, std::string(design::to_string(g.height_origin)), centred());
    if (s.spec.bench_width)
      num(ws, r, 9, *s.spec.bench_width, lf);
    else
      text(ws, r, 9, none, centred());
    std::string areas, probabilities;
    for (const auto& w : s.spec.work_areas)
      areas += fmt::format("{}{} {} m", areas.empty() ? "" : "; ", w.name, format_number(w.distance));
    for (double p : s.spec.exceedance)
      probabilities += fmt::format("{}{} %", probabilities.empty() ? "" : ", ", format_number(100 * p));
    text(ws, r, 10, keep(areas.empty() ? none : areas), wrap());
    const std::string* areas_text = &strings_.back();
    text(ws, r, 11, keep(probabilities.empty() ? none : probabilities), wrap());
    const std::string* observed = &s.spec.observed_source;
    text(ws, r, 12, observed->empty() ? none : *observed, wrap());
    fit_row(ws, r, {{areas_text, 16}, {&s.spec.name, 30}, {observed, 16}, {&s.spec.rules, 16}});
    ++r;
  }
  return r;
}

// The barriers' inputs: one column per barrier, one row per input.
Row Report::inputs_barriers(lxw_worksheet* ws, Row r) {
  if (d_.barriers.empty()) return r;
  r = table_title(ws, r, "barrier_inputs");
  text(ws, r, 0, h("barrier_inputs", "field"), heading());
  // The heading row as tall as the name that wraps to most lines (bold: narrower than the
  // column's 16 characters).
  const std::string* tallest = nullptr;
  for (std::size_t i = 0; i < d_.barriers.size() && i < 200; ++i) {
    const std::string& name = d_.barriers[i].spec.name;
    text(ws, r, static_cast<Col>(1 + i), name, heading());
    if (!tallest || wrapped_lines(name, 14) > wrapped_lines(*tallest, 14)) tallest = &name;
  }
  if (tallest) fit_row(ws, r, {{tallest, 14}});
  ++r;
  auto row = [&](std::string_view key) {
    text(ws, r, 0, h("barrier_inputs", key), bold());
    return r++;
  };
  const Row line = row("line"), rules = row("rules"), block = row("design_block"),
            volume = row("volume"), density = row("density"), pct = row("percentile"),
            df = row("free_board_diameter"), dq = row("data_quality"),
            cls = row("energy_class"), mel = row("mel"), sel = row("sel"),
            height = row("height"), el_mel = row("elongation_mel"),
            el_sel = row("elongation_sel"), dist = row("distance_to_object"),
            resid = row("residual_height"), acc_e = row("acceptable_energy"),
            acc_h = row("acceptable_height"), obs = row("observed_file");
  for (std::size_t i = 0; i < d_.barriers.size() && i < 200; ++i) {
    const design::BarrierDesign& bd = d_.barriers[i];
    const auto& s = bd.spec;
    const Col c = static_cast<Col>(1 + i);
    // A value the scenario gives is a number; one the procedure resolved or defaulted is a text
    // with the value used and where it comes from: a blank would read as a missing input.
    auto derived = [&](Row at, std::string_view label, double v, std::string_view key,
                       const std::string& fallback) {
      const auto how = bd.how.find(std::string(key));
      std::string t = replace_all(t_.get("labels", label), "{value}", shown(v));
      t = replace_all(std::move(t), "{how}", how == bd.how.end() ? fallback : how->second);
      text(ws, at, c, keep(std::move(t)), wrap());
      fit_row(ws, at, {{&strings_.back(), 16}});
    };
    text(ws, line, c, s.line);
    text(ws, rules, c, s.rules);
    using K = design::DesignBlock::Kind;
    const auto& db = s.design_block;
    text(ws, block, c,
         db.kind == K::given     ? "given"
         : db.kind == K::largest ? "largest"
                                 : "percentile");
    if (db.kind == K::given)
      num(ws, volume, c, db.volume, number("volume"));
    else
      derived(volume, "resolved", bd.design_volume, "volume",
              db.kind == K::largest ? "largest" : "percentile");
    if (db.density > 0)
      num(ws, density, c, db.density, number("density"));
    else
      derived(density, "resolved", bd.design_density, "density", "the blocks'");
    if (db.kind == K::percentile) num(ws, pct, c, db.percentile, number("general"));
    if (s.free_board_diameter)
      num(ws, df, c, *s.free_board_diameter, number("length"));
    else
      derived(df, "defaulted", bd.free_board_diameter, "free_board_diameter",
              "the mean equivalent diameter of the blocks thrown");
    std::string q;
    for (const auto& [k, v] : s.data_quality) q += (q.empty() ? "" : "; ") + k + " = " + v;
    text(ws, dq, c, keep(q), wrap());
    fit_row(ws, dq, {{&strings_.back(), 16}});
    if (s.candidate) {
      const auto& cb = *s.candidate;
      if (cb.energy_class) num(ws, cls, c, *cb.energy_class, number("count"));
      // MEL and SEL given, or those of the class (an open-ended class has none of its own).
      for (auto [at, given, used] : {std::tuple{mel, &cb.mel_kJ, bd.candidate_mel_kJ},
                                     std::tuple{sel, &cb.sel_kJ, bd.candidate_sel_kJ}}) {
        if (*given) {
          num(ws, at, c, **given, number("energy"));
        } else if (cb.energy_class) {
          const std::string cls_text = std::to_string(*cb.energy_class);
          std::string t = std::isfinite(used)
                              ? replace_all(t_.get("labels", "from_class"), "{value}", shown(used))
                              : t_.get("labels", "open_class_capacity");
          text(ws, at, c, keep(replace_all(std::move(t), "{class}", cls_text)), wrap());
          fit_row(ws, at, {{&strings_.back(), 16}});
        }
      }
      opt(ws, height, c, cb.height, number("length"));
      opt(ws, el_mel, c, cb.elongation_mel, number("length"));
      opt(ws, el_sel, c, cb.elongation_sel, number("length"));
      opt(ws, dist, c, cb.distance_to_object, number("length"));
      opt(ws, resid, c, cb.residual_height, number("length"));
    }
    opt(ws, acc_e, c, s.acceptable_energy_exceedance, number("probability"));
    opt(ws, acc_h, c, s.acceptable_height_exceedance, number("probability"));
    text(ws, obs, c, s.observed_file);
  }
  return r;
}

// The scenario file as read, one line per row.
void Report::inputs_scenario_text(lxw_worksheet* ws, Row r, const LoadedScenario& sc) {
  r = table_title(ws, r, "scenario_text");
  text(ws, r++, 0, sc.file.string(), note());
  for (const auto& o : sc.overrides) text(ws, r++, 0, t_.get("labels", "overrides") + ": " + o, note());
  for (const auto& n : sc.notes) text(ws, r++, 0, t_.get("labels", "input_notes") + ": " + n.message(), note());
  std::size_t line_no = 1, p = 0;
  const std::string& s = sc.text;
  while (p < s.size()) {
    std::size_t e = s.find('\n', p);
    if (e == std::string::npos) e = s.size();
    std::string l = s.substr(p, e - p);
    if (!l.empty() && l.back() == '\r') l.pop_back();
    num(ws, r, 0, static_cast<double>(line_no++), number("count", 2));
    text(ws, r++, 1, l);
    p = e + 1;
  }
}

}  // namespace pierre::io::detail
