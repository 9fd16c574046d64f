// Field-by-field reading of a toml++ table with the checks the scenario format demands: exact
// types (an integer is accepted where a float is expected, nothing else converts), finite
// numbers, unknown keys rejected, and every error an InputError with the node's line.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace pierre::io::detail {

// How a node looks in a message: "1" as "\"1\"", 1.5 as 1.5, nan, an array, a table...
std::string describe(const toml::node& n);

// "a", "b", "c" (each in quotes, joined by sep): names for an error message's expectation.
std::string quoted_list(const std::vector<std::string>& v, const char* sep = ", ");
long line_of(const toml::node& n);

class TomlTable {
 public:
  // `prefix` is the dotted path of the table ("simulation", "blocks.table[2]"; empty for the
  // root). `line` is where the table starts (0 for the root). Every key not in `allowed` is an
  // error (the first in file order is reported); an empty `allowed` accepts any key.
  TomlTable(std::filesystem::path file, const toml::table& t, std::string prefix, long line,
            std::initializer_list<std::string_view> allowed);

  const toml::table& table() const { return *t_; }
  const std::filesystem::path& file() const { return file_; }
  long line() const { return line_; }
  const std::string& path() const { return prefix_; }  // "blocks.table[2]"; empty for the root
  std::string field(std::string_view key) const;

  const toml::node* find(std::string_view key) const;
  bool has(std::string_view key) const { return find(key) != nullptr; }

  // Throw for `key`: at the node when present, else at the table's line with "nothing".
  [[noreturn]] void fail(std::string_view key, std::string_view expected) const;
  [[noreturn]] void missing(std::string_view key, std::string_view expected) const;

  // Numbers: finite floats (integers accepted).
  std::optional<double> number(std::string_view key) const;
  double number(std::string_view key, double fallback) const;
  double required_number(std::string_view key, std::string_view expected) const;
  // Integers: exact integers only.
  std::optional<std::int64_t> integer(std::string_view key) const;
  std::optional<bool> boolean(std::string_view key) const;
  std::optional<std::string> string(std::string_view key) const;
  std::string required_string(std::string_view key, std::string_view expected) const;
  // The file a string at `key` names, relative to this TOML file's folder (or absolute), or
  // nullopt when the key is absent. A missing file, or a folder, is an error at this key's
  // line: "found \"blocks.csv\" (no such file: /abs/blocks.csv), expected a readable <what>".
  std::optional<std::filesystem::path> file_path(std::string_view key, std::string_view what) const;
  // A nested table, or nullopt when absent; an error when the key holds something else.
  std::optional<TomlTable> subtable(std::string_view key,
                                    std::initializer_list<std::string_view> allowed) const;
  // An array of tables ([[key]]) or nullptr when absent.
  const toml::array* array_of_tables(std::string_view key) const;
  // Table i of the array of tables array_of_tables(key) returned: field "key[i]", at its line.
  TomlTable element(std::string_view key, const toml::array& a, std::size_t i,
                    std::initializer_list<std::string_view> allowed) const;
  const toml::array* array(std::string_view key) const;

  // Checks a value read from `key`: throws "found <node>, expected <expected>" unless ok.
  void check(std::string_view key, bool ok, std::string_view expected) const {
    if (!ok) fail(key, expected);
  }

 private:
  // The file's own sections (the root's allowed keys), handed down to its tables: a section's
  // name typed below another section's header is told so (TOML puts it in that section).
  using Sections = std::shared_ptr<const std::vector<std::string>>;
  TomlTable(std::filesystem::path file, const toml::table& t, std::string prefix, long line,
            std::initializer_list<std::string_view> allowed, Sections sections);

  std::filesystem::path file_;
  const toml::table* t_;
  std::string prefix_;
  long line_;
  Sections sections_;
};

// What a probability in (0, 1) expects, with the fraction meant when `found` reads as a
// percentage (5 for 5 %: "a fraction: 5 % is 0.05").
std::string probability_expected(std::string expected, double found);

// TOML text parsed; InputError at the syntax error's line.
toml::table parse_toml(const std::filesystem::path& file, const std::string& text);

}  // namespace pierre::io::detail
