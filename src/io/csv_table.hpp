// A small CSV reader for the input tables (profile, blocks): a header line, then rows with
// exactly as many cells. Line ends may be LF, CRLF or CR alone. Blank lines and lines starting
// with '#' are ignored; cells are trimmed and may be enclosed in double quotes. Every problem
// is an InputError with the CSV line number.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pierre::io::detail {

struct CsvRow {
  long line = 0;  // 1-based line in the file
  std::vector<std::string> cells;
};

struct CsvTable {
  std::filesystem::path file;
  long header_line = 0;
  std::vector<std::string> header;
  std::vector<CsvRow> rows;

  // Index of a column, or nullopt when the header does not have it.
  std::optional<std::size_t> column(std::string_view name) const;
  // A cell as a finite number; InputError naming the file, the row's line and the column.
  double number(const CsvRow& row, std::size_t col) const;
};

// Other names a column may have in a header: {alias, name}, e.g. {"x_m", "x"}. The table then
// knows the column by its name.
using ColumnAliases = std::vector<std::pair<std::string, std::string>>;

// A field record of observations (a barrier's observed crossings, a quarry's observed
// distances) may say which block each row is and add a remark: columns read and left alone,
// each under its own name (as aliases, `id` beside `block` was refused as "id" twice).
inline const std::vector<std::string> kRecordColumns = {"id",   "block_id", "block",
                                                        "note", "comment",  "remark"};
// `values` with the record columns, as read_csv's `allowed` and `may_be_empty` take them.
inline std::vector<std::string> with_record_columns(std::vector<std::string> values) {
  values.insert(values.end(), kRecordColumns.begin(), kRecordColumns.end());
  return values;
}

// Digits only, with an optional leading minus ("16", "-0"): the halves of a number split by a
// decimal comma ("16,5").
bool whole_number_text(std::string_view s);

// Reads `file`; every header name must be one of `allowed` or an alias of one (no duplicates).
// `expected_header` says in messages what the header should hold. Empty cells after the last
// column, and rows of empty cells only, are what spreadsheets write for nothing: ignored.
// `may_be_empty`: the columns a row may leave empty (the reader decides what that means); a
// row short of only such cells is still an error (a cut-off row), whose message shows the
// row with its empty cells.
CsvTable read_csv(const std::filesystem::path& file, const std::vector<std::string>& allowed,
                  std::string_view expected_header, const ColumnAliases& aliases = {},
                  const std::vector<std::string>& may_be_empty = {});

}  // namespace pierre::io::detail
