#include "pierre/io/report_template.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

#include "text_file.hpp"
#include "toml_fields.hpp"

namespace pierre::io {
namespace detail {
extern const char kShippedReportTemplate[];  // templates/report.toml, built in (CMakeLists.txt)
}
namespace {

namespace fs = std::filesystem;
using detail::line_of;
using detail::TomlTable;

using Keys = std::vector<std::string>;

const Keys kChartKeys = {"title", "x_axis", "y_axis"};
const Keys kCharts = {"speed_histogram", "height_histogram", "energy_histogram",
                      "speed_cdf",       "height_cdf",       "energy_cdf",
                      "profile",         "rd_histogram",     "id_histogram",
                      "rd_cdf",          "id_cdf",           "quarry_section"};
const Keys kSheetKeys = {"summary", "inputs",       "blocks",   "barrier", "quarry",
                         "profile", "trajectories", "crossings"};
const Keys kOrderKeys = {"summary", "barriers", "quarries",     "profile",
                         "inputs",  "blocks",   "trajectories", "crossings"};
// Sheet names holding "{name}" (one sheet per barrier / per quarry row).
bool per_item_sheet(std::string_view key) { return key == "barrier" || key == "quarry"; }

std::map<std::string, Keys, std::less<>> make_sections() {
  std::map<std::string, Keys, std::less<>> s;
  s["sheets"] = kSheetKeys;
  s["formats"] = {"count",   "speed",     "length",   "length_at_least", "coordinate", "energy", "mass",
                  "volume",  "density",   "factor",   "parameter",   "p_value", "scientific", "probability",
                  "percent", "small_percent", "time",      "angle",    "material",    "general", "date",
                  "open_class", "open_energy", "info_energy"};
  s["titles"] = {"summary",      "run",          "barrier_values", "lines",
                 "barrier_classes", "checks",   "inputs",       "simulation",     "materials",
                 "blocks",       "sources",      "profile_vertices", "observation_lines", "barrier_inputs",
                 "scenario_text", "barrier",     "statistics",     "bootstrap",
                 "design",       "factors",      "exceedance",     "barrier_checks",
                 "notes",        "chart_data",   "profile",        "trajectories",
                 "crossings",    "capped",       "complete",     "no_rows",     "quarry",
                 "quarry_summary", "quarry_average", "quarry_geometry", "quarry_counts",
                 "quarry_zones", "quarry_statistics", "quarry_fits", "quarry_exceedance",
                 "quarry_governing", "stop_reasons", "quarry_profile", "quarry_inputs",
                 "profile_lines", "profile_plain", "basis"};
  s["labels"] = {"project",       "description", "reference", "revision", "prepared_by",
                 "checked_by", "revision_in_header", "scenario_file", "date",        "version",
                 "seed",          "throws",      "trajectories",  "rule_sets",   "runout_p50", "runout_p95", "runout_p99", "runout_max",
                 "materials_file", "rules",      "crossings",     "not_reached", "design_block",
                 "bootstrap_seed", "none",     "calculated",    "observed",    "rd",
                 "id",            "beyond_profile", "pooled",    "observed_source", "total",
                 "quarry_profile", "verdict", "no_checks", "fit_doubtful", "fit_past_floor",
                 "lines_every_crossing", "overrides", "energy_classes", "read_from", "line_not_crossed", "stop_energy", "stop_friction",
                 "stop_boundary", "stop_time_limit", "stop_impact_limit", "stop_numerical",
                 "quarry_average_note", "resolved", "defaulted", "from_class",
                 "open_class_capacity", "input_notes", "quarry_all", "quarry_all_note", "travel_time",
                 "travel_time_value", "runout_quarry_note", "runout_note", "failing", "no_candidate", "no_design",
                 "verify_note", "passing_height_note",
                 "translational_energy_note", "blocks_sheet"};
  s["basis"] = {"model", "not_modelled", "statistics", "barriers", "quarries"};
  s["headings.barriers"] = {"name",      "line",      "chainage", "v_k",          "h_k",
                            "v_d",       "m_d",       "e_d",        "free_board", "interception_height",
                            "rules",     "mel_req",   "sel_req",  "energy_class", "class_mel",
                            "class_sel", "candidate", "verdict",  "verdict_lines"};
  s["headings.lines"] = {"name", "chainage", "count", "not_reached", "quantity", "mean", "p50",
                         "p95",  "max",      "speed", "height",      "energy"};
  s["headings.stop_reasons"] = {"reason", "count", "share", "meaning"};
  s["headings.checks"] = {"subject", "id", "what", "value", "limit", "unit",
                          "rule",    "status", "reason"};
  s["headings.simulation"] = {"seed",        "throws",           "gravity",          "max_time",
                              "max_impacts", "stop_head_factor", "max_sliding_speed",
                              "roughness_distribution", "roughness_mean", "roughness_sd",
                              "size_reduction", "size_reduction_b", "size_reduction_m",
                              "size_reduction_floor"};
  s["headings.materials"] = {"name",      "source",    "normal_energy", "normal_energy_k",
                             "tangential_energy", "tangential_energy_k", "roughness",
                             "friction_angle"};
  s["headings.blocks"] = {"id",       "mass",      "volume",    "density",
                          "diameter", "shape_min", "shape_max", "count"};
  s["headings.sources"] = {"name", "x", "z", "vx", "vz", "omega"};
  s["headings.profile_vertices"] = {"x", "z", "material"};
  s["headings.observation_lines"] = {"name", "x"};
  s["headings.barrier_inputs"] = {
      "field",          "name",           "line",          "rules",
      "design_block",   "volume",         "density",       "percentile",
      "free_board_diameter", "data_quality", "energy_class", "mel",
      "sel",            "height",         "elongation_mel", "elongation_sel",
      "distance_to_object", "residual_height", "acceptable_energy", "acceptable_height",
      "observed_file"};
  s["headings.statistics"] = {
      "statistic",      "speed",          "height",        "energy",         "rotational_energy",
      "observed_speed", "observed_height", "observed_energy", "count",        "mean",
      "sd",             "min",            "max",           "p50",            "p95",
      "weibull_k",      "weibull_lambda", "weibull_ks_d",  "weibull_ks_p",   "lognormal_mu",
      "lognormal_sigma", "lognormal_ks_d", "lognormal_ks_p"};
  s["headings.bootstrap"] = {"quantity",   "estimate",  "lower", "upper", "half_width",
                             "confidence", "resamples", "v_k",   "h_k",   "E_d",
                             "h_i"};
  s["headings.design"] = {"v_d", "m_d", "E_d", "sel_req", "mel_req", "h_i", "energy_class"};
  s["headings.factors"] = {
      "quantity",      "value",       "unit",          "how",         "v_k_weibull",
      "v_k_empirical", "v_k",         "gamma_F",       "v_d",         "density",
      "volume",        "gamma_M",     "m_d",           "E_d",         "gamma_E_SEL",
      "sel_req",       "gamma_E_MEL", "mel_req",       "gamma_d_MEL", "gamma_d_SEL",
      "h_k_weibull",   "h_k_empirical",
      "h_k",           "gamma_h",     "h_d",           "free_board_diameter", "free_board",
      "h_i",           "h_max_sim",   "candidate_mel", "candidate_sel",
      "residual_height_category"};
  s["headings.exceedance"] = {"what",     "threshold", "unit", "simulated_weibull",
                              "simulated_empirical", "observed_weibull"};
  s["headings.histogram"] = {"bin_lower",   "bin_upper",     "count",         "density",
                             "outline_x",   "outline_y",     "curve_x",       "weibull_pdf",
                             "lognormal_pdf", "empirical_cdf", "weibull_cdf", "lognormal_cdf",
                             "histogram",   "source"};
  s["headings.profile"] = {"x", "z", "profile", "paths", "lines", "barriers"};
  s["headings.trajectories"] = {
      "trajectory", "source",   "block",       "throw",          "mass",
      "start_x",    "start_z",  "stop_x",      "stop_z",         "runout",
      "stop_reason", "duration", "impacts",    "first_impact_x", "first_impact_z",
      "floor_contact_x", "floor_contact_z", "id", "rd", "max_jump_height", "max_speed", "max_energy", "section"};
  s["headings.crossings"] = {"trajectory", "line",  "chainage", "block",  "mass",
                             "time",       "direction", "vx",   "vz",     "speed",
                             "omega",      "translational_energy", "rotational_energy",
                             "passing_height", "sliding", "section"};
  // Quarry danger zones (design-checks.md §2).
  s["headings.quarry_summary"] = {"row",    "source", "height", "thrown", "rd_gov", "id_gov",
                                  "rd50_h", "rd95_h", "rdmax_h", "id50_h", "id95_h", "idmax_h"};
  s["headings.quarry_geometry"] = {"section", "crest_x",  "crest_z", "crest_origin",
                                   "toe_x",   "toe_z",    "toe_origin", "height",
                                   "height_derived", "height_origin", "floor_angle",
                                   "floor_length", "seed"};
  s["headings.quarry_inputs"] = {"section",       "group",       "rules",       "crest_x",
                                 "crest_origin",  "toe_x",       "toe_origin",  "height",
                                 "height_origin", "bench_width", "work_areas",  "exceedance",
                                 "observed_source"};
  s["headings.quarry_counts"] = {"section",   "thrown",       "reached_floor", "not_reached_floor",
                                 "above_toe", "left_profile", "left_upslope",  "abnormal"};
  s["headings.quarry_zones"] = {"section",   "danger_zone", "first_impact_zone", "bench_width",
                                "retention", "ritchie_width", "work_areas"};
  s["headings.quarry_statistics"] = {"distance", "source", "count", "zeros", "censored", "p50",
                                     "p95",      "p99",    "max",   "p50_h", "p95_h",    "p99_h",
                                     "max_h"};
  s["headings.quarry_fits"] = {"distance", "zero_share", "mu",     "sigma",    "observed",
                               "censored", "ks_d",       "ks_p",   "ks_below", "cdf_rmse",
                               "observed_ks_d", "observed_ks_p", "fit_error"};
  s["headings.quarry_exceedance"] = {"probability", "rd_fit_h", "rd_empirical_h", "rd_fit",
                                     "rd_empirical", "id_fit_h", "id_empirical_h", "id_fit",
                                     "id_empirical"};
  s["headings.quarry_governing"] = {"quantity", "value_h", "value", "how", "rd_gov", "id_gov",
                                    "rd_lower", "rd_upper"};
  s["headings.quarry_chart"] = {"outline_x",  "outline_y",  "curve_x",     "fitted_pdf",
                                "empirical_cdf", "fitted_cdf", "observed_x", "observed_cdf",
                                "histogram", "source",     "x",           "z",
                                "profile",   "paths",      "toe",         "danger_zone",
                                "first_impact_zone", "work_areas", "bench"};
  for (const auto& c : kCharts) s["chart." + c] = kChartKeys;
  return s;
}

// Keys an earlier layout had and this one no longer uses, by section: a firm's copy that still
// holds them is read (they are ignored, and listed in ReportTemplate::retired_keys), so that
// it keeps working. A key that was never in any layout is still an error.
const std::map<std::string, Keys, std::less<>>& retired_sections() {
  static const std::map<std::string, Keys, std::less<>> r = {
      // Before the Summary's observation lines showed mean, P50, P95 and max of each quantity.
      {"headings.lines", {"speed_mean", "speed_p95", "height_p95", "energy_p95", "energy_max"}},
      // Before the Summary gave each candidate barrier's kit and verdict in its own table.
      {"labels", {"candidate_passes", "candidate_fails", "candidate_warns"}},
      // Before the Summary's barrier table was split (titles.barrier_values, barrier_classes).
      {"titles", {"barriers"}},
  };
  return r;
}

const Keys kColours = {"heading_font", "heading_fill", "title_font", "note_font", "pass_font",
                       "pass_fill",    "fail_font",    "fail_fill",  "warn_font", "warn_fill",
                       "profile",      "paths",        "lines",      "barriers",  "histogram",
                       "weibull",      "lognormal",    "empirical",  "observed",  "toe",
                       "danger_zone",  "first_impact_zone", "work_areas", "bench"};

std::string joined(const Keys& keys) {
  std::string s;
  for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

// A table holding exactly `keys`, each a string, and perhaps keys of `section` an earlier
// layout had (retired_sections()), which are listed in `retired` and otherwise ignored.
std::map<std::string, std::string, std::less<>> read_strings(const TomlTable& t, const Keys& keys,
                                                             std::string_view what,
                                                             std::string_view section = {},
                                                             std::vector<std::string>* retired = nullptr) {
  const auto old = retired_sections().find(section);
  // TomlTable rejects unknown keys only from an initializer list; check them here.
  for (auto&& [k, v] : t.table()) {
    if (std::find(keys.begin(), keys.end(), k.str()) != keys.end()) continue;
    if (old != retired_sections().end() && retired &&
        std::find(old->second.begin(), old->second.end(), k.str()) != old->second.end()) {
      retired->push_back(std::string(section) + "." + std::string(k.str()));
      continue;
    }
    throw InputError(t.file(), static_cast<long>(k.source().begin.line), t.field(k.str()),
                     "an unknown key", fmt::format("one of {}", joined(keys)));
  }
  std::map<std::string, std::string, std::less<>> out;
  for (const auto& k : keys) out[k] = t.required_string(k, std::string(what));
  return out;
}

// The sub-table `key` of `t` (required).
TomlTable required_table(const TomlTable& t, std::string_view key) {
  const toml::node* n = t.find(key);
  if (!n) t.missing(key, "a table");
  const auto* sub = n->as_table();
  if (!sub) t.fail(key, "a table");
  return TomlTable(t.file(), *sub, t.field(key), line_of(*n), {});
}

void reject_unknown(const TomlTable& t, const Keys& keys) {
  for (auto&& [k, v] : t.table()) {
    if (std::find(keys.begin(), keys.end(), k.str()) == keys.end())
      throw InputError(t.file(), static_cast<long>(k.source().begin.line), t.field(k.str()),
                       "an unknown key", fmt::format("one of {}", joined(keys)));
  }
}

std::int64_t required_integer(const TomlTable& t, std::string_view key, std::int64_t lo,
                              std::int64_t hi) {
  const auto expected = fmt::format("an integer from {} to {}", lo, hi);
  const auto v = t.integer(key);
  if (!v) t.missing(key, expected);
  t.check(key, *v >= lo && *v <= hi, expected);
  return *v;
}

std::uint32_t parse_colour(const TomlTable& t, std::string_view key) {
  const std::string expected = "a colour \"#RRGGBB\"";
  const std::string s = t.required_string(key, expected);
  bool ok = s.size() == 7 && s[0] == '#' &&
            std::all_of(s.begin() + 1, s.end(), [](char c) { return std::isxdigit(
                                                           static_cast<unsigned char>(c)) != 0; });
  t.check(key, ok, expected);
  return static_cast<std::uint32_t>(std::strtoul(s.c_str() + 1, nullptr, 16));
}

// Excel's rules for a sheet name (checked again by libxlsxwriter when writing).
void check_sheet_name(const TomlTable& t, std::string_view key, const std::string& name) {
  const std::string expected =
      "a sheet name: 1 to 31 characters, none of [ ] : * ? / \\, not starting or ending with '";
  bool ok = !name.empty() && name.size() <= 31 &&
            name.find_first_of("[]:*?/\\") == std::string::npos && name.front() != '\'' &&
            name.back() != '\'';
  if (per_item_sheet(key)) ok = ok || (!name.empty() && name.find("{name}") != std::string::npos);
  t.check(key, ok, expected);
  t.check(key, !sheet_name_reads_as_reference(name),
          "a sheet name that does not read as a cell reference (A1, R1C1) or start with a digit "
          "or a point: charts and print areas would point at the cell, not the sheet");
}

// Copies into `t` every key of `base` that `t` lacks, recursing into tables both hold, and
// lists the dotted names of the copies in `filled`. A key `t` holds is kept as it is, whatever
// its type: the strict reading after this judges it, at its own line.
void fill_missing(toml::table& t, const toml::table& base, const std::string& prefix,
                  std::vector<std::string>& filled) {
  for (auto&& [k, v] : base) {
    const std::string name = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    toml::node* mine = t.get(k.str());
    if (!mine) {
      t.insert(k, v);
      filled.push_back(name);
    } else if (mine->is_table() && v.is_table()) {
      fill_missing(*mine->as_table(), *v.as_table(), name, filled);
    }
  }
}

// A copy's sheet order made before a sheet was added lacks it: each missing sheet goes in
// after the sheet it follows in the built-in order (first if none does), and is listed.
void complete_order(Keys& order, std::vector<std::string>& filled) {
  for (std::size_t i = 0; i < kOrderKeys.size(); ++i) {
    if (std::find(order.begin(), order.end(), kOrderKeys[i]) != order.end()) continue;
    auto at = order.begin();
    for (std::size_t k = i; k-- > 0;) {
      if (const auto p = std::find(order.begin(), order.end(), kOrderKeys[k]); p != order.end()) {
        at = p + 1;
        break;
      }
    }
    order.insert(at, kOrderKeys[i]);
    filled.push_back("sheets.order: " + kOrderKeys[i]);
  }
}

bool same_ignoring_case(std::string_view x, std::string_view y) {
  return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
         });
}

// Distinct fixed sheet names (the per-item sheets are made distinct when written). A clash
// with a name the built-in layout supplied is blamed on the copy's own key, at its own line.
void check_distinct_sheet_names(const TomlTable& t,
                                const std::map<std::string, std::string, std::less<>>& names,
                                const std::vector<std::string>& filled) {
  auto built_in = [&](const std::string& key) {
    return std::find(filled.begin(), filled.end(), "sheets." + key) != filled.end();
  };
  for (std::size_t i = 0; i < kSheetKeys.size(); ++i)
    for (std::size_t j = i + 1; j < kSheetKeys.size(); ++j) {
      const std::string &a = kSheetKeys[i], &b = kSheetKeys[j];
      // Excel compares sheet names without regard to case.
      if (per_item_sheet(a) || per_item_sheet(b) || !same_ignoring_case(names.at(a), names.at(b)))
        continue;
      const bool blame_a = built_in(b);
      const std::string& other = blame_a ? b : a;
      t.fail(blame_a ? a : b,
             fmt::format("a name other than sheets.{}'s{}", other,
                         built_in(other) ? " (the copy leaves it out: the built-in layout gives it)"
                                         : ""));
    }
}

}  // namespace

