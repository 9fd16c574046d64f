#include "pierre/io/input_error.hpp"

#include <fmt/format.h>

namespace pierre::io {
namespace {

// A found value is echoed whole up to kFoundWhole bytes; a longer one (a 100 000-digit CSV cell,
// a pasted paragraph) by its first kFoundStart bytes and its length, so the message stays
// readable (the margin between them keeps a value from being cut for a few bytes). A field and an
// expectation quote the input too (a key, the names to choose from, a path), with more room.
constexpr std::size_t kFoundWhole = 240, kFoundStart = 200;
constexpr std::size_t kExpectedWhole = 1200, kExpectedStart = 1000;

std::string shown(const std::string& text, std::size_t whole = kFoundWhole,
                  std::size_t start = kFoundStart) {
  if (text.size() <= whole) return text;
  std::size_t cut = start;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // UTF-8
  return fmt::format("{}… ({} bytes in all)", text.substr(0, cut), text.size());
}

// "<file>:<line>: <field>: found <value>, expected <expectation>"; without ":<line>" when the
// error is about the whole file (line 0). found(), field() and expected() keep theirs whole.
std::string message(const std::filesystem::path& file, long line, const std::string& field_whole,
                    const std::string& found_whole, const std::string& expected_whole) {
  const std::string found = shown(found_whole);
  const std::string field = shown(field_whole);
  const std::string expected = shown(expected_whole, kExpectedWhole, kExpectedStart);
  if (line > 0)
    return fmt::format("{}:{}: {}: found {}, expected {}", file.string(), line, field, found,
                       expected);
  return fmt::format("{}: {}: found {}, expected {}", file.string(), field, found, expected);
}

}  // namespace

InputError::InputError(std::filesystem::path file, long line, std::string field,
                       std::string found, std::string expected)
    : std::runtime_error(message(file, line, field, found, expected)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)),
      found_(std::move(found)),
      expected_(std::move(expected)) {}

std::string InputNote::message() const {
  if (line > 0) return fmt::format("{}:{}: {}: {}", file.string(), line, field, text);
  return fmt::format("{}: {}: {}", file.string(), field, text);
}

}  // namespace pierre::io
