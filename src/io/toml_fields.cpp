#include "toml_fields.hpp"

#include "pierre/io/nearest_name.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "pierre/io/input_error.hpp"
#include "text_check.hpp"
#include "text_file.hpp"

namespace pierre::io::detail {

std::string quoted_list(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + ("\"" + x + "\"");
  return s;
}

std::string describe(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return fmt::format("\"{}\"", n.as_string()->get());
    case toml::node_type::integer: return fmt::format("{}", n.as_integer()->get());
    case toml::node_type::floating_point: {
      const double v = n.as_floating_point()->get();
      if (std::isnan(v)) return "nan";
      if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
      std::string t = fmt::format("{}", v);
      if (t.find_first_of(".e") == std::string::npos) t += ".0";  // 2.0 stays a float
      return t;
    }
    case toml::node_type::boolean: return n.as_boolean()->get() ? "true" : "false";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date or time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

long line_of(const toml::node& n) { return static_cast<long>(n.source().begin.line); }

// A key as TOML writes it: bare when it may be (A–Z, a–z, 0–9, _ and -), else in quotes, so
// that an empty key or one with a space or a dot reads as what it is ("" = 1, "a.b" = 1).
// A TOML basic string: in quotes, with '"' and '\' escaped (a Windows path pasted back reads
// as written).
std::string toml_string(std::string_view s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

std::string written_key(std::string_view k) {
  const bool bare = !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
  return bare ? std::string(k) : toml_string(k);
}

TomlTable::TomlTable(std::filesystem::path file, const toml::table& t, std::string prefix,
                     long line, std::initializer_list<std::string_view> allowed)
    : TomlTable(std::move(file), t, std::move(prefix), line, allowed, nullptr) {}

namespace {

// Line n (1-based) of text, without its newline; empty past the end.
std::string_view line_text(std::string_view text, long n) {
  std::size_t pos = 0;
  for (long k = 1; k < n && pos != std::string_view::npos; ++k) {
    pos = text.find('\n', pos);
    if (pos != std::string_view::npos) ++pos;
  }
  if (pos == std::string_view::npos || pos > text.size()) return {};
  return text.substr(pos, text.find('\n', pos) - pos);
}

// Said where a unit was typed with a value.
constexpr const char* kFixedUnits = "fixed unit: m, kg, kg/m³, m/s, °; docs/scenario-format.md";

// Text that opens with a number: "2700 kg/m3", "12,5", " 5".
bool number_in_text(std::string_view t) {
  const std::size_t i = t.find_first_not_of(" \t+-");
  return i != std::string_view::npos && std::isdigit(static_cast<unsigned char>(t[i]));
}

// Where a `key = value` line's value starts, or npos.
std::size_t value_start(std::string_view line) {
  const std::size_t eq = line.find('=');
  return eq == std::string_view::npos ? eq : line.find_first_not_of(" \t", eq + 1);
}

// A key's value that opens with a letter: `name = Preg 1` (true, false, inf and nan are values).
bool bare_word_value(std::string_view line) {
  const std::size_t i = value_start(line);
  return i != std::string_view::npos && std::isalpha(static_cast<unsigned char>(line[i]));
}

// What else to leave out of a number written as text: "2,650" a thousands separator (a comma
// before three digits: read as a decimal comma it is 1000 times too small), "12,5" a decimal
// comma, "2700 kg/m3" a unit.
std::string number_text_advice(std::string_view t) {
  const std::size_t c = t.find(',');
  if (c != std::string_view::npos) {
    std::size_t d = c + 1;
    while (d < t.size() && std::isdigit(static_cast<unsigned char>(t[d]))) ++d;
    if (d - c - 1 == 3) return " and without a thousands separator (2650, not \"2,650\")";
    return " and with a decimal point (12.5, not \"12,5\")";
  }
  return fmt::format(" or unit (each value has a {})", kFixedUnits);
}

// A syntax error at a letter (or °, %) right after a number that opens a key's value:
// `height = 5 m`, `mass = 2700kg`, `angle = 35°`.
bool unit_after_number(std::string_view line, std::string_view what) {
  if (what.find("saw '") == std::string_view::npos) return false;
  std::size_t i = value_start(line);
  if (i == std::string_view::npos) return false;
  if (line[i] == '+' || line[i] == '-') ++i;
  if (i >= line.size() || !std::isdigit(static_cast<unsigned char>(line[i]))) return false;
  while (i < line.size() && (std::isdigit(static_cast<unsigned char>(line[i])) || line[i] == '.' || line[i] == '_'))
    ++i;
  while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
  if (i >= line.size()) return false;
  const unsigned char c = static_cast<unsigned char>(line[i]);
  // Not an exponent (5e3 is a number) unless letters follow it (5em is not).
  if (!((std::isalpha(c) && !((c == 'e' || c == 'E') && i + 1 < line.size() &&
                              (std::isdigit(static_cast<unsigned char>(line[i + 1])) || line[i + 1] == '-' ||
                               line[i + 1] == '+'))) ||
        c == '%' || c >= 0x80))  // ° and other units in UTF-8
    return false;
  // A unit is one short word (m, kg/m3, m/s, °) that ends the line, or a comment follows it:
  // "2nd road" or "100 blocks of 1.5 Mg" is text without its quotes.
  std::size_t end = i;
  while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '#') ++end;
  const std::size_t rest = line.find_first_not_of(" \t", end);
  return end - i <= 8 && (rest == std::string_view::npos || line[rest] == '#');
}

// The header a table's keys are written under, from its field path: [simulation] for
// "simulation", [materials.face], [[sources]] for "sources[0]", [barriers.candidate] for
// "barriers[1].candidate".
std::string header_of(std::string_view prefix) {
  std::string path;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (prefix[i] == '[') {
      i = prefix.find(']', i);
      if (i == std::string_view::npos) break;
      continue;
    }
    path += prefix[i];
  }
  return prefix.empty() || prefix.back() != ']' ? fmt::format("[{}]", path)
                                                : fmt::format("[[{}]]", path);
}

// What to do with a section found below another section's header.
std::string section_advice(std::string_view key) {
  return fmt::format("write {} above the first header, or under a header of its own", key);
}

// A table at the top level written after a [[list]] item (`[candidate]` below [[barriers]]):
// TOML reads a header as a full path, so an item's own table is [barriers.candidate]. The item
// is the one whose [[header]] stands last above the table, whichever list it is of (items
// written inline, `x = [{ … }]`, have no header to follow). Said as a condition: the table may
// be meant for the top level and misspelt.
std::string item_table_hint(const toml::table& top, std::string_view key, toml::source_index line) {
  std::string list;
  toml::source_index latest = 0;
  for (auto&& [k, v] : top) {
    const toml::array* a = v.as_array();
    if (!a || !a->is_array_of_tables()) continue;
    for (const toml::node& item : *a) {
      const toml::table* t = item.as_table();
      const toml::source_index at = item.source().begin.line;
      if (t && !t->is_inline() && at < line && at > latest) {
        latest = at;
        list = std::string(k.str());
      }
    }
  }
  if (list.empty()) return {};
  return fmt::format("; if it belongs to the [[{0}]] item above, write [{0}.{1}] (a TOML header is "
                     "a full path: [{1}] opens a section at the top level)",
                     list, key);
}

}  // namespace

TomlTable::TomlTable(std::filesystem::path file, const toml::table& t, std::string prefix,
                     long line, std::initializer_list<std::string_view> allowed,
                     Sections sections)
    : file_(std::move(file)), t_(&t), prefix_(std::move(prefix)), line_(line),
      sections_(std::move(sections)) {
  if (allowed.size() == 0) return;
  if (prefix_.empty())
    sections_ = std::make_shared<const std::vector<std::string>>(allowed.begin(), allowed.end());
  const toml::key* worst = nullptr;
  for (auto&& [k, v] : t) {
    if (std::find(allowed.begin(), allowed.end(), k.str()) != allowed.end()) continue;
    if (!worst || k.source().begin.line < worst->source().begin.line) worst = &k;
  }
  if (worst) {
    std::string names;
    for (std::string_view a : allowed) names += (names.empty() ? "" : ", ") + std::string(a);
    const std::string key(worst->str());
    std::string hint = nearest_name_hint(key, {allowed.begin(), allowed.end()});
    // A section's name below another section's header (not inside an inline table, where it
    // stands as written): meant as that section when it holds a table or a list, or when no
    // key of this table is near it (`materials = "…"` in [scenario] was materials_file).
    const toml::node& value = *t.get(key);
    const bool section = sections_ && !prefix_.empty() && !t.is_inline() &&
                         std::find(sections_->begin(), sections_->end(), key) != sections_->end();
    if (section && (value.is_table() || value.is_array() || hint.empty()))
      hint = fmt::format("; {} is a section of its own, and TOML puts every key below the {} "
                         "header into it: {}",
                         key, header_of(prefix_), section_advice(key));
    if (prefix_.empty() && hint.empty() && value.is_table())
      hint = item_table_hint(t, key, worst->source().begin.line);
    throw InputError(file_, static_cast<long>(worst->source().begin.line), field(written_key(key)),
                     "an unknown key", fmt::format("one of {}{}", names, hint));
  }
}

std::string TomlTable::field(std::string_view key) const {
  return prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
}

const toml::node* TomlTable::find(std::string_view key) const { return t_->get(key); }

void TomlTable::fail(std::string_view key, std::string_view expected) const {
  const toml::node* n = find(key);
  if (!n) missing(key, expected);
  throw InputError(file_, line_of(*n), field(key), describe(*n), std::string(expected));
}

std::optional<std::filesystem::path> TomlTable::file_path(std::string_view key,
                                                          std::string_view what) const {
  const auto name = string(key);
  if (!name) return std::nullopt;
  const std::filesystem::path full = relative_to(file_, *name);
  std::error_code ec;
  const auto st = std::filesystem::status(full, ec);
  std::string problem;
  if (!std::filesystem::exists(st))
    problem = "no such file: " + full.string();
  else if (std::filesystem::is_directory(st))
    problem = "a folder, not a file: " + full.string();
  if (problem.empty()) return full;
  const std::string relative_to_what =
      std::filesystem::path(*name).is_absolute()
          ? std::string()
          : fmt::format(" (a path relative to {})", file_.parent_path().empty()
                                                        ? std::string("the current folder")
                                                        : file_.parent_path().string());
  throw InputError(file_, line_of(*find(key)), field(key), "\"" + *name + "\" (" + problem + ")",
                   fmt::format("a readable {}{}", what, relative_to_what));
}

void TomlTable::missing(std::string_view key, std::string_view expected) const {
  // A section missing from the root may stand below another section's header, where TOML put
  // it (`profile = "p.csv"` at the end of the file, under the last [[observation_lines]]).
  // Tables at any depth (not inline ones, whose keys stand where they are written).
  if (prefix_.empty()) {
    const auto misplaced = [&](const auto& self, const toml::table& t,
                               const std::string& path) -> void {
      if (!path.empty() && !t.is_inline())
        if (const toml::node* n = t.get(key))
          throw InputError(file_, line_of(*n), field(key), "nothing",
                           fmt::format("{}; the key {} on this line stands below the {} header, "
                                       "and TOML puts it into that table: {}",
                                       expected, key, header_of(path), section_advice(key)));
      for (auto&& [k, v] : t) {
        const std::string sub = path.empty() ? std::string(k.str()) : path + "." + std::string(k.str());
        if (const auto* tt = v.as_table()) self(self, *tt, sub);
        if (const auto* a = v.as_array(); a && a->is_array_of_tables())
          for (const toml::node& e : *a) self(self, *e.as_table(), sub + "[0]");
      }
    };
    misplaced(misplaced, *t_, "");
  }
  throw InputError(file_, line_, field(key), "nothing", std::string(expected));
}

std::optional<double> TomlTable::number(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n) return std::nullopt;
  double v;
  if (const auto* i = n->as_integer())
    v = static_cast<double>(i->get());
  else if (const auto* f = n->as_floating_point())
    v = f->get();
  else if (const auto* s = n->as_string(); s && number_in_text(s->get()))
    fail(key, "a number, written without quotes" + number_text_advice(s->get()));
  else
    fail(key, "a number");
  if (!std::isfinite(v)) fail(key, "a finite number");
  return v;
}

