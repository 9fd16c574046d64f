#include "confirmed_inputs.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "pierre/io/nearest_name.hpp"

namespace pierre::io::detail {
namespace {

struct Confirmation {
  std::string key;  // flattened: "simulation.gravity" whether quoted or nested
  double value = 0;
  long line = 0;
  bool used = false;
};

void read(const TomlTable& t, const std::string& prefix, std::vector<Confirmation>& out) {
  for (auto&& [k, node] : t.table()) {
    const std::string key(k.str());
    const std::string full = prefix.empty() ? key : prefix + "." + key;
    if (node.is_table()) {
      read(*t.subtable(key, {}), full, out);
      continue;
    }
    if (!node.is_number())
      t.fail(key, "the number the input note names, under the field it names, as the note "
                  "says: \"blocks.density\" = 2.65");
    const double v = *t.number(key);  // NaN, infinity: an error there
    // "a.b" quoted and a = { b = ... } are two TOML keys but one confirmation.
    for (const Confirmation& c : out)
      if (c.key == full)
        t.fail(key, fmt::format("\"{}\" once (it is confirmed at line {} too)", full, c.line));
    out.push_back({full, v, line_of(node)});
  }
}

// The value as the note and the confirmation print it: the shortest text that reads back the
// same double, so a value copied from the note matches exactly.
std::string shown(double v) { return fmt::format("{}", v); }

}  // namespace

std::string confirmation_key(const InputNote& note, const std::filesystem::path& scenario_file) {
  namespace fs = std::filesystem;
  const std::string& field = note.doubt ? note.doubt->field : note.field;
  if (note.file == scenario_file) return field;
  // The CSV as seen from the scenario's folder: two sections' a/blocks.csv and b/blocks.csv are
  // two keys (each note must be confirmable on its own).
  std::error_code ec;
  const fs::path file = fs::absolute(note.file, ec).lexically_normal();
  const fs::path folder = fs::absolute(scenario_file, ec).lexically_normal().parent_path();
  const fs::path rel = ec ? fs::path() : file.lexically_relative(folder);
  // Its line too, as the note prints it ("blocks.csv:26: mass"): two notes on one column (the
  // heaviest block, a row given by mass among rows by volume) are two keys.
  return (rel.empty() ? note.file.filename() : rel).generic_string() + ":" +
         std::to_string(note.line) + ":" + field;
}

void apply_confirmations(const TomlTable& top, std::vector<InputNote>& notes) {
  std::vector<Confirmation> given;
  if (const auto c = top.subtable("confirmed", {})) read(*c, "", given);
  std::vector<std::string> keys;  // of the doubting notes, for a misspelt confirmation
  for (InputNote& n : notes) {
    if (!n.doubt) continue;
    const std::string key = confirmation_key(n, top.file());
    keys.push_back(key);
    const std::string entry = fmt::format("\"{}\" = {}", key, shown(n.doubt->value));
    // A check line names the input as the key does: "rests on blocks.csv:2:mass", not on "mass".
    n.doubt->field = key;
    const auto c = std::find_if(given.begin(), given.end(),
                                [&](const Confirmation& g) { return g.key == key; });
    if (c == given.end()) {
      if (std::isfinite(n.doubt->value))  // (a doubt without its value cannot be confirmed)
        n.text += fmt::format(". If it is meant, confirm it in the scenario: [confirmed] {}", entry);
      continue;
    }
    c->used = true;
    if (c->value == n.doubt->value) {
      n.text += fmt::format(". Confirmed as meant ([confirmed] {}, line {})", entry, c->line);
      n.doubt.reset();
    } else {
      n.text += fmt::format(". [confirmed] gives {} for it (line {}), not the value noted: it "
                            "stays in doubt until the confirmation restates it ({})",
                            shown(c->value), c->line, entry);
    }
  }
  for (const Confirmation& g : given) {
    if (g.used) continue;
    notes.push_back({top.file(), g.line, "confirmed." + g.key,
                     fmt::format("\"{}\" confirms nothing, as no input is noted as a likely "
                                 "slip under that name{}: remove it, or correct the name",
                                 g.key,
                                 keys.empty() ? std::string(" (none is)")
                                              : nearest_name_hint(g.key, keys)),
                     {}});
  }
}

}  // namespace pierre::io::detail