const std::map<std::string, std::vector<std::string>, std::less<>>& report_template_sections() {
  static const auto s = make_sections();
  return s;
}

const std::vector<std::string>& report_template_colours() { return kColours; }

bool sheet_name_reads_as_reference(std::string_view name) {
  if (name.empty()) return false;
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  if (digit(name[0]) || name[0] == '.') return true;
  // A1: one to three letters, then digits only (checked as a shape: a little wider than
  // Excel's XFD1048576 does no harm).
  std::size_t i = 0;
  while (i < name.size() && letter(name[i])) ++i;
  if (i >= 1 && i <= 3 && i < name.size() &&
      std::all_of(name.begin() + static_cast<std::ptrdiff_t>(i), name.end(), digit))
    return true;
  // R1C1: R, C, RC, R5, C7, R5C7 (either part may be left out).
  std::size_t k = 0;
  auto part = [&](char upper) {
    if (k < name.size() && (name[k] == upper || name[k] == upper + ('a' - 'A'))) {
      ++k;
      while (k < name.size() && digit(name[k])) ++k;
      return true;
    }
    return false;
  };
  const bool r = part('R');
  const bool c = part('C');
  return (r || c) && k == name.size();
}

const std::string& ReportTemplate::get(std::string_view section, std::string_view key) const {
  const auto s = text.find(section);
  if (s != text.end()) {
    const auto k = s->second.find(key);
    if (k != s->second.end()) return k->second;
  }
  throw std::out_of_range(fmt::format("report template {}: no {}.{}", file.string(), section, key));
}

