#include "csv_table.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "pierre/io/input_error.hpp"
#include "text_check.hpp"
#include "text_file.hpp"

namespace pierre::io::detail {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// The cells of one line (RFC 4180 within a line): a cell in double quotes may hold commas and
// doubled quotes ("P,01", "5"" block"); spaces around a cell are trimmed.
std::vector<std::string> split(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::string cell;
    if (i < line.size() && line[i] == '"') {
      std::size_t j = i + 1;
      for (; j < line.size(); ++j) {
        if (line[j] != '"') {
          cell += line[j];
        } else if (j + 1 < line.size() && line[j + 1] == '"') {
          cell += '"';
          ++j;
        } else {
          break;  // the closing quote
        }
      }
      if (j >= line.size()) {  // no closing quote: the text as it stands
        cell = std::string(trim(line.substr(i)));
        cells.push_back(std::move(cell));
        break;
      }
      const std::size_t comma = line.find(',', j + 1);
      // Anything between the closing quote and the comma is kept, so that it is not lost quietly.
      cell += trim(line.substr(j + 1, comma == std::string_view::npos ? std::string_view::npos
                                                                       : comma - j - 1));
      cells.push_back(std::move(cell));
      if (comma == std::string_view::npos) break;
      i = comma + 1;
      continue;
    }
    const std::size_t comma = line.find(',', i);
    cells.emplace_back(trim(line.substr(i, comma == std::string_view::npos ? std::string_view::npos
                                                                           : comma - i)));
    if (comma == std::string_view::npos) break;
    i = comma + 1;
  }
  return cells;
}

