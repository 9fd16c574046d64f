#include "pierre/io/input_error.hpp"

#include <fmt/format.h>

namespace pierre::io {
namespace {

// "<file>:<line>: <field>: found <value>, expected <expectation>"; without ":<line>" when the
// error is about the whole file (line 0).
std::string message(const std::filesystem::path& file, long line, const std::string& field,
                    const std::string& found, const std::string& expected) {
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

}  // namespace pierre::io