std::uint32_t ReportTemplate::colour(std::string_view key) const {
  const auto c = colours.find(key);
  if (c == colours.end())
    throw std::out_of_range(fmt::format("report template {}: no colours.{}", file.string(), key));
  return c->second;
}

const std::string& shipped_report_template_text() {
  static const std::string text = detail::kShippedReportTemplate;
  return text;
}

ReportTemplate load_report_template(const std::filesystem::path& file) {
  const std::string text = detail::read_text(file, "report template (templates/report.toml)");
  toml::table root = detail::parse_toml(file, text);
  // A firm's own copy made before keys were added is completed from the layout this binary was
  // built with; what it holds is read strictly (unknown keys, types, ranges) as before.
  std::vector<std::string> filled;
  fill_missing(root, detail::parse_toml("templates/report.toml (built in)", shipped_report_template_text()),
               "", filled);
  const TomlTable top(file, root, "", 0,
                      {"sheets", "rows", "page", "charts", "colours", "formats", "titles",
                       "basis", "labels", "headings", "chart"});

  ReportTemplate tpl;
  tpl.file = file;
  tpl.source = input_file(file, text);
  tpl.built_in_keys = std::move(filled);
  const auto& sections = report_template_sections();

  // [sheets]: the names (strings) and the order (an array).
  {
    const TomlTable t = required_table(top, "sheets");
    Keys allowed = kSheetKeys;
    allowed.push_back("order");
    reject_unknown(t, allowed);
    auto& names = tpl.text["sheets"];
    for (const auto& k : kSheetKeys) {
      names[k] = t.required_string(k, "a string: the sheet's name");
      check_sheet_name(t, k, names[k]);
    }
    const std::string expected =
        fmt::format("an array holding each of {} at most once", joined(kOrderKeys));
    const toml::array* order = t.array("order");
    if (!order) t.missing("order", expected);
    for (const auto& e : *order) {
      const auto* s = e.as_string();
      if (!s) t.fail("order", expected);
      const bool known = std::find(kOrderKeys.begin(), kOrderKeys.end(), s->get()) != kOrderKeys.end();
      const bool again = std::find(tpl.order.begin(), tpl.order.end(), s->get()) != tpl.order.end();
      t.check("order", known && !again,
              fmt::format("{} (\"{}\" is {})", expected, s->get(),
                          known ? "there twice" : "not a sheet of the report"));
      tpl.order.push_back(s->get());
    }
    complete_order(tpl.order, tpl.built_in_keys);
    check_distinct_sheet_names(t, names, tpl.built_in_keys);
  }
  {
    const TomlTable t = required_table(top, "rows");
    reject_unknown(t, {"trajectories", "crossings", "print"});
    tpl.trajectory_rows =
        static_cast<std::size_t>(required_integer(t, "trajectories", 0, 1'000'000));
    tpl.crossing_rows = static_cast<std::size_t>(required_integer(t, "crossings", 0, 1'000'000));
    tpl.print_rows = static_cast<std::size_t>(required_integer(t, "print", 0, 1'000'000));
  }
  {
    const TomlTable t = required_table(top, "page");
    reject_unknown(t, {"landscape", "paper", "footer", "header"});
    const auto l = t.boolean("landscape");
    if (!l) t.missing("landscape", "true or false");
    tpl.landscape = *l;
    tpl.paper = static_cast<int>(required_integer(t, "paper", 0, 118));
    // No picture codes in the footer or header: pierre gives them no image, and libxlsxwriter
    // fails (or worse) on a &G without one.
    auto no_picture_codes = [&](const char* key, const std::string& text) {
      std::string upper = text;
      for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      t.check(key, upper.find("&G") == std::string::npos && upper.find("&[PICTURE]") == std::string::npos,
              fmt::format("a {} without picture codes (&G, &[Picture]): the report puts no image in it",
                          key));
    };
    const std::string footer = t.required_string("footer", "a string: the page footer");
    t.check("footer", footer.size() <= 255, "a footer of at most 255 characters (Excel's limit)");
    no_picture_codes("footer", footer);
    tpl.text["page"]["footer"] = footer;
    // The header, with {project} and {document} (the reference, revision and date): optional,
    // so that a layout copied before it existed keeps working.
    const std::string header = t.string("header").value_or("&L{project}&R{document}");
    t.check("header", header.size() <= 50,
            "a header of at most 50 characters (Excel allows 255 in all, and the project's name "
            "and the document's reference and revision are put in)");
    no_picture_codes("header", header);
    tpl.text["page"]["header"] = header;
  }
  {
    const TomlTable t = required_table(top, "charts");
    reject_unknown(t, {"histogram_bins", "curve_points", "profile_line_height", "width",
                       "height"});
    tpl.histogram_bins = static_cast<int>(required_integer(t, "histogram_bins", 2, 500));
    tpl.curve_points = static_cast<int>(required_integer(t, "curve_points", 2, 2000));
    tpl.profile_line_height = t.required_number("profile_line_height", "a height in m");
    t.check("profile_line_height", tpl.profile_line_height > 0, "a positive height in m");
    tpl.chart_width = static_cast<int>(required_integer(t, "width", 100, 4000));
    tpl.chart_height = static_cast<int>(required_integer(t, "height", 100, 4000));
  }
  {
    const TomlTable t = required_table(top, "colours");
    reject_unknown(t, kColours);
    for (const auto& k : kColours) tpl.colours[k] = parse_colour(t, k);
  }
  for (const char* plain : {"formats", "titles", "labels", "basis"}) {
    const TomlTable t = required_table(top, plain);
    tpl.text[plain] = read_strings(t, sections.at(plain), "a string", plain, &tpl.retired_keys);
  }
  {
    const TomlTable h = required_table(top, "headings");
    Keys tables;
    for (const auto& [name, keys] : sections)
      if (name.rfind("headings.", 0) == 0) tables.push_back(name.substr(9));
    reject_unknown(h, tables);
    for (const auto& name : tables) {
      const TomlTable t = required_table(h, name);
      tpl.text["headings." + name] =
          read_strings(t, sections.at("headings." + name), "a string: the column heading",
                       "headings." + name, &tpl.retired_keys);
    }
  }
  {
    const TomlTable c = required_table(top, "chart");
    reject_unknown(c, kCharts);
    for (const auto& name : kCharts) {
      const TomlTable t = required_table(c, name);
      tpl.text["chart." + name] = read_strings(t, kChartKeys, "a string: the chart's label");
    }
  }
  return tpl;
}

}  // namespace pierre::io