// Spreadsheets capitalise headings ("X", "Volume"): a column's name is matched without case.
bool same_name(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

bool is_number(std::string_view s) {
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && ec == std::errc{} && ptr == s.data() + s.size();
}

// The input tables' columns that hold names; every other column holds numbers.
bool text_column(std::string_view name) { return name == "material" || name == "id"; }

// Whether a row too wide for its header fits it once whole numbers side by side are read as
// one number with a decimal comma ("16,5,0,floor" → 16.5, 0, floor): a number under every
// column that takes one. Pairs from `from` on are tried, each way (rows are short).
bool fits_with_decimal_commas(const std::vector<std::string>& cells,
                              const std::vector<std::string>& header, std::size_t from = 0) {
  if (cells.size() == header.size()) {
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (!text_column(header[i]) && !cells[i].empty() && !is_number(cells[i])) return false;
    return true;
  }
  for (std::size_t i = from; cells.size() > header.size() && i + 1 < cells.size(); ++i) {
    if (!whole_number_text(cells[i]) || !whole_number_text(cells[i + 1]) || cells[i + 1].front() == '-')
      continue;
    std::vector<std::string> merged = cells;
    merged[i] += "." + merged[i + 1];
    merged.erase(merged.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    if (fits_with_decimal_commas(merged, header, i + 1)) return true;
  }
  return false;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

// " (x may be written x_m, z z_m)": how the aliases read in a message.
std::string alias_note(const ColumnAliases& aliases) {
  std::string s = " (";
  for (std::size_t i = 0; i < aliases.size(); ++i)
    s += fmt::format("{}{}{} {}", i ? ", " : "", aliases[i].second,
                     i ? "" : " may be written", aliases[i].first);
  return s + ")";
}

// A spreadsheet set to a European locale separates cells by ';', a text export by tabs: a line
// of too few cells holding either (outside quotes, where a text may hold them) was most likely
// written so. How the message names it: the more frequent of the two, or nothing.
std::optional<std::string_view> other_separator(std::string_view line) {
  std::size_t semicolons = 0, tabs = 0;
  bool quoted = false;  // a doubled quote inside a quoted cell toggles twice
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (!quoted && c == ';') ++semicolons;
    else if (!quoted && c == '\t') ++tabs;
  }
  if (semicolons == 0 && tabs == 0) return std::nullopt;
  return semicolons >= tabs ? std::string_view("\";\"") : std::string_view("tabs");
}

// The found-value of that error: the line in quotes, a tab as \t (a terminal shows it as spaces,
// which would look like a third separator), then how many cells it made.
std::string separated_line(std::string_view line, std::string_view cells, std::string_view sep) {
  std::string shown;
  for (char c : line) shown += c == '\t' ? std::string_view("\\t") : std::string_view(&c, 1);
  return fmt::format("\"{}\" ({}: the cells are separated by {})", shown, cells, sep);
}

}  // namespace

bool whole_number_text(std::string_view s) {
  if (!s.empty() && s.front() == '-') s.remove_prefix(1);
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::optional<std::size_t> CsvTable::column(std::string_view name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) return std::nullopt;
  return static_cast<std::size_t>(it - header.begin());
}

double CsvTable::number(const CsvRow& row, std::size_t col) const {
  const std::string& cell = row.cells[col];
  double v = 0;
  const char* end = cell.data() + cell.size();
  // from_chars takes no '+', which spreadsheets write for positive numbers ("+0.0"); one more
  // sign after it ("+-1") is still refused.
  const char* begin = cell.data();
  if (cell.size() > 1 && cell[0] == '+' && cell[1] != '-' && cell[1] != '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, v);
  if (cell.empty())
    throw InputError(file, row.line, header[col], "an empty cell", "a number");
  if (ec != std::errc{} || ptr != end)
    throw InputError(file, row.line, header[col], fmt::format("\"{}\"", cell), "a number");
  if (!std::isfinite(v))
    throw InputError(file, row.line, header[col], fmt::format("\"{}\"", cell), "a finite number");
  return v;
}

namespace {

// Whether the cells from `from` on are all empty (a spreadsheet pads rows to its widest).
bool all_empty(const std::vector<std::string>& cells, std::size_t from) {
  return std::all_of(cells.begin() + static_cast<std::ptrdiff_t>(from), cells.end(),
                     [](const std::string& c) { return c.empty(); });
}

// The file's text in UTF-8 without its byte-order mark, every line ended by LF; a UTF-16 text
// or a NUL byte is said where it is.
std::string csv_text(const std::filesystem::path& file, std::string_view expected_header) {
  std::string text = read_text(file, fmt::format("CSV file with header {}", expected_header));
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 byte-order mark
  // Excel's "Unicode text" export is UTF-16: two bytes a character, half of them zero here.
  const bool utf16 = text.rfind("\xFF\xFE", 0) == 0 || text.rfind("\xFE\xFF", 0) == 0;
  const std::size_t nul = text.find('\0');
  if (utf16 || nul != std::string::npos) {
    // Where the first NUL byte is: a UTF-16 text has one in its first line, a stray one (a
    // broken copy, a binary file's tail) is named at its own line.
    const auto before = std::string_view(text).substr(0, utf16 ? 0 : nul);
    const long line = 1 + static_cast<long>(std::count(before.begin(), before.end(), '\n'));
    const std::size_t column = before.size() - (before.rfind('\n') + 1) + 1;  // npos + 1 = 0
    throw InputError(file, line, "file",
                     utf16 ? "a UTF-16 text (it starts with the byte-order mark of UTF-16)"
                           : fmt::format("a NUL byte (code 0) at column {} (a UTF-16 text, a binary "
                                         "file or a damaged copy)",
                                         column),
                     fmt::format("a CSV file in UTF-8 with header {} (in Excel: Save As, "
                                 "\"CSV UTF-8\")",
                                 expected_header));
  }

  // The line ends of old Mac spreadsheets ("CSV (Macintosh)"): a CR alone. A CR before an LF
  // is the end of a Windows line and is trimmed with the line.
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
  return text;
}

// The header's cells (empty ones a spreadsheet adds after the last already dropped) as column
// names: matched without case and through the aliases, each an allowed column, once. A row of
// values in its place, another separator, an unknown column are said. `commas_below`: the rows
// below hold commas (with ';' separators, decimal commas).
void name_columns(std::vector<std::string>& cells, const std::filesystem::path& file, long line_no,
                  std::string_view line, const std::vector<std::string>& allowed,
                  std::string_view expected_header, const ColumnAliases& aliases,
                  bool commas_below) {
  // A file that starts with its data: the first row is taken for the header. Looked for in
  // every cell first, so that a row led by an id ("V001,1500") is said as such too, not as an
  // unknown column "V001" (new-user review).
  for (const std::string& h : cells)
    if (is_number(h) && std::find(allowed.begin(), allowed.end(), h) == allowed.end())
      throw InputError(file, line_no, "header",
                       fmt::format("a row of values (\"{}\") where the header belongs", line),
                       fmt::format("a header line {} above the data rows", expected_header));
  for (std::string& h : cells) {
    if (auto bad = unwritable_text(h))
      throw InputError(file, line_no, "header", *bad, std::string(kWritableText));
    // The unit in the name, as pierre's own CSVs write it ("x_m", "mass_kg").
    for (const auto& [alias, name] : aliases)
      if (same_name(h, alias)) h = name;
    for (const std::string& name : allowed)
      if (same_name(h, name)) h = name;
    if (std::find(allowed.begin(), allowed.end(), h) == allowed.end()) {
      const auto sep = other_separator(line);
      if (sep && h.find_first_of(";\t") != std::string::npos)
        throw InputError(file, line_no, "header",
                         separated_line(line,
                                        fmt::format("{} column{}", cells.size(),
                                                    cells.size() == 1 ? "" : "s"),
                                        *sep),
                         fmt::format("cells separated by commas ({}){}", expected_header,
                                     // A European export: its decimal commas go too.
                                     *sep == "\";\"" && commas_below
                                         ? "; the rows' decimal commas must then become "
                                           "points (10,5 → 10.5)"
                                         : ""));
      // One cell where several columns belong: a title line above the header, as a spreadsheet
      // export often has.
      const bool title = cells.size() == 1 && allowed.size() > 1 && commas_below;
      throw InputError(file, line_no, "header", fmt::format("column \"{}\"", h),
                       fmt::format("only the columns {}{}{}", join(allowed),
                                   aliases.empty() ? "" : alias_note(aliases),
                                   title ? "; a title line? delete it, or start it with # (a "
                                           "comment line)"
                                         : ""));
    }
    if (std::count(cells.begin(), cells.end(), h) > 1)
      throw InputError(file, line_no, "header", fmt::format("column \"{}\" twice", h),
                       "each column once");
  }
}

// A row as wide as the header (empty cells past it dropped), or what is likely wrong: another
// separator, a cut-off row (and how to leave a cell empty), a decimal comma, an unnamed column.
void fit_row_to_header(std::vector<std::string>& cells, const CsvTable& t,
                       const std::filesystem::path& file, long line_no, std::string_view line,
                       std::size_t header_cells, const std::string& header_text,
                       const std::vector<std::string>& may_be_empty) {
  if (cells.size() < t.header.size()) {
    if (const auto sep = other_separator(line))
      throw InputError(file, line_no, "row",
                       separated_line(line, fmt::format("{} of {} columns", cells.size(),
                                                        t.header.size()),
                                      *sep),
                       fmt::format("cells separated by commas ({})", join(t.header)));
    // Where the missing columns may be left empty (a block given by its mass in a table
    // with a volume column), say how: a cut-off row and an empty cell differ by a comma.
    const std::vector<std::string> missing(t.header.begin() + static_cast<std::ptrdiff_t>(cells.size()),
                                           t.header.end());
    const bool may_skip = std::all_of(missing.begin(), missing.end(), [&](const std::string& h) {
      return std::find(may_be_empty.begin(), may_be_empty.end(), h) != may_be_empty.end();
    });
    throw InputError(
        file, line_no, t.header[cells.size()],
        fmt::format("nothing (the row has {} of {} columns)", cells.size(), t.header.size()),
        may_skip ? fmt::format("a value or an empty cell in every column of {} (\"{}{}\" leaves "
                               "{} empty)",
                               join(t.header), line, std::string(missing.size(), ','),
                               join(missing))
                 : fmt::format("a value in every column of {}", join(t.header)));
  }
  if (cells.size() > t.header.size() && all_empty(cells, t.header.size()))
    cells.resize(t.header.size());
  if (cells.size() > t.header.size()) {
    // The first value past the header's columns. Where the header has an empty name there
    // ("x,z," for "x,z,material") the fault may be the header's, not the row's: say both.
    std::size_t k = t.header.size();
    while (cells[k].empty()) ++k;  // (not all are empty: see above)
    const std::string unnamed =
        header_cells > k ? fmt::format(", or a name for column {} in the header (line {}: \"{}\")",
                                       k + 1, t.header_line, header_text)
                         : "";
    throw InputError(file, line_no, "row",
                     fmt::format("{} columns (column {} holds \"{}\")", cells.size(), k + 1,
                                 cells[k]),
                     fmt::format("{} column{} ({}){}{}", t.header.size(),
                                 t.header.size() == 1 ? "" : "s", join(t.header), unnamed,
                                 fits_with_decimal_commas(cells, t.header)
                                     ? "; a decimal comma? numbers take a point (16.5, not 16,5)"
                                     : ""));
  }
}

}  // namespace

CsvTable read_csv(const std::filesystem::path& file, const std::vector<std::string>& allowed,
                  std::string_view expected_header, const ColumnAliases& aliases,
                  const std::vector<std::string>& may_be_empty) {
  const std::string text = csv_text(file, expected_header);

  CsvTable t;
  t.file = file;
  long line_no = 0;
  std::size_t pos = 0;
  std::size_t comments = 0;      // comment lines
  std::string header_text;       // the header line as written
  std::size_t header_cells = 0;  // its cells, with the empty ones a spreadsheet adds
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    const std::string_view line = trim(std::string_view(text).substr(pos, nl - pos));
    pos = nl + 1;
    ++line_no;
    if (line.empty()) continue;
    if (line.front() == '#') {
      ++comments;
      continue;
    }
    std::vector<std::string> cells = split(line);
    // A spreadsheet writes every row as wide as its widest: ",,," for a row left empty, and
    // empty cells after the last column. Both say nothing.
    if (all_empty(cells, 0)) continue;
    if (t.header.empty()) {
      t.header_line = line_no;
      header_text = line;
      header_cells = cells.size();
      while (cells.back().empty()) cells.pop_back();  // (not all are empty)
      name_columns(cells, file, line_no, line, allowed, expected_header, aliases,
                   text.find(',', pos) != std::string::npos);
      t.header = std::move(cells);
      continue;
    }
    fit_row_to_header(cells, t, file, line_no, line, header_cells, header_text, may_be_empty);
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (auto bad = unwritable_text(cells[c]))
        throw InputError(file, line_no, t.header[c], *bad, std::string(kWritableText));
    t.rows.push_back({line_no, std::move(cells)});
  }
  if (t.header.empty())
    throw InputError(file, 0, "header",
                     comments > 0 ? fmt::format("only comment lines ({} starting with #), no header",
                                                comments)
                                  : std::string("an empty file"),
                     fmt::format("a header line {} and data rows", expected_header));
  return t;
}

}  // namespace pierre::io::detail