double TomlTable::number(std::string_view key, double fallback) const {
  return number(key).value_or(fallback);
}

double TomlTable::required_number(std::string_view key, std::string_view expected) const {
  const auto v = number(key);
  if (!v) missing(key, expected);
  return *v;
}

std::optional<std::int64_t> TomlTable::integer(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n) return std::nullopt;
  const auto* i = n->as_integer();
  if (const auto* s = n->as_string(); !i && s && number_in_text(s->get()))
    fail(key, "an integer, written without quotes" + number_text_advice(s->get()));
  if (!i) fail(key, "an integer");
  return i->get();
}

std::optional<bool> TomlTable::boolean(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n) return std::nullopt;
  const auto* b = n->as_boolean();
  if (!b) fail(key, "true or false");
  return b->get();
}

std::optional<std::string> TomlTable::string(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n) return std::nullopt;
  const auto* s = n->as_string();
  if (!s) fail(key, "a string");
  if (auto bad = unwritable_text(s->get()))
    throw InputError(file_, line_of(*n), field(key), *bad, std::string(kWritableText));
  return s->get();
}

std::string TomlTable::required_string(std::string_view key, std::string_view expected) const {
  auto s = string(key);
  if (!s) missing(key, expected);
  return *s;
}

std::optional<TomlTable> TomlTable::subtable(std::string_view key,
                                             std::initializer_list<std::string_view> allowed) const {
  const toml::node* n = find(key);
  if (!n) return std::nullopt;
  const auto* t = n->as_table();
  if (!t) {
    // `profile = "profile.csv"` for a table that takes a file: the form that was meant.
    const auto* s = n->as_string();
    if (s && std::find(allowed.begin(), allowed.end(), "file") != allowed.end()) {
      const std::string path = toml_string(s->get().empty() ? "..." : s->get());
      const std::string f = field(key);
      const std::string inline_form = fmt::format("{} = {{ file = {} }}", key, path);
      fail(key, f.find_first_of(".[") == std::string::npos
                    ? fmt::format("a table: [{}] with file = {} on the line below it, or {}", f,
                                  path, inline_form)
                    : "a table, e.g. " + inline_form);
    }
    fail(key, "a table");
  }
  return TomlTable(file_, *t, field(key), line_of(*n), allowed, sections_);
}

