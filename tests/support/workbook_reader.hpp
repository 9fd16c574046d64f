// Reading back a workbook the report wrote: LibreOffice (headless) exports its sheets to CSV,
// read here as rows of fields; the xlsx's zip parts (charts, workbook.xml) come out with unzip.
// Shared by the xlsx report tests.
#pragma once

#include "support/tools.hpp"

#include <sys/wait.h>

#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pierre::test {

// ---- running programs ------------------------------------------------------------------

struct Exec {
  int status = -1;
  std::string output;
};

// Runs `command` through the shell, stdout and stderr into `log`, and reads the log back.
inline Exec run(const std::string& command, const std::filesystem::path& log) {
  Exec r;
  const int s = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  r.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  std::ifstream in(log, std::ios::binary);
  r.output.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return r;
}


// soffice with a private profile (parallel tests must not share one) and a time limit.
inline Exec soffice(const std::string& args, const std::filesystem::path& work) {
  const std::filesystem::path profile = work / "lo-profile";
  return run("timeout 180 soffice -env:UserInstallation=file://" + profile.string() +
                 " --headless --norestore " + args,
             work / "soffice.log");
}

// ---- CSV as LibreOffice writes it (text cells quoted, numbers not) ---------------------

struct Field {
  std::string text;
  bool quoted = false;
};
using Sheet = std::vector<std::vector<Field>>;

inline Sheet parse_csv(const std::string& s) {
  Sheet rows(1);
  rows.back().emplace_back();
  bool in_quotes = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    Field& f = rows.back().back();
    if (in_quotes) {
      if (c == '"' && i + 1 < s.size() && s[i + 1] == '"') {
        f.text += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        f.text += c;
      }
    } else if (c == '"') {
      in_quotes = true;
      f.quoted = true;
    } else if (c == ',') {
      rows.back().emplace_back();
    } else if (c == '\n') {
      rows.emplace_back();
      rows.back().emplace_back();
    } else if (c != '\r') {
      f.text += c;
    }
  }
  if (rows.back().size() == 1 && rows.back()[0].text.empty()) rows.pop_back();
  return rows;
}

inline const Field* cell(const Sheet& s, std::size_t r, std::size_t c) {
  if (r >= s.size() || c >= s[r].size()) return nullptr;
  return &s[r][c];
}

// The first row from `from` whose column `c` holds `text`.
inline std::optional<std::size_t> find_row(const Sheet& s, std::size_t c, const std::string& text,
                                           std::size_t from = 0) {
  for (std::size_t r = from; r < s.size(); ++r)
    if (c < s[r].size() && s[r][c].text == text) return r;
  return std::nullopt;
}

// A number cell: unquoted and parsing as a double in full. LibreOffice keeps the % of a
// percentage format even when it writes raw values ("2.5%" for 0.025).
inline std::optional<double> number(const Sheet& s, std::size_t r, std::size_t c) {
  const Field* f = cell(s, r, c);
  if (!f || f->quoted || f->text.empty()) return std::nullopt;
  std::string t = f->text;
  const bool percent = t.back() == '%';
  if (percent) t.pop_back();
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size()) return std::nullopt;
  return percent ? v / 100 : v;
}

// A row as text, for failure messages: quoted cells in quotes.
inline std::string dump(const Sheet& s, std::size_t r) {
  std::string out;
  if (r >= s.size()) return "(no row)";
  for (const auto& f : s[r]) out += (f.quoted ? "\"" + f.text + "\"" : f.text) + " | ";
  return out;
}

// Every sheet of a workbook exported by LibreOffice, by sheet name: one CSV per sheet
// (LibreOffice >= 7.2: sheet token -1), text cells quoted (token 7), UTF-8 (76), and numbers
// as raw values or, with as_shown, as their format shows them (token 9). `exec` says how
// soffice ended; no sheets when it failed.
struct SheetExport {
  Exec exec;
  std::map<std::string, Sheet> sheets;
};
inline SheetExport export_sheets(const std::filesystem::path& xlsx, const std::filesystem::path& work,
                                 bool as_shown = false) {
  const std::filesystem::path out = work / "csv";
  std::filesystem::create_directories(out);
  SheetExport e;
  e.exec = soffice(std::string("--convert-to 'csv:Text - txt - csv (StarCalc):44,34,76,1,,0,true,true,") +
                       (as_shown ? "true" : "false") + ",false,false,-1' --outdir '" + out.string() +
                       "' '" + xlsx.string() + "'",
                   work);
  if (e.exec.status != 0) return e;
  const std::string prefix = xlsx.stem().string() + "-";  // report-<Sheet>.csv
  for (const auto& f : std::filesystem::directory_iterator(out)) {
    std::string name = f.path().stem().string();
    if (name.rfind(prefix, 0) == 0) name.erase(0, prefix.size());
    std::ifstream in(f.path(), std::ios::binary);
    e.sheets[name] = parse_csv(std::string(std::istreambuf_iterator<char>(in), {}));
  }
  return e;
}

// ---- the xlsx as a zip (unzip, installed by the test set-up) ---------------------------

// The part names, one per line of `unzip -Z1`.
inline std::vector<std::string> zip_list(const std::filesystem::path& xlsx,
                                         const std::filesystem::path& work) {
  const Exec r = run("unzip -Z1 '" + xlsx.string() + "'", work / "unzip.log");
  std::vector<std::string> names;
  std::size_t p = 0;
  while (p < r.output.size()) {
    auto e = r.output.find('\n', p);
    if (e == std::string::npos) e = r.output.size();
    names.push_back(r.output.substr(p, e - p));
    p = e + 1;
  }
  return names;
}

// One part's text (a chart's or a sheet's XML).
inline std::string zip_entry(const std::filesystem::path& xlsx, const std::string& entry,
                             const std::filesystem::path& work) {
  return run("unzip -p '" + xlsx.string() + "' '" + entry + "'", work / "entry.log").output;
}

inline std::size_t occurrences(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

}  // namespace pierre::test