const toml::array* TomlTable::array_of_tables(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n) return nullptr;
  const auto* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    fail(key, fmt::format("an array of tables ([[{}]])", field(key)));
  return a;
}

TomlTable TomlTable::element(std::string_view key, const toml::array& a, std::size_t i,
                             std::initializer_list<std::string_view> allowed) const {
  const toml::node& node = *a.get(i);
  return TomlTable(file_, *node.as_table(), fmt::format("{}[{}]", field(key), i), line_of(node),
                   allowed, sections_);
}

const toml::array* TomlTable::array(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n) return nullptr;
  const auto* a = n->as_array();
  if (!a) fail(key, "an array");
  return a;
}

namespace {

// toml++'s description, "Error while parsing floating-point: expected decimal digit or exponent,
// saw '.'", as what was found: "a malformed floating-point number (expected decimal digit or
// exponent, saw '.'; column 9)". Control characters it quotes (a '\n' it saw) are escaped, so
// that the message stays on one line. A description of another shape is kept as it is.
std::string syntax_problem(std::string_view description, long column) {
  std::string detail;
  for (const char c : description) {
    if (c == '\n') detail += "\\n";
    else if (c == '\r') detail += "\\r";
    else if (c == '\t') detail += "\\t";
    else if (static_cast<unsigned char>(c) < 0x20) detail += fmt::format("\\x{:02x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
    else detail += c;
  }
  constexpr std::string_view kPrefix = "Error while parsing ";
  const std::size_t colon = detail.find(": ");
  if (detail.rfind(kPrefix, 0) != 0 || colon == std::string::npos)
    return fmt::format("{} (column {})", detail, column);
  std::string what = detail.substr(kPrefix.size(), colon - kPrefix.size());
  const std::string rest = detail.substr(colon + 2);
  // The root table's errors are about a line that starts no key, table or comment.
  if (what.empty() || what == "root table")
    return fmt::format("a line that is not TOML ({}; column {})", rest, column);
  if (what.size() >= 14 && what.compare(what.size() - 14, 14, "floating-point") == 0)
    what += " number";
  return fmt::format("a malformed {} ({}; column {})", what, rest, column);
}

}  // namespace

std::string probability_expected(std::string expected, double found) {
  if (found >= 1 && found < 100)
    expected += fmt::format(" (a fraction, not a percentage: {:g} % is {:g})", found, found / 100);
  return expected;
}

toml::table parse_toml(const std::filesystem::path& file, const std::string& text) {
  // Text that is not UTF-8, or holds control characters, checked here line by line: toml++
  // names such a byte at the line before when it opens a line, in its own words.
  long line_no = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    ++line_no;
    if (auto bad = unwritable_text(std::string_view(text).substr(pos, nl - pos), "column"))
      throw InputError(file, line_no, "TOML syntax", *bad,
                       "UTF-8 text without control characters other than tab (as TOML requires)");
    pos = nl + 1;
  }
  try {
    return toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    std::string expected = "valid TOML (https://toml.io)";
    // The one syntax error a reader of our docs is led into: rows ([[a.b.rows]]) or a sub-table
    // added to a table written inline (`b = { … }`), which TOML closes where it ends.
    const std::string_view what = e.description();
    const std::string_view at_line = line_text(text, static_cast<long>(e.source().begin.line));
    if (what.find("existing inline table") != std::string_view::npos)
      expected += "; an inline table `name = { … }` cannot take rows or sub-tables later: write it "
                  "as a table, `[name]` with its keys on the lines below";
    if (const std::string ext = file.extension().string(); ext == ".csv" || ext == ".CSV") {
      // A profile or block table given where the scenario belongs.
      expected += "; this is a CSV file: give the scenario (.toml) that names it";
    } else if (what.find("expected a comment or whitespace, saw ','") != std::string_view::npos) {
      // A value cut short by a comma: most often a decimal comma (a European keyboard).
      expected += "; a decimal comma? TOML numbers take a point (0.5, not 0,5); several values "
                  "are an array, [1.0, 2.0]";
    } else if (unit_after_number(at_line, what)) {
      // `height = 5 m`, `density = 2700kg`: the unit typed as a habit.
      expected += fmt::format("; a unit after the number? write the number alone (5.0): each value "
                              "has a {}", kFixedUnits);
    } else if (what.find("could not determine value type") != std::string_view::npos &&
               bare_word_value(at_line)) {
      // `name = Preg 1`: text without its quotes.
      expected += "; text? put it in quotes (name = \"Preg 1\")";
    } else if (what.find("unescaped control characters") != std::string_view::npos) {
      // toml++ reads past a string's missing closing quote to the end of the line.
      expected += "; a string not closed on its line? every \"…\" needs its closing quote";
    }
    throw InputError(file, static_cast<long>(e.source().begin.line), "TOML syntax",
                     syntax_problem(e.description(), static_cast<long>(e.source().begin.column)),
                     expected);
  }
}

}  // namespace pierre::io::detail
